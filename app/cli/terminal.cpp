#include "terminal.h"

#include "core/checks/diagnostic.h"

namespace cli {

TerminalBuffer::TerminalBuffer(std::ostream& sink)
    : m_sink(sink)
{
}

TerminalBuffer::~TerminalBuffer()
{
    flushPending();
    m_sink.flush();
}

void TerminalBuffer::endLine()
{
    flushPending();
    m_sink.put('\n');
}

void TerminalBuffer::writeVerbatim(std::string_view text)
{
    flushPending();
    m_sink.write(text.data(), static_cast<std::streamsize>(text.size()));
}

TerminalBuffer::int_type TerminalBuffer::overflow(int_type c)
{
    if (traits_type::eq_int_type(c, traits_type::eof()))
        return traits_type::not_eof(c);
    m_pending.push_back(traits_type::to_char_type(c));
    return c;
}

std::streamsize TerminalBuffer::xsputn(const char* text, std::streamsize count)
{
    m_pending.append(text, static_cast<std::size_t>(count));
    return count;
}

int TerminalBuffer::sync()
{
    flushPending();
    m_sink.flush();
    return m_sink ? 0 : -1;
}

void TerminalBuffer::flushPending()
{
    if (m_pending.empty())
        return;
    m_sink << core::escapeControlCharacters(m_pending);
    m_pending.clear();
}

TerminalStream::TerminalStream(std::ostream& sink)
    : std::ostream(nullptr)
    , m_buffer(sink)
{
    rdbuf(&m_buffer);
}

std::ostream& lineEnd(std::ostream& stream)
{
    if (auto* terminal = dynamic_cast<TerminalBuffer*>(stream.rdbuf()))
        terminal->endLine();
    else
        stream.put('\n');
    return stream;
}

void writeVerbatim(std::ostream& stream, std::string_view text)
{
    if (auto* terminal = dynamic_cast<TerminalBuffer*>(stream.rdbuf()))
        terminal->writeVerbatim(text);
    else
        stream.write(text.data(), static_cast<std::streamsize>(text.size()));
}

} // namespace cli
