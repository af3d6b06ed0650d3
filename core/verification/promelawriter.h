#pragma once

// Writes Promela text line by line with its indentation, counting lines so
// that a marker's line can be named (the SPIN cross-checks read pan's
// unreached-code report by line).

#include <cstddef>
#include <string>
#include <utility>

namespace core {

class PromelaWriter {
public:
    // Returns the 1-based number of the line written.
    int line(const std::string& text)
    {
        if (!text.empty())
            m_text.append(static_cast<std::size_t>(m_indent) * 4, ' ');
        m_text += text;
        m_text += '\n';
        return ++m_lines;
    }
    void in() { ++m_indent; }
    void out() { --m_indent; }
    std::string take() { return std::move(m_text); }

private:
    std::string m_text;
    int m_lines = 0;
    int m_indent = 0;
};

} // namespace core
