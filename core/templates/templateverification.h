#pragma once

// What each template gives the verification entry points (checkProperty,
// verifyModel), as templateengines.h does for the checks and the code
// generator. Part of the verification library (core/CMakeLists.txt).

#include "core/verification/property.h"
#include "core/verification/verification.h"

#include <string_view>
#include <vector>

namespace core {

class Model;

struct VerificationEngines {
    std::vector<PropertyProblem> (*checkProperty)(const Model& model, std::string_view text);
    VerificationResult (*verifyModel)(const Model& model, const VerificationOptions& options);
};

// The property checker and the verifier of the model's template.
const VerificationEngines& verificationEnginesOf(const Model& model);

} // namespace core
