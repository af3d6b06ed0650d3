#pragma once

// Strict JSON reading shared by the model file loaders: stricter than
// nlohmann::ordered_json::parse (duplicate keys, nesting depth and invalid UTF-8 are
// errors with a location, and so is a NUL byte, where nlohmann would stop
// reading) plus typed accessors whose errors name the JSON
// path ("/steps/F1/hidden: expected true or false, found \"yes\"").

#include "core/formats/loaderror.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace core {

class Model;

inline constexpr std::size_t kMaxJsonDepth = 64;

// Where and what. location is "line 3, column 14" or a JSON pointer
// ("/transitions/F1->A2/order"); empty for the document as a whole.
struct JsonReadError {
    std::string location;
    std::string message;
    std::string advice = {}; // as LoadError::advice
};

// Parses the whole text as one JSON value, keeping the keys in file order.
// Fails on invalid UTF-8, a NUL byte, nesting deeper than kMaxJsonDepth, malformed JSON
// (with line and column) and duplicate object keys (with their JSON path).
std::optional<nlohmann::ordered_json> parseStrictJson(std::string_view text, JsonReadError& error);

// A model file's loading: parseStrictJson, then `build` on the root (which
// throws JsonReadError); either failure becomes a LoadError for `displayName`.
std::variant<std::unique_ptr<Model>, LoadError> loadModelJson(
    std::string_view text, const std::string& displayName,
    const std::function<std::unique_ptr<Model>(const nlohmann::ordered_json&)>& build);

// The typed accessors below throw JsonReadError; loaders catch it at their
// boundary so it never escapes the core API.
[[noreturn]] void failAt(std::string path, std::string message);

// RFC 6901 JSON pointer steps ("~" and "/" escaped).
std::string childPath(const std::string& path, std::string_view key);
std::string childPath(const std::string& path, std::size_t index);

// A short description for messages: "\"yes\"", "12", "true", "null",
// "an object", "an array". Long strings are cut.
std::string describeJsonValue(const nlohmann::ordered_json& value);

const nlohmann::ordered_json& expectObject(const nlohmann::ordered_json& value, const std::string& path);
const nlohmann::ordered_json& expectArray(const nlohmann::ordered_json& value, const std::string& path);
bool readBool(const nlohmann::ordered_json& value, const std::string& path);
std::string readString(const nlohmann::ordered_json& value, const std::string& path);
// Integral numbers only (20 and 20.0, not 20.5), inside [min, max].
long long readInteger(const nlohmann::ordered_json& value, const std::string& path, long long min, long long max);

// The member of an object, or nullptr when absent.
const nlohmann::ordered_json* findMember(const nlohmann::ordered_json& object, std::string_view key);

// The first non-blank character after an optional UTF-8 byte order mark;
// '\0' for a blank text. Used for format detection.
char firstSignificantCharacter(std::string_view text);

} // namespace core
