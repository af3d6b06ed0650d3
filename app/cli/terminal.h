#pragma once

// What the commands print passes through a TerminalStream, which escapes
// control characters and invalid UTF-8 (core::escapeControlCharacters), so
// that user text in a message (a variable name, a condition, a file name)
// can neither break its line nor drive the terminal. A line ends only with
// `lineEnd`; a '\n' inside the text is printed as "\n".

#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace cli {

class TerminalBuffer : public std::streambuf {
public:
    explicit TerminalBuffer(std::ostream& sink);
    ~TerminalBuffer() override;

    TerminalBuffer(const TerminalBuffer&) = delete;
    TerminalBuffer& operator=(const TerminalBuffer&) = delete;

    void endLine();
    void writeVerbatim(std::string_view text);

protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* text, std::streamsize count) override;
    int sync() override;

private:
    void flushPending();

    std::ostream& m_sink;
    std::string m_pending; // escaped as a whole, so multi-byte characters are never split
};

class TerminalStream : public std::ostream {
public:
    explicit TerminalStream(std::ostream& sink);

private:
    TerminalBuffer m_buffer;
};

// Ends the line: the only way a line feed reaches the sink.
std::ostream& lineEnd(std::ostream& stream);

// Text printed as it is: generated code, the help. On a stream that is not
// a TerminalStream, a plain write.
void writeVerbatim(std::ostream& stream, std::string_view text);

} // namespace cli
