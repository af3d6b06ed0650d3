#pragma once

#include "core/templates/templateverification.h"

namespace core {

// GEMMA's property checks and verifier.
const VerificationEngines& gemmaVerificationEngines();

} // namespace core
