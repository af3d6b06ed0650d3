#include "core/formats/jsonreader.h"

#include "core/formats/fileio.h"
#include "core/model/model.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <utility>
#include <vector>

using json = nlohmann::ordered_json;

namespace core {

namespace {

// Byte offset of the bracket that opens level maxDepth + 1, if any. Done
// before parsing so the error can carry a line and column.
std::optional<std::size_t> findExcessiveNesting(std::string_view text, std::size_t maxDepth)
{
    std::size_t depth = 0;
    bool inString = false;
    bool escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > maxDepth)
                return i;
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

// nlohmann's messages read "[json.exception.parse_error.101] parse error at
// line 1, column 5: syntax error while ...": keep the part after the
// position, which we compute ourselves in characters rather than bytes.
std::string syntaxMessage(const std::string& what)
{
    const std::size_t colon = what.find(": ");
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

// Builds the DOM like nlohmann's own SAX DOM parser, but refuses duplicate
// keys (nlohmann silently keeps the last one). What it spares (issue #36):
// the JSON path of a duplicate key is made from the open containers only
// when there is one; and an object's members gather in a buffer of movable
// pairs, moved once into the object when it closes, because ordered_json's
// own member vector holds const keys and so copies every member, whole
// subtrees included, each time it grows.
class StrictDomBuilder : public json::json_sax_t {
public:
    StrictDomBuilder(std::string_view text, json& root, JsonReadError& error)
        : m_text(text), m_root(root), m_error(error)
    {
    }

    bool null() override { return add(json(nullptr)); }
    bool boolean(bool value) override { return add(json(value)); }
    bool number_integer(number_integer_t value) override { return add(json(value)); }
    bool number_unsigned(number_unsigned_t value) override { return add(json(value)); }
    bool number_float(number_float_t value, const string_t&) override { return add(json(value)); }
    bool string(string_t& value) override { return add(json(std::move(value))); }
    bool binary(binary_t& value) override { return add(json::binary(std::move(value))); }

    bool start_object(std::size_t) override { return open(json::object()); }
    bool start_array(std::size_t) override { return open(json::array()); }

    bool end_object() override
    {
        Frame& frame = m_stack[m_depth - 1];
        auto& target = static_cast<json::object_t::Container&>(frame.value->get_ref<json::object_t&>());
        target.reserve(frame.members.size());
        for (auto& [name, value] : frame.members)
            target.emplace_back(std::move(name), std::move(value));
        return close();
    }

    bool end_array() override { return close(); }

    bool key(string_t& key) override
    {
        Frame& frame = m_stack[m_depth - 1];
        if (isDuplicate(frame, key)) {
            m_error = {childPath(openPath(), key), "duplicate key \"" + key + "\" (each key may appear once per object)"};
            return false;
        }
        frame.pendingKey = std::move(key);
        return true;
    }

    bool parse_error(std::size_t position, const std::string&, const json::exception& exception) override
    {
        // position counts the bytes read, up to the one where parsing
        // stopped (the end of the offending token).
        const std::size_t offset = position > 0 ? position - 1 : 0;
        m_error = {describePosition(textPosition(m_text, offset)), "malformed JSON: " + syntaxMessage(exception.what())};
        return false;
    }

private:
    // Objects up to this many members are searched for a duplicate key one
    // member at a time; a larger one gets a hash set of its keys, so that a
    // hostile object of a million keys still loads in linear time.
    static constexpr std::size_t kLinearKeySearch = 16;

    // One open container. Frames are kept when closed, so that the next
    // container at that depth reuses their buffers.
    struct Frame {
        json* value = nullptr;
        std::vector<std::pair<std::string, json>> members; // an object's, until it closes
        std::string pendingKey;
        std::unique_ptr<std::unordered_set<std::string>> keys; // from kLinearKeySearch members on
    };

    static bool isDuplicate(Frame& frame, const std::string& key)
    {
        if (!frame.keys) {
            if (frame.members.size() < kLinearKeySearch) {
                return std::any_of(frame.members.begin(), frame.members.end(),
                                   [&](const auto& member) { return member.first == key; });
            }
            frame.keys = std::make_unique<std::unordered_set<std::string>>();
            for (const auto& member : frame.members)
                frame.keys->insert(member.first);
        }
        return !frame.keys->insert(key).second;
    }

    // The JSON path of the innermost open container: each one is the last
    // element or member of the one around it.
    std::string openPath() const
    {
        std::string path;
        for (std::size_t i = 1; i < m_depth; ++i) {
            const Frame& parent = m_stack[i - 1];
            if (parent.value->is_array())
                path = childPath(path, parent.value->size() - 1);
            else
                path = childPath(path, parent.members.back().first);
        }
        return path;
    }

    // Inserts into the current container; returns where the value went (it
    // stays there while it is the last one, that is while it is open).
    json* insert(json&& value)
    {
        if (m_depth == 0) {
            m_root = std::move(value);
            return &m_root;
        }
        Frame& frame = m_stack[m_depth - 1];
        if (frame.value->is_array()) {
            auto& elements = frame.value->get_ref<json::array_t&>();
            elements.push_back(std::move(value));
            return &elements.back();
        }
        frame.members.emplace_back(std::move(frame.pendingKey), std::move(value));
        return &frame.members.back().second;
    }

    bool add(json&& value)
    {
        insert(std::move(value));
        return true;
    }

    bool open(json&& container)
    {
        json* inserted = insert(std::move(container));
        if (m_depth == m_stack.size())
            m_stack.emplace_back();
        Frame& frame = m_stack[m_depth++];
        frame.value = inserted;
        frame.members.clear();
        frame.keys.reset();
        return true;
    }

    bool close()
    {
        --m_depth;
        return true;
    }

    std::string_view m_text;
    json& m_root;
    JsonReadError& m_error;
    std::vector<Frame> m_stack;
    std::size_t m_depth = 0; // open containers: the first m_depth frames
};

std::string cut(std::string text, std::size_t maxLength)
{
    if (text.size() <= maxLength)
        return text;
    // Never cut inside a UTF-8 sequence.
    std::size_t end = maxLength;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0u) == 0x80u)
        --end;
    text.resize(end);
    return text + "...";
}

// Whether the byte at offset lies inside a string of text read as JSON from
// its start (the text before it need not be valid JSON).
bool insideJsonString(std::string_view text, std::size_t offset)
{
    bool inString = false;
    for (std::size_t i = 0; i < offset; ++i) {
        if (!inString) {
            inString = text[i] == '"';
        } else if (text[i] == '\\') {
            ++i; // the escaped character, which may be a quote
        } else if (text[i] == '"') {
            inString = false;
        }
    }
    return inString;
}

// A raw NUL can stand nowhere in JSON; only inside a string does it have a
// spelling, the escape \u0000.
JsonReadError nulByteError(std::string_view text, std::size_t offset)
{
    const std::string location = describePosition(textPosition(text, offset));
    if (insideJsonString(text, offset))
        return {location, "a NUL byte inside a string: JSON text cannot contain one raw", "write it as \\u0000"};
    return {location, "a NUL byte outside any string: JSON text cannot contain one", {}};
}

} // namespace

