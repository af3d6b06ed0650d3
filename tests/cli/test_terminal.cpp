#include <catch2/catch.hpp>

#include "commands.h"
#include "terminal.h"

#include <sstream>
#include <string>

TEST_CASE("a TerminalStream escapes what it is given; only lineEnd ends a line", "[terminal]")
{
    std::ostringstream sink;
    {
        cli::TerminalStream out(sink);
        out << "name: " << std::string("a\nb\x1b]0;x\x07") << cli::lineEnd;
        out << "count " << 3 << ", split \xe2\x80";
        out << "\xae character" << cli::lineEnd;
        cli::writeVerbatim(out, "CODE\n\tkept\n");
        out << "unfinished\r";
    }
    CHECK(sink.str() == "name: a\\nb\\x1b]0;x\\x07\ncount 3, split \\u202e character\nCODE\n\tkept\nunfinished\\r");
}

TEST_CASE("lineEnd and writeVerbatim on another stream write plainly", "[terminal]")
{
    std::ostringstream plain;
    plain << "x" << cli::lineEnd;
    cli::writeVerbatim(plain, "y\n");
    CHECK(plain.str() == "x\ny\n");
}

TEST_CASE("file names in messages are escaped, invalid UTF-8 included", "[terminal]")
{
    std::ostringstream out;
    std::ostringstream err;
    const int code = cli::run({"validate", "no-such-dir/\xff\x1b]0;x\x07\nforged.json"}, {out, err});
    CHECK(code == cli::UnreadableInput);
    const std::string text = err.str();
    INFO(text);
    CHECK(text.find("no-such-dir/\\xff\\x1b]0;x\\x07\\nforged.json") != std::string::npos);
    CHECK(text.find('\x1b') == std::string::npos);
    CHECK(text.find('\n') == text.size() - 1); // one line
}
