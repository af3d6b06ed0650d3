#pragma once

#include <string>
#include <string_view>

namespace core {


// Appends lines and counts them, so the preview knows where each element went.
class LineWriter {
public:
    void line(int indent, std::string_view text)
    {
        m_text.append(static_cast<std::size_t>(indent), ' ');
        m_text.append(text);
        m_text.push_back('\n');
        ++m_lines;
    }
    int lines() const { return m_lines; }
    std::string& text() { return m_text; }

private:
    std::string m_text;
    int m_lines = 0;
};

} // namespace core
