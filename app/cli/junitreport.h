#pragma once

// JUnit XML as CI servers (Jenkins, GitLab, GitHub actions' test reporters)
// read it: <testsuites>, one <testsuite> per model, one <testcase> per
// scenario with a <failure> (an expectation failed, or a run-time fault)
// or an <error> (the model or the scenario cannot be used). User text is
// escaped: markup characters as entities, control characters and bytes that
// are not UTF-8 as \xNN, which XML 1.0 cannot carry.

#include <string>
#include <string_view>
#include <vector>

namespace cli {

struct JUnitCase {
    enum class Outcome { Passed, Failed, Error };
    std::string name;      // the scenario's file name
    Outcome outcome = Outcome::Passed;
    std::string message;   // failed or error: one line (the first failed expectation)
    std::string details;   // failed or error: every failure, one per line
};

struct JUnitSuite {
    std::string name; // the model's file name
    std::vector<JUnitCase> cases;
};

// Text for an XML attribute or element.
std::string escapeXml(std::string_view text);

std::string writeJUnit(const std::vector<JUnitSuite>& suites);

} // namespace cli
