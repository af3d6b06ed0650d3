#pragma once

// What the verification tests share: the findings of one code, the codes
// and messages of a result, and a Status that must be ok (its message shown
// when it is not).

#include "core/model/status.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
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

// "GV132 <message>", one a finding: what a failed check prints.
inline std::vector<std::string> codesOf(const core::VerificationResult& result)
{
    std::vector<std::string> codes;
    for (const core::VerificationFinding& f : result.findings)
        codes.push_back(f.code + " " + f.message);
    return codes;
}

// The first finding of `findingCode`, or null.
inline const core::VerificationFinding* findingOf(const core::VerificationResult& result, const std::string& findingCode)
{
    const auto found = std::find_if(result.findings.begin(), result.findings.end(),
                                    [&](const core::VerificationFinding& f) { return f.code == findingCode; });
    return found == result.findings.end() ? nullptr : &*found;
}

inline void require(const core::Status& status)
{
    INFO(status.message);
    REQUIRE(status.ok);
}

} // namespace verificationtest
