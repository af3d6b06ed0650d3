#pragma once

// What the verification tests share: the findings of one code, the codes
// and messages of a result, the lines that tell two results apart, and a
// Status that must be ok (its message shown when it is not).

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

// What tells two results apart for the engineer: each finding, its severity,
// its elements and message, and whether its run replays.
inline std::vector<std::string> findingLines(const core::VerificationResult& result)
{
    std::vector<std::string> lines;
    for (const core::VerificationFinding& f : result.findings) {
        std::string line = f.code + " " + std::to_string(static_cast<int>(f.severity)) + " " + f.message;
        for (const std::string& element : f.elements)
            line += " | " + element;
        if (f.counterexample)
            line += f.counterexample->confirmed ? " [confirmed]" : " [not confirmed]";
        lines.push_back(line);
    }
    return lines;
}

inline void require(const core::Status& status)
{
    INFO(status.message);
    REQUIRE(status.ok);
}

} // namespace verificationtest
