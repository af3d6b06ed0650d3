#pragma once

#include "core/templates/templateverification.h"

namespace core {

// GEMMA's verifier.
const VerificationEngines& gemmaVerificationEngines();

} // namespace core
