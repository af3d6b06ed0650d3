#pragma once

#include "core/templates/templateverification.h"

namespace core::packml {

// PackML's verifier.
const VerificationEngines& verificationEngines();

} // namespace core::packml