std::optional<json> parseStrictJson(std::string_view text, JsonReadError& error)
{
    if (auto problem = findInvalidUtf8(text)) {
        error = {describePosition(problem->position), "invalid UTF-8: the file must be UTF-8 text"};
        return std::nullopt;
    }
    // nlohmann's lexer takes a NUL byte for the end of the input (it also reads
    // C strings): without this check, whatever follows a NUL would be ignored.
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        error = nulByteError(text, nul);
        return std::nullopt;
    }
    if (auto offset = findExcessiveNesting(text, kMaxJsonDepth)) {
        error = {describePosition(textPosition(text, *offset)),
            "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels"};
        return std::nullopt;
    }
    json root;
    StrictDomBuilder builder(text, root, error);
    try {
        if (!json::sax_parse(text, &builder, json::input_format_t::json, true, false))
            return std::nullopt;
    } catch (const json::exception& exception) {
        // sax_parse reports through parse_error; this only guards the unexpected.
        error = {{}, std::string("malformed JSON: ") + exception.what()};
        return std::nullopt;
    }
    return root;
}

std::variant<std::unique_ptr<Model>, LoadError> loadModelJson(
    std::string_view text, const std::string& displayName,
    const std::function<std::unique_ptr<Model>(const json&)>& build)
{
    JsonReadError error;
    const std::optional<json> root = parseStrictJson(text, error);
    if (!root)
        return LoadError{displayName, error.location, error.message, error.advice};
    try {
        return build(*root);
    } catch (const JsonReadError& failure) {
        return LoadError{displayName, failure.location, failure.message, failure.advice};
    }
}

void failAt(std::string path, std::string message)
{
    throw JsonReadError{std::move(path), std::move(message)};
}

std::string childPath(const std::string& path, std::string_view key)
{
    std::string result = path + "/";
    for (char c : key) {
        if (c == '~')
            result += "~0";
        else if (c == '/')
            result += "~1";
        else
            result += c;
    }
    return result;
}

std::string childPath(const std::string& path, std::size_t index)
{
    return path + "/" + std::to_string(index);
}

std::string describeJsonValue(const json& value)
{
    switch (value.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
    case json::value_t::string:
        return cut(value.dump(-1, ' ', false, json::error_handler_t::replace), 60);
    default:
        return cut(value.dump(), 60);
    }
}

const json& expectObject(const json& value, const std::string& path)
{
    if (!value.is_object())
        failAt(path, "expected an object, found " + describeJsonValue(value));
    return value;
}

const json& expectArray(const json& value, const std::string& path)
{
    if (!value.is_array())
        failAt(path, "expected an array, found " + describeJsonValue(value));
    return value;
}

bool readBool(const json& value, const std::string& path)
{
    if (!value.is_boolean())
        failAt(path, "expected true or false, found " + describeJsonValue(value));
    return value.get<bool>();
}

std::string readString(const json& value, const std::string& path)
{
    if (!value.is_string())
        failAt(path, "expected a string, found " + describeJsonValue(value));
    return value.get<std::string>();
}

long long readInteger(const json& value, const std::string& path, long long min, long long max)
{
    const auto fail = [&] {
        failAt(path, "expected an integer from " + std::to_string(min) + " to " + std::to_string(max)
            + ", found " + describeJsonValue(value));
    };
    if (value.is_number_integer() && !value.is_number_unsigned()) {
        const auto number = value.get<json::number_integer_t>();
        if (number < min || number > max)
            fail();
        return number;
    }
    if (value.is_number_unsigned()) {
        const auto number = value.get<json::number_unsigned_t>();
        if (max < 0 || number > static_cast<json::number_unsigned_t>(max) || static_cast<long long>(number) < min)
            fail();
        return static_cast<long long>(number);
    }
    if (value.is_number_float()) {
        const double number = value.get<double>();
        if (!std::isfinite(number) || std::floor(number) != number || number < static_cast<double>(min)
            || number > static_cast<double>(max))
            fail();
        return static_cast<long long>(number);
    }
    fail();
    return 0; // not reached: fail() throws
}

const json* findMember(const json& object, std::string_view key)
{
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
}

char firstSignificantCharacter(std::string_view text)
{
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    for (char c : text) {
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
            return c;
    }
    return '\0';
}

} // namespace core
