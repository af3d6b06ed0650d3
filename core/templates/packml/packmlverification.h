#pragma once

#include "core/templates/templateverification.h"

namespace core::packml {

// PackML's property checks and verifier.
const VerificationEngines& verificationEngines();

} // namespace core::packml
