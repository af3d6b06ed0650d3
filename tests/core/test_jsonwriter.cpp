// The JSON the native format writes and reads faster (issue #36): JsonWriter
// writes what nlohmann's dump(2) writes, byte for byte, and the strict
// reader, which keeps an object's members aside until the object closes and
// makes a JSON path only on error, still names the place of a duplicate key
// and keeps the keys in file order.

#include "core/formats/jsonreader.h"
#include "core/formats/jsonwriter.h"
#include "core/formats/nativeformat.h"
#include "core/model/model.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace test_jsonwriter {

using namespace core;
using nlohmann::ordered_json;

namespace {

std::string dumped(const ordered_json& value)
{
    return value.dump(2, ' ', false, ordered_json::error_handler_t::replace);
}

std::string written(const ordered_json& value)
{
    JsonWriter writer;
    writer.value(value);
    return writer.take();
}

// Strings as nlohmann escapes or replaces them, and as it leaves them.
ordered_json awkwardStrings()
{
    return ordered_json::array({"", "plain", "\"quoted\"", "back\\slash", "tab\tnew\nline\r", std::string("nul\0x", 5),
                                "\x01\x1f\x7f", "é ↑ 🙂", "\xff invalid \xc3", "slash / tilde ~"});
}

JsonReadError parseError(std::string_view text)
{
    JsonReadError error;
    REQUIRE_FALSE(parseStrictJson(text, error).has_value());
    return error;
}

} // namespace

TEST_CASE("JsonWriter: any value written as dump(2) writes it", "[files][jsonwriter]")
{
    CHECK(written(ordered_json::object()) == "{}");
    CHECK(written(ordered_json::array()) == "[]");
    for (const ordered_json& value : awkwardStrings())
        CHECK(written(value) == dumped(value));
    ordered_json nested = ordered_json::parse(R"({"z": 1, "a": [], "m": {}, "list": [1, -2, 18446744073709551615,
        2.5, -0.0, 1e300, true, false, null, {"inner": {"deeper": [[], [{}], "x"]}}], "last": "end"})");
    nested["strings"] = awkwardStrings();
    nested["strings as keys"] = ordered_json::object();
    for (const ordered_json& text : awkwardStrings())
        nested["strings as keys"][text.get<std::string>()] = text;
    CHECK(written(nested) == dumped(nested));
}

TEST_CASE("JsonWriter: built member by member", "[files][jsonwriter]")
{
    JsonWriter writer;
    writer.beginObject();
    writer.key("name");
    writer.string("a \"b\"");
    writer.key("count");
    writer.integer(-42);
    writer.key("flags");
    writer.beginArray();
    writer.boolean(true);
    writer.boolean(false);
    writer.endArray();
    writer.key("empty");
    writer.beginObject();
    writer.endObject();
    writer.key("none");
    writer.beginArray();
    writer.endArray();
    writer.endObject();
    const ordered_json expected = {{"name", "a \"b\""}, {"count", -42}, {"flags", {true, false}},
                                   {"empty", ordered_json::object()}, {"none", ordered_json::array()}};
    CHECK(writer.text() == dumped(expected));
}

TEST_CASE("Native: a saved model is the dump of its own JSON, odd texts included", "[files][jsonwriter]")
{
    Model model;
    REQUIRE(model.setName("Cell \"7\" \\ é \x01"));
    Variable input{"Start", IecType::Bool, "", "tab\there\nnew line"};
    REQUIRE(model.addVariable(input));
    Variable count{"Count", IecType::Int, "3", "\xff not UTF-8"};
    count.kind = VariableKind::Internal;
    REQUIRE(model.addVariable(count));
    REQUIRE(model.setStepComment("A1", "\"quoted\" ~/"));
    REQUIRE(model.setCondition("A1->F4", "Start AND \"x\""));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "first \\ step", {{ActionTiming::OnActivation, "Count := Count + 1"}}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "Start"}));
    REQUIRE(model.addProperty({"never Start AND NOT Start", "a \"property\""}));

    const std::string saved = saveNativeJson(model);
    JsonReadError error;
    const std::optional<ordered_json> parsed = parseStrictJson(saved, error);
    REQUIRE(parsed.has_value());
    CHECK(saved == dumped(*parsed) + "\n");
    CHECK(saved.find("\xef\xbf\xbd not UTF-8") != std::string::npos); // replaced, as dump replaces it
}

TEST_CASE("Strict JSON: keys stay in file order, nested objects whole", "[files][jsonwriter]")
{
    const std::string text = R"({"b": {"y": 1, "x": {"q": [1, {"k": "v", "j": []}], "p": {}}}, "a": [{"z": 0, "w": 1}, {}], "c": null})";
    JsonReadError error;
    const std::optional<ordered_json> parsed = parseStrictJson(text, error);
    REQUIRE(parsed.has_value());
    CHECK(parsed->dump() == text.substr(0, 0) + R"({"b":{"y":1,"x":{"q":[1,{"k":"v","j":[]}],"p":{}}},"a":[{"z":0,"w":1},{}],"c":null})");
}

TEST_CASE("Strict JSON: a duplicate key is named by its whole path, in small and large objects", "[files][jsonwriter]")
{
    // Deep inside arrays and objects, after a closed sibling object.
    JsonReadError error = parseError(R"({"a": {"done": {"x": 1}, "list": [0, {"k": 1}, {"ok": {}, "k": 2, "k": 3}]}})");
    CHECK(error.location == "/a/list/2/k");
    CHECK(error.message == "duplicate key \"k\" (each key may appear once per object)");

    // Keys that need escaping in a JSON pointer.
    error = parseError(R"({"a/b": [{"c~d": {"e": 1, "e": 2}}]})");
    CHECK(error.location == "/a~1b/0/c~0d/e");

    // An object of many members, where keys are looked up by hash: the
    // duplicate of the first, of a middle one and of the last.
    std::string many = R"({"outer": {)";
    for (int i = 0; i < 40; ++i)
        many += "\"m" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
    for (const char* repeated : {"m0", "m17", "m39"}) {
        error = parseError(many + "\"" + repeated + "\": 0}}");
        CHECK(error.location == "/outer/" + std::string(repeated));
        CHECK(error.message == "duplicate key \"" + std::string(repeated) + "\" (each key may appear once per object)");
    }
    JsonReadError none;
    CHECK(parseStrictJson(many + "\"m40\": 0}}", none).has_value());
}

} // namespace test_jsonwriter
