// The PackML code as the Structured Text dock previews it: the PROGRAM's
// lines of each mode and state, a GRAFCET's function block.

#include "packmlcapper.h"

#include "core/codegen/stgenerator.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlpreview.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace test_packmlpreview {

namespace {

std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::string lineAt(const std::vector<std::string>& lines, int number)
{
    REQUIRE(number >= 1);
    REQUIRE(static_cast<std::size_t>(number) <= lines.size());
    return lines[static_cast<std::size_t>(number - 1)];
}

} // namespace

TEST_CASE("The PackML PROGRAM preview locates each mode's and state's branch", "[packml-preview]")
{
    const auto capper = packmltests::loadCapper();
    const core::StPreview preview = core::packml::previewPackmlProgram(*capper, core::Dialect::Iec);
    REQUIRE(preview.text.rfind("PROGRAM ", 0) == 0);
    const std::vector<std::string> lines = linesOf(preview.text);

    // Section 3's branches, not section 2's (the mode manager has the same labels).
    const core::LineRange production = preview.ranges.at("1");
    CHECK(lineAt(lines, production.first) == "1: (* Production *)");
    CHECK(lineAt(lines, production.last + 1) == "3: (* Manual *)");
    CHECK(lineAt(lines, production.first - 1) == "CASE Mode OF");
    CHECK(lineAt(lines, production.first - 2).find("3. State machine") != std::string::npos);

    const core::LineRange execute = preview.ranges.at("1/Execute");
    CHECK(lineAt(lines, execute.first) == "    6: (* Execute *)");
    CHECK(lineAt(lines, execute.last + 1) == "    9: (* Aborted *)");
    CHECK(execute.first > production.first);
    CHECK(execute.last < production.last);

    const core::LineRange resetting = preview.ranges.at("1/Resetting");
    CHECK(lineAt(lines, resetting.last - 1).find("Production_Resetting.Complete") != std::string::npos);
    CHECK(lineAt(lines, resetting.last) == "        END_IF;");
    CHECK(lineAt(lines, resetting.last + 1) == "    END_CASE;");

    // Manual disables Resetting: it has no branch there.
    CHECK(preview.ranges.count("3/Stopped") == 1);
    CHECK(preview.ranges.count("3/Resetting") == 0);
    const core::LineRange manual = preview.ranges.at("3");
    CHECK(lineAt(lines, manual.last + 1) == "END_CASE;");
}

TEST_CASE("The PackML function block preview is the GRAFCET's FB with its steps' lines", "[packml-preview]")
{
    const auto capper = packmltests::loadCapper();
    const core::StPreview preview =
        core::packml::previewPackmlFunctionBlock(*capper, "1/Resetting", core::Dialect::Iec);
    REQUIRE(preview.text.rfind("FUNCTION_BLOCK Production_Resetting_FB", 0) == 0);
    const std::vector<std::string> lines = linesOf(preview.text);
    CHECK(lineAt(lines, preview.ranges.at("X1").first).find("X1") != std::string::npos);
    CHECK(preview.ranges.count("T1") == 1);

    CHECK(core::packml::previewPackmlFunctionBlock(*capper, "3/Resetting", core::Dialect::Iec).text.empty());
    CHECK(core::packml::previewPackmlFunctionBlock(*capper, "nonsense", core::Dialect::Iec).text.empty());
}

} // namespace test_packmlpreview
