#include <catch2/catch.hpp>

#include "core/model/model.h"
#include "core/verification/promela.h"
#include "core/verification/promelaprogram.h"
#include "hostilemodels.h"

#include <regex>
#include <string>

namespace test_promela {

using namespace core;

namespace {

// The Promela text with its /* */ comments removed; fails on one left open.
std::string promelaCode(const std::string& text)
{
    std::string code;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find("/*", at);
        code += text.substr(at, open == std::string::npos ? std::string::npos : open - at);
        if (open == std::string::npos)
            break;
        const std::size_t close = text.find("*/", open + 2);
        REQUIRE(close != std::string::npos);
        at = close + 2;
    }
    return code;
}

} // namespace

// `verify --promela` writes user names into a program SPIN compiles: only
// identifiers may get there, never a name the code cannot declare.
TEST_CASE("Promela of models with hostile user text names only identifiers", "[promela][property]")
{
    const std::regex input("\\b(in|tk)_[A-Za-z0-9_]*");
    for (std::uint32_t seed = 1; seed <= 80; ++seed) {
        INFO("hostile model " << seed);
        const Model model = samples::hostileModel(seed);
        const std::string code = promelaCode(exportPromela(model));
        CHECK(code.find(samples::kInjectedMarker) == std::string::npos);
        for (char c : code) {
            INFO("character " << static_cast<int>(static_cast<unsigned char>(c)));
            CHECK(((c >= ' ' && c <= '~') || c == '\n'));
        }
        // An input is a declared variable with a name the code can use.
        for (auto match = std::sregex_iterator(code.begin(), code.end(), input); match != std::sregex_iterator();
             ++match) {
            const std::string name = match->str().substr(3);
            INFO("Promela name " << match->str());
            const std::size_t end = static_cast<std::size_t>(match->position() + match->length());
            CHECK((end >= code.size() || code[end] != '.'));
            if (match->str().rfind("in_", 0) == 0) // tk_ names are the generator's own: X_F1_2_MEM
                CHECK(identifierProblem(name) == IdentifierProblem::None);
        }
    }
}

// The model name goes into the header comment of both Promela models: no
// control character, bidi override or comment delimiter may survive there.
TEST_CASE("Promela headers escape the model name as the ST writer escapes comments", "[promela]")
{
    Model model;
    const std::string hostile = std::string("Cell\0one", 8) + "\x1b[31m red \xE2\x80\xAE evil */ x /* y\nnext";
    REQUIRE(model.setName(hostile));
    for (const std::string& text : {exportPromela(model), buildProgramPromela(model).text}) {
        const std::string header = text.substr(0, text.find("*/", 2) + 2);
        INFO(header);
        CHECK(header.find("Cell?one") != std::string::npos);
        CHECK(header.find('\0') == std::string::npos);
        CHECK(header.find('\x1b') == std::string::npos);
        CHECK(header.find("\xE2\x80\xAE") == std::string::npos);
        CHECK(header.find("evil * / x / * y next") != std::string::npos);
        promelaCode(text); // every comment closes where it should
        const std::string code = promelaCode(text);
        CHECK(code.find("evil") == std::string::npos);
    }
}

// The condition language admits only ASCII identifiers, so no name injects
// code; but one the generated ST cannot declare (here a generator name) makes
// the condition FALSE there, and Promela must model the same program.
TEST_CASE("A condition reading a name the code cannot use reaches Promela as FALSE", "[promela]")
{
    Model model;
    REQUIRE(model.addVariable({"State", IecType::Bool, "", ""}));
    REQUIRE(model.addVariable({"Start", IecType::Bool, "", ""}));
    REQUIRE(model.setCondition("A6->A1", "State OR Start"));
    REQUIRE(model.setCondition("A1->F1", "Start"));
    const std::string code = promelaCode(exportPromela(model));
    CHECK(code.find("in_State") == std::string::npos);
    CHECK(code.find("in_Start") != std::string::npos);
}

} // namespace test_promela
