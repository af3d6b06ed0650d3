#pragma once

// What each template gives the verification entry point (verifyModel), as
// templateengines.h does for the checks, the property language and the code
// generator. Part of the verification library (core/CMakeLists.txt).

#include "core/verification/verification.h"

namespace core {

class Model;

struct VerificationEngines {
    VerificationResult (*verifyModel)(const Model& model, const VerificationOptions& options);
};

// The verifier of the model's template.
const VerificationEngines& verificationEnginesOf(const Model& model);

} // namespace core
