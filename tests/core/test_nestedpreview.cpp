// The preview of a nested GRAFCET's function block and the lines of its
// elements, which the editor's Structured Text dock highlights.

#include "core/codegen/nestedpreview.h"
#include "core/model/model.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace test_nestedpreview {

using namespace core;

namespace {

// F1: 1 --RE Start--> 2 (N Lamp, Count := Count + 1) --5s/X2--> 3 (S Complete) --TRUE--> 1.
Model previewModel()
{
    Model model = samples::lampGrafcetModel();
    REQUIRE(model.addGrafcetTransition("F1", {3, {3}, {1}, "TRUE"}));
    return model;
}

std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);)
        lines.push_back(line);
    return lines;
}

// The lines of every range of `key` ("X2", "X2@2"...), joined.
std::string linesOfElement(const StPreview& preview, const std::string& key)
{
    const std::vector<std::string> lines = linesOf(preview.text);
    std::string result;
    for (const auto& [name, range] : preview.ranges) {
        if (name != key && name.rfind(key + "@", 0) != 0)
            continue;
        for (int line = range.first; line <= range.last; ++line)
            result += lines.at(static_cast<std::size_t>(line - 1)) + "\n";
    }
    return result;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("The preview of a nested GRAFCET is its function block", "[nested-preview]")
{
    const Model model = previewModel();
    const StPreview preview = previewNestedFunctionBlock(model, "F1", Dialect::Iec);
    CHECK(contains(preview.text, "\nFUNCTION_BLOCK F1_FB\n"));
    CHECK(contains(preview.text, "END_FUNCTION_BLOCK"));
    CHECK_FALSE(contains(preview.text, "PROGRAM GEMMA"));
    CHECK(previewNestedFunctionBlock(model, "F1", Dialect::Codesys).text != preview.text);
    // A step with no GRAFCET, or one whose GRAFCET generates nothing, has no preview.
    CHECK(previewNestedFunctionBlock(model, "F2", Dialect::Iec).text.empty());
    Model hidden = previewModel();
    REQUIRE(hidden.setStepHidden("F1", true));
    CHECK(previewNestedFunctionBlock(hidden, "F1", Dialect::Iec).text.empty());
}

TEST_CASE("Each nested step and transition has the lines of its code", "[nested-preview]")
{
    const StPreview preview = previewNestedFunctionBlock(previewModel(), "F1", Dialect::Iec);
    const std::string t1 = linesOfElement(preview, "T1");
    CHECK(contains(t1, "GG_Fire1 : BOOL"));
    CHECK(contains(t1, "GG_Fire1 := X1 AND"));
    CHECK_FALSE(contains(t1, "GG_Fire2"));
    const std::string t2 = linesOfElement(preview, "T2");
    CHECK(contains(t2, "GG_Fire2 := X2 AND"));
    CHECK_FALSE(contains(t2, "GG_Fire1"));

    const std::string x2 = linesOfElement(preview, "X2");
    CHECK(contains(x2, "X2 : BOOL"));
    CHECK(contains(x2, "X2 := X2 AND NOT GG_Left2;"));
    CHECK(contains(x2, "IF GG_Entered2 THEN"));
    CHECK(contains(x2, "Count := Count + 1;")); // its stored action, inside its IF block
    CHECK_FALSE(contains(x2, "Complete := TRUE;")); // step 3's
    CHECK(contains(linesOfElement(preview, "X3"), "Complete := TRUE;"));
    // Every range lies inside the text and names a step or transition.
    const std::size_t lineCount = linesOf(preview.text).size();
    for (const auto& [name, range] : preview.ranges) {
        CHECK((name[0] == 'X' || name[0] == 'T'));
        CHECK(range.first >= 1);
        CHECK(range.first <= range.last);
        CHECK(static_cast<std::size_t>(range.last) <= lineCount);
    }
}

} // namespace test_nestedpreview
