// The clipboard's GRAFCET fragment as JSON: what Copy writes reads back
// equal, and what another program may have put on the clipboard is refused
// with the place of the fault.

#include "core/formats/grafcetfragmentjson.h"
#include "core/model/grafcetediting.h"

#include <catch2/catch.hpp>

#include <string>

namespace test_grafcetfragmentjson {

using namespace core;

namespace {

// 1 -> T1 -> 2 -> T2 -> 3, with actions of each timing, a comment and
// receptivities that name steps and hold characters JSON escapes.
Grafcet sample()
{
    Grafcet g;
    REQUIRE(g.addStep({1, true, "start", {{ActionTiming::Continuous, "A_Plus"}}}).ok);
    REQUIRE(g.addStep({2, false, "\"quoted\" \\ and é", {{ActionTiming::OnActivation, "S Complete"},
                                                          {ActionTiming::OnDeactivation, "Count := Count + 1"}}})
                .ok);
    REQUIRE(g.addStep({3, false, "", {}}).ok);
    REQUIRE(g.addTransition({1, {1}, {2}, "5s/X1 AND NOT a1"}).ok);
    REQUIRE(g.addTransition({2, {2}, {3}, "↑StepButton"}).ok);
    return g;
}

std::string refusal(const std::string& text)
{
    auto result = loadGrafcetFragmentJson(text);
    if (std::holds_alternative<GrafcetFragment>(result))
        FAIL("accepted: " << text.substr(0, 200));
    const JsonReadError& error = std::get<JsonReadError>(result);
    return error.location + ": " + error.message;
}

const std::string kHeader = R"({"format": "ggstudio-grafcet-fragment", "version": "1.0", )";

} // namespace

TEST_CASE("A copied fragment reads back equal, never initial", "[grafcetfragmentjson]")
{
    const Grafcet g = sample();
    const GrafcetFragment copied = copyFragment(g, {1, 2, 3});
    const std::string text = saveGrafcetFragmentJson(copied);
    CHECK(text == saveGrafcetFragmentJson(copied)); // deterministic
    CHECK(text.find("\"format\": \"ggstudio-grafcet-fragment\"") != std::string::npos);

    auto result = loadGrafcetFragmentJson(text);
    REQUIRE(std::holds_alternative<GrafcetFragment>(result));
    const GrafcetFragment& read = std::get<GrafcetFragment>(result);
    GrafcetFragment expected = copied;
    expected.steps.front().initial = false; // pasted steps never are
    CHECK(read.steps == expected.steps);
    CHECK(read.transitions == expected.transitions);

    // And pastes as the copied fragment does.
    Grafcet viaText = sample();
    Grafcet direct = sample();
    REQUIRE(pasteFragment(viaText, read, 0).ok);
    REQUIRE(pasteFragment(direct, copied, 0).ok);
    CHECK(viaText.sameContent(direct));
}

TEST_CASE("A hostile or malformed fragment is refused with its place", "[grafcetfragmentjson]")
{
    const std::string steps = R"("grafcet": {"steps": [{"number": 1}, {"number": 2}], "transitions": )";
    CHECK(refusal("") .find("line") != std::string::npos);
    CHECK(refusal("not json at all").find("line 1") != std::string::npos);
    CHECK(refusal("[1, 2]").find("expected an object") != std::string::npos);
    CHECK(refusal(R"({"format": "ggstudio-model", "version": "2.0"})").rfind("/format", 0) == 0);
    CHECK(refusal(kHeader.substr(0, kHeader.find("\"version\"")) + R"("version": "9.0", "grafcet": {}})")
              .rfind("/version", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": []}})").rfind("/grafcet/steps", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": 1}]}, "extra": 1})").rfind("/extra", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": -3}]}})").rfind("/grafcet/steps/0/number", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": 1.5}]}})").rfind("/grafcet/steps/0/number", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": 1e300}]}})").rfind("/grafcet/steps/0/number", 0)
          == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": 1}, {"number": 1}]}})")
              .rfind("/grafcet/steps/1", 0) == 0);
    CHECK(refusal(kHeader + steps + R"([{"number": 1, "upstream": [1], "downstream": [7]}]}})")
              .rfind("/grafcet/transitions/0", 0) == 0);
    CHECK(refusal(kHeader + steps + R"([{"number": 1, "upstream": [1], "downstream": []}]}})")
              .rfind("/grafcet/transitions/0", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": 1, "actions": [{"timing": "often"}]}]}})")
              .rfind("/grafcet/steps/0/actions/0/timing", 0) == 0);
    CHECK(refusal(kHeader + R"("grafcet": {"steps": [{"number": 1, "comment": 5}]}})")
              .rfind("/grafcet/steps/0/comment", 0) == 0);
    CHECK(refusal(std::string(70, '[') + std::string(70, ']')).find("deep") != std::string::npos);
}

TEST_CASE("A fragment's size is bounded before it is read", "[grafcetfragmentjson]")
{
    const std::string huge = kHeader + R"("grafcet": {"steps": [{"number": 1, "comment": ")"
                           + std::string(kMaxGrafcetFragmentBytes, 'x') + "\"}]}}";
    CHECK(refusal(huge).find("at most") != std::string::npos);

    std::string many = kHeader + R"("grafcet": {"steps": [)";
    for (std::size_t n = 1; n <= kMaxGrafcetFragmentSteps + 1; ++n)
        many += (n > 1 ? ", " : "") + std::string(R"({"number": )") + std::to_string(n) + "}";
    many += "]}}";
    REQUIRE(many.size() < kMaxGrafcetFragmentBytes);
    CHECK(refusal(many).rfind("/grafcet/steps: 1001 steps", 0) == 0);
}

} // namespace test_grafcetfragmentjson
