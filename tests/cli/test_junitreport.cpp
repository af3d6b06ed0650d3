// The JUnit XML of `ggstudio-cli test` (app/cli/junitreport.h): the
// elements CI servers read, and user text escaped so the file stays XML.

#include "junitreport.h"

#include <catch2/catch.hpp>

namespace {

using cli::JUnitCase;

} // namespace

TEST_CASE("XML text is escaped: markup, control characters and bytes that are not UTF-8", "[cli][junit]")
{
    CHECK(cli::escapeXml("a<b>&\"c'") == "a&lt;b&gt;&amp;&quot;c&apos;");
    CHECK(cli::escapeXml("line 1\nline 2\tend") == "line 1&#10;line 2&#9;end");
    CHECK(cli::escapeXml(std::string("bell\x07 esc\x1b", 10)) == "bell\\x07 esc\\x1b");
    CHECK(cli::escapeXml("caf\xc3\xa9 \xe2\x82\xac") == "caf\xc3\xa9 \xe2\x82\xac"); // UTF-8 kept
    CHECK(cli::escapeXml("bad \xff byte") == "bad \\xff byte");
    CHECK(cli::escapeXml("overlong \xc0\xaf") == "overlong \\xc0\\xaf");
    CHECK(cli::escapeXml("cut \xe2\x82") == "cut \\xe2\\x82");
    CHECK(cli::escapeXml("surrogate \xed\xa0\x80") == "surrogate \\xed\\xa0\\x80");
    CHECK(cli::escapeXml(std::string("nul\0", 4)) == "nul\\x00");
}

TEST_CASE("The JUnit report has a testsuite per model and a testcase per scenario", "[cli][junit]")
{
    cli::JUnitSuite first{"cell.json", {}};
    first.cases.push_back({"start.scenario", JUnitCase::Outcome::Passed, "", ""});
    first.cases.push_back({"fault.scenario", JUnitCase::Outcome::Failed, "line 9: scan 3: expected step D1 <x>",
                           "line 9: scan 3: expected step D1 <x>\nline 10: scan 4: other\n"});
    cli::JUnitSuite second{"student & co.json", {}};
    second.cases.push_back({"start.scenario", JUnitCase::Outcome::Error, "cannot read", "cannot read\n"});
    const std::string xml = cli::writeJUnit({first, second});
    CHECK(xml
          == "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<testsuites name=\"ggstudio-cli test\" tests=\"3\" failures=\"1\" errors=\"1\">\n"
             "  <testsuite name=\"cell.json\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\">\n"
             "    <testcase name=\"start.scenario\" classname=\"cell.json\"/>\n"
             "    <testcase name=\"fault.scenario\" classname=\"cell.json\">\n"
             "      <failure message=\"line 9: scan 3: expected step D1 &lt;x&gt;\" type=\"ScenarioFailure\">"
             "line 9: scan 3: expected step D1 &lt;x&gt;&#10;line 10: scan 4: other&#10;</failure>\n"
             "    </testcase>\n"
             "  </testsuite>\n"
             "  <testsuite name=\"student &amp; co.json\" tests=\"1\" failures=\"0\" errors=\"1\" skipped=\"0\">\n"
             "    <testcase name=\"start.scenario\" classname=\"student &amp; co.json\">\n"
             "      <error message=\"cannot read\" type=\"ScenarioError\">cannot read&#10;</error>\n"
             "    </testcase>\n"
             "  </testsuite>\n"
             "</testsuites>\n");
}
