#pragma once

// What the verification tests share: the findings of one code, and a Status
// that must be ok (its message shown when it is not).

#include "core/model/status.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace verificationtest {

inline std::vector<const core::VerificationFinding*> findingsWith(const core::VerificationResult& result,
                                                                  const std::string& findingCode)
{
    std::vector<const core::VerificationFinding*> out;
    for (const core::VerificationFinding& finding : result.findings) {
        if (finding.code == findingCode)
            out.push_back(&finding);
    }
    return out;
}

inline void require(const core::Status& status)
{
    INFO(status.message);
    REQUIRE(status.ok);
}

} // namespace verificationtest
