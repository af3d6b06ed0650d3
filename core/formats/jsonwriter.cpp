#include "core/formats/jsonwriter.h"

namespace core {

namespace {

// What nlohmann writes unchanged between the quotes: printable ASCII but the
// quote and the backslash. Anything else (controls, non-ASCII, invalid UTF-8)
// takes nlohmann's escaping.
bool isPlainJsonText(std::string_view text)
{
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte > 0x7E || c == '"' || c == '\\')
            return false;
    }
    return true;
}

} // namespace

void JsonWriter::newLine()
{
    m_text += '\n';
    m_text.append(2 * m_levels.size(), ' ');
}

void JsonWriter::beforeValue()
{
    if (m_levels.empty() || !m_levels.back().array)
        return; // at the top, or after a key
    if (!m_levels.back().empty)
        m_text += ',';
    m_levels.back().empty = false;
    newLine();
}

void JsonWriter::quoted(std::string_view text)
{
    if (isPlainJsonText(text)) {
        m_text += '"';
        m_text += text;
        m_text += '"';
    } else {
        m_text += nlohmann::ordered_json(std::string(text)).dump(-1, ' ', false,
                                                                 nlohmann::ordered_json::error_handler_t::replace);
    }
}

void JsonWriter::beginObject()
{
    beforeValue();
    m_text += '{';
    m_levels.push_back({false, true});
}

void JsonWriter::beginArray()
{
    beforeValue();
    m_text += '[';
    m_levels.push_back({true, true});
}

void JsonWriter::close(char bracket)
{
    const bool empty = m_levels.back().empty;
    m_levels.pop_back();
    if (!empty)
        newLine();
    m_text += bracket;
}

void JsonWriter::endObject()
{
    close('}');
}

void JsonWriter::endArray()
{
    close(']');
}

void JsonWriter::key(std::string_view name)
{
    Level& level = m_levels.back();
    if (!level.empty)
        m_text += ',';
    level.empty = false;
    newLine();
    quoted(name);
    m_text += ": ";
}

void JsonWriter::string(std::string_view text)
{
    beforeValue();
    quoted(text);
}

void JsonWriter::boolean(bool value)
{
    beforeValue();
    m_text += value ? "true" : "false";
}

void JsonWriter::integer(std::int64_t value)
{
    beforeValue();
    m_text += std::to_string(value);
}

void JsonWriter::value(const nlohmann::ordered_json& value)
{
    switch (value.type()) {
    case nlohmann::ordered_json::value_t::object:
        beginObject();
        for (const auto& [name, member] : value.items()) {
            key(name);
            this->value(member);
        }
        endObject();
        return;
    case nlohmann::ordered_json::value_t::array:
        beginArray();
        for (const auto& element : value)
            this->value(element);
        endArray();
        return;
    case nlohmann::ordered_json::value_t::string:
        string(value.get_ref<const std::string&>());
        return;
    default: // numbers, booleans, null: one token, whatever the indentation
        beforeValue();
        m_text += value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
        return;
    }
}

} // namespace core
