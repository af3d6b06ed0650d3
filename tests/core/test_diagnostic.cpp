#include <catch2/catch.hpp>

#include "core/checks/diagnostic.h"

#include <string>

namespace test_diagnostic {

using namespace core;

TEST_CASE("control characters in user text are escaped for the terminal", "[diagnostic]")
{
    CHECK(escapeControlCharacters("Start_Button") == "Start_Button");
    CHECK(escapeControlCharacters("Arrêt d'urgence") == "Arrêt d'urgence");
    CHECK(escapeControlCharacters("a\nb\rc\td") == "a\\nb\\rc\\td");
    CHECK(escapeControlCharacters("\x1b]0;x\x07") == "\\x1b]0;x\\x07");
    CHECK(escapeControlCharacters(std::string("nul\0end", 7)) == "nul\\x00end");
    CHECK(escapeControlCharacters("del\x7f") == "del\\x7f");
    CHECK(escapeControlCharacters("back\\slash") == "back\\\\slash"); // reversible: "\\n" is not a line feed
    // C1 controls, as UTF-8: U+0085 (NEL), U+009B (CSI).
    CHECK(escapeControlCharacters("x\xc2\x85y\xc2\x9b") == "x\\u0085y\\u009b");
    CHECK(escapeControlCharacters("\xc2\xa0") == "\xc2\xa0"); // U+00A0 is not a control
    // Bidi embeddings, overrides and isolates; line and paragraph separators.
    CHECK(escapeControlCharacters("\xe2\x80\xaa\xe2\x80\xae") == "\\u202a\\u202e");
    CHECK(escapeControlCharacters("\xe2\x81\xa6\xe2\x81\xa9") == "\\u2066\\u2069");
    CHECK(escapeControlCharacters("\xe2\x80\xa8\xe2\x80\xa9") == "\\u2028\\u2029");
    CHECK(escapeControlCharacters("\xe2\x80\xa9x") == "\\u2029x");
    CHECK(escapeControlCharacters("\xe2\x80\x94") == "\xe2\x80\x94"); // an em dash stays
    // Invalid UTF-8: each byte that starts no valid character.
    CHECK(escapeControlCharacters("bad\xff") == "bad\\xff");
    CHECK(escapeControlCharacters("\xc3") == "\\xc3");                      // truncated
    CHECK(escapeControlCharacters("\xc0\xaf") == "\\xc0\\xaf");              // overlong '/'
    CHECK(escapeControlCharacters("\xed\xa0\x80") == "\\xed\\xa0\\x80");     // a surrogate
    CHECK(escapeControlCharacters("\xe2\x80") == "\\xe2\\x80");              // cut short
    CHECK(escapeControlCharacters("\xf0\x9f\x98\x80") == "\xf0\x9f\x98\x80"); // U+1F600 stays
}

TEST_CASE("the escaped text is one line with no control character", "[diagnostic]")
{
    std::string everyByte;
    for (int c = 0; c < 256; ++c)
        everyByte += static_cast<char>(c);
    const std::string escaped = escapeControlCharacters(everyByte + "\xe2\x80\xae\xc2\x9b");
    for (std::size_t i = 0; i < escaped.size();) {
        const Utf8Character character = decodeUtf8(std::string_view(escaped).substr(i));
        INFO("offset " << i);
        REQUIRE(character.valid);
        CHECK_FALSE(isControlCharacter(character.codePoint));
        i += character.length;
    }
}

} // namespace test_diagnostic
