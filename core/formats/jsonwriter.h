#pragma once

// Writes JSON text straight from the data, byte for byte as
// nlohmann::ordered_json::dump(2, ' ', false, error_handler_t::replace) writes
// the same values (two-space indentation, "key": value, "{}" and "[]" when
// empty), without building a DOM first: saving a large model was mostly the
// building and freeing of that DOM (issue #36). Strings that are not plain
// printable ASCII go through nlohmann's own escaping, so invalid UTF-8 is
// replaced exactly as before.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class JsonWriter {
public:
    void beginObject();
    void endObject();
    void beginArray();
    void endArray();

    // The next member of the current object; its value follows.
    void key(std::string_view name);

    // Distinct names rather than overloads: a string literal would otherwise
    // convert to bool.
    void string(std::string_view text);
    void boolean(bool value);
    void integer(std::int64_t value);
    // Any value, written as dump(2) would write it at this place.
    void value(const nlohmann::ordered_json& value);

    // The text written so far (the caller closes every object and array first).
    const std::string& text() const { return m_text; }
    std::string take() { return std::move(m_text); }

private:
    struct Level {
        bool array = false;
        bool empty = true;
    };

    void beforeValue();
    void newLine();
    void quoted(std::string_view text);
    void close(char bracket);

    std::string m_text;
    std::vector<Level> m_levels;
};

} // namespace core
