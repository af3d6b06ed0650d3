#include "core/model/iectypes.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <vector>

namespace test_iectypes {

using namespace core;

TEST_CASE("IEC types are listed in spec order and named in upper case", "[iectypes]")
{
    const auto& types = allIecTypes();
    REQUIRE(types.size() == 11);
    CHECK(types.front() == IecType::Bool);
    CHECK(types.back() == IecType::Lreal);
    std::string names;
    for (IecType type : types)
        names += std::string(iecTypeName(type)) + " ";
    CHECK(names == "BOOL SINT INT DINT LINT USINT UINT UDINT ULINT REAL LREAL ");
}

TEST_CASE("IEC type names parse case-insensitively", "[iectypes]")
{
    for (IecType type : allIecTypes()) {
        CHECK(parseIecType(iecTypeName(type)) == type);
        CHECK(parseIecType(toUpperAscii(iecTypeName(type))) == type);
    }
    CHECK(parseIecType("lreal") == IecType::Lreal);
    CHECK(parseIecType("Bool") == IecType::Bool);
    CHECK_FALSE(parseIecType("STRING"));
    CHECK_FALSE(parseIecType(""));
    CHECK_FALSE(parseIecType("INT "));
}

TEST_CASE("IEC type classes", "[iectypes]")
{
    CHECK_FALSE(isNumericType(IecType::Bool));
    CHECK_FALSE(isIntegerType(IecType::Bool));
    CHECK_FALSE(isRealType(IecType::Bool));
    for (IecType type : {IecType::Sint, IecType::Int, IecType::Dint, IecType::Lint, IecType::Usint,
                         IecType::Uint, IecType::Udint, IecType::Ulint}) {
        CHECK(isIntegerType(type));
        CHECK(isNumericType(type));
        CHECK_FALSE(isRealType(type));
    }
    for (IecType type : {IecType::Real, IecType::Lreal}) {
        CHECK(isRealType(type));
        CHECK(isNumericType(type));
        CHECK_FALSE(isIntegerType(type));
    }
}

TEST_CASE("implicit defaults", "[iectypes]")
{
    CHECK(implicitDefault(IecType::Bool) == "FALSE");
    CHECK(implicitDefault(IecType::Usint) == "0");
    CHECK(implicitDefault(IecType::Lint) == "0");
    CHECK(implicitDefault(IecType::Real) == "0.0");
    CHECK(implicitDefault(IecType::Lreal) == "0.0");
    for (IecType type : allIecTypes())
        CHECK(defaultValueProblem(type, implicitDefault(type)).empty());
}

TEST_CASE("BOOL default values", "[iectypes]")
{
    for (const char* ok : {"TRUE", "FALSE", "true", "False", "0", "1", ""})
        CHECK(defaultValueProblem(IecType::Bool, ok).empty());
    CHECK(defaultValueProblem(IecType::Bool, "yes") == "'yes' is not a BOOL literal (TRUE or FALSE)");
    CHECK_FALSE(defaultValueProblem(IecType::Bool, "2").empty());
    CHECK_FALSE(defaultValueProblem(IecType::Bool, "TRUEX").empty());
}

TEST_CASE("integer default values are checked against their range", "[iectypes]")
{
    struct Case {
        IecType type;
        const char* low;
        const char* high;
        const char* belowLow;
        const char* aboveHigh;
        const char* range;
    };
    const Case cases[] = {
        {IecType::Sint, "-128", "127", "-129", "128", "(-128..127)"},
        {IecType::Int, "-32768", "32767", "-32769", "32768", "(-32768..32767)"},
        {IecType::Dint, "-2147483648", "2147483647", "-2147483649", "2147483648", "(-2147483648..2147483647)"},
        {IecType::Lint, "-9223372036854775808", "9223372036854775807", "-9223372036854775809",
         "9223372036854775808", "(-9223372036854775808..9223372036854775807)"},
        {IecType::Usint, "0", "255", "-1", "256", "(0..255)"},
        {IecType::Uint, "0", "65535", "-1", "65536", "(0..65535)"},
        {IecType::Udint, "0", "4294967295", "-1", "4294967296", "(0..4294967295)"},
        {IecType::Ulint, "0", "18446744073709551615", "-1", "18446744073709551616", "(0..18446744073709551615)"},
    };
    for (const Case& c : cases) {
        INFO(iecTypeName(c.type));
        CHECK(defaultValueProblem(c.type, c.low).empty());
        CHECK(defaultValueProblem(c.type, c.high).empty());
        const std::string name(iecTypeName(c.type));
        CHECK(defaultValueProblem(c.type, c.belowLow)
              == "'" + std::string(c.belowLow) + "' is out of range for " + name + " " + c.range);
        CHECK(defaultValueProblem(c.type, c.aboveHigh)
              == "'" + std::string(c.aboveHigh) + "' is out of range for " + name + " " + c.range);
    }
    CHECK(defaultValueProblem(IecType::Sint, "300") == "'300' is out of range for SINT (-128..127)");
    CHECK(defaultValueProblem(IecType::Usint, "-0").empty());
    CHECK(defaultValueProblem(IecType::Int, "+5").empty());
    CHECK(defaultValueProblem(IecType::Int, "007").empty());
    CHECK(defaultValueProblem(IecType::Dint, "1_000_000").empty());
    CHECK(defaultValueProblem(IecType::Lint, "99999999999999999999999999").find("out of range") != std::string::npos);
}

TEST_CASE("malformed integer default values", "[iectypes]")
{
    CHECK(defaultValueProblem(IecType::Int, "abc") == "'abc' is not an INT literal: write a whole number such as 42");
    CHECK(defaultValueProblem(IecType::Sint, "1.5").find("is not a SINT literal") != std::string::npos);
    for (const char* bad : {"1__0", "1_", "_1", "-", "+", "1e3", "0x10", "16#FF", "--1", "1 0", "TRUE"})
        CHECK_FALSE(defaultValueProblem(IecType::Dint, bad).empty());
    CHECK(defaultValueProblem(IecType::Int, " 5") == "' 5' has leading or trailing spaces");
    CHECK(defaultValueProblem(IecType::Int, "5 ") == "'5 ' has leading or trailing spaces");
}

TEST_CASE("real default values", "[iectypes]")
{
    for (const char* ok : {"1.5", "-2.0E3", "2e-2", "3", "+0.5", "1_000.25", "3.4E38", "1e-400"})
        CHECK(defaultValueProblem(IecType::Real, ok).empty());
    CHECK(defaultValueProblem(IecType::Real, "3.5E38") == "'3.5E38' is out of range for REAL (-3.4E38..3.4E38)");
    CHECK(defaultValueProblem(IecType::Real, "-3.5E38").find("out of range for REAL") != std::string::npos);
    CHECK(defaultValueProblem(IecType::Lreal, "3.5E38").empty());
    CHECK(defaultValueProblem(IecType::Lreal, "1e309") == "'1e309' is out of range for LREAL (-1.8E308..1.8E308)");
    CHECK(defaultValueProblem(IecType::Lreal, "abc")
          == "'abc' is not a LREAL literal: write a decimal number such as 1.5 or 2.0E3");
    for (const char* bad : {"1.", ".5", "1.5.3", "1e", "1e+", "1,5", "inf", "nan", "1.5f", "0x1p3"})
        CHECK_FALSE(defaultValueProblem(IecType::Lreal, bad).empty());
}

TEST_CASE("value problems carry their kind and pieces, and the same English text", "[iectypes]")
{
    using Kind = ValueProblem::Kind;
    struct Case {
        IecType type;
        std::string value;
        ValueProblem problem;
        std::string message; // exact
    };
    const std::vector<Case> cases = {
        {IecType::Int, " 5", {Kind::Spaces, " 5", "INT", "", ""}, "' 5' has leading or trailing spaces"},
        {IecType::Bool, "TRUE\t", {Kind::Spaces, "TRUE\t", "BOOL", "", ""}, "'TRUE\t' has leading or trailing spaces"},
        {IecType::Bool, "yes", {Kind::NotBool, "yes", "BOOL", "", ""}, "'yes' is not a BOOL literal (TRUE or FALSE)"},
        {IecType::Int, "abc", {Kind::NotInteger, "abc", "INT", "", ""},
         "'abc' is not an INT literal: write a whole number such as 42"},
        {IecType::Udint, "1.5", {Kind::NotInteger, "1.5", "UDINT", "", ""},
         "'1.5' is not a UDINT literal: write a whole number such as 42"},
        {IecType::Real, "hot", {Kind::NotReal, "hot", "REAL", "", ""},
         "'hot' is not a REAL literal: write a decimal number such as 1.5 or 2.0E3"},
        {IecType::Int, "40000", {Kind::OutOfRange, "40000", "INT", "-32768", "32767"},
         "'40000' is out of range for INT (-32768..32767)"},
        {IecType::Lint, "-9223372036854775809",
         {Kind::OutOfRange, "-9223372036854775809", "LINT", "-9223372036854775808", "9223372036854775807"},
         "'-9223372036854775809' is out of range for LINT (-9223372036854775808..9223372036854775807)"},
        {IecType::Real, "3.5E38", {Kind::OutOfRange, "3.5E38", "REAL", "-3.4E38", "3.4E38"},
         "'3.5E38' is out of range for REAL (-3.4E38..3.4E38)"},
        {IecType::Lreal, "-1e309", {Kind::OutOfRange, "-1e309", "LREAL", "-1.8E308", "1.8E308"},
         "'-1e309' is out of range for LREAL (-1.8E308..1.8E308)"},
    };
    for (const Case& c : cases) {
        INFO(iecTypeName(c.type) << " " << c.value);
        const std::optional<ValueProblem> problem = valueProblem(c.type, c.value);
        REQUIRE(problem.has_value());
        CHECK(*problem == c.problem);
        CHECK(toText(*problem) == c.message);
        CHECK(defaultValueProblem(c.type, c.value) == c.message);

        // The form GG304 appends to Diagnostic::arguments reads back to the same problem.
        std::vector<std::string> arguments{"Speed"};
        appendArguments(*problem, arguments);
        REQUIRE(arguments.size() == 6);
        CHECK(arguments[1] == kindName(c.problem.kind));
        CHECK(valueProblemFromArguments(arguments, 1) == problem);
    }
    CHECK_FALSE(valueProblem(IecType::Int, "").has_value());
    CHECK_FALSE(valueProblem(IecType::Int, "-32768").has_value());

    // Every kind has its own name.
    std::set<std::string_view> names;
    for (int k = 0; k <= static_cast<int>(Kind::OutOfRange); ++k) {
        const std::string_view name = kindName(static_cast<Kind>(k));
        CHECK_FALSE(name.empty());
        CHECK(valueProblemKind(name) == static_cast<Kind>(k));
        names.insert(name);
    }
    CHECK(names.size() == static_cast<std::size_t>(Kind::OutOfRange) + 1);

    // Arguments from elsewhere (an unknown kind, too few) are not read.
    CHECK_FALSE(valueProblemFromArguments({"unknown-kind", "1", "INT", "", ""}, 0));
    CHECK_FALSE(valueProblemFromArguments({"out-of-range", "1", "INT", ""}, 0));
}

TEST_CASE("parseRealLiteral reads IEC decimals without the C locale", "[iectypes]")
{
    CHECK(parseRealLiteral("1.5") == 1.5);
    CHECK(parseRealLiteral("+1.5") == 1.5);
    CHECK(parseRealLiteral("-2.5e2") == -250.0);
    CHECK(parseRealLiteral("1_000.5") == 1000.5);
    CHECK(parseRealLiteral("2E-2").value_or(0.0) == Approx(0.02));
    CHECK(parseRealLiteral("42") == 42.0);
    CHECK(parseRealLiteral("1e-400") == 0.0);
    CHECK(parseRealLiteral("0.0000000000000000000000001e-380") == 0.0);
    CHECK_FALSE(parseRealLiteral("1e400"));
    CHECK_FALSE(parseRealLiteral("1,5"));
    CHECK_FALSE(parseRealLiteral(""));
}

TEST_CASE("identifier rules of spec section 3", "[iectypes]")
{
    CHECK(identifierProblem("Start") == IdentifierProblem::None);
    CHECK(identifierProblem("_Start") == IdentifierProblem::None);
    CHECK(identifierProblem("Motor_On2") == IdentifierProblem::None);
    for (const char* ok : {"MOTOR_ON", "NOTIFY", "DOOR_CLOSED", "ORDER_OK", "ANDY", "NOTX", "Var_Speed", "S", "R"})
        CHECK(identifierProblem(ok) == IdentifierProblem::None);
    CHECK(identifierProblem("") == IdentifierProblem::Empty);
    for (const char* bad : {"1abc", "a b", "a-b", "Température", "a.b", "a$", " a"})
        CHECK(identifierProblem(bad) == IdentifierProblem::InvalidCharacter);
    CHECK(identifierProblem("a__b") == IdentifierProblem::DoubleUnderscore);
    CHECK(identifierProblem("__a") == IdentifierProblem::DoubleUnderscore);
    CHECK(identifierProblem("a_") == IdentifierProblem::TrailingUnderscore);
    CHECK(identifierProblem("_") == IdentifierProblem::TrailingUnderscore);
    CHECK(identifierProblem("if") == IdentifierProblem::Keyword);
    CHECK(identifierProblem("Int") == IdentifierProblem::Keyword);
    CHECK(identifierProblem("State") == IdentifierProblem::GeneratorName);
}

TEST_CASE("IEC keywords, case-insensitive", "[iectypes]")
{
    for (const char* word :
         {"AND", "OR", "XOR", "NOT", "MOD", "IF", "THEN", "ELSIF", "ELSE", "END_IF", "CASE", "OF", "END_CASE", "FOR",
          "TO", "BY", "DO", "WHILE", "REPEAT", "UNTIL", "EXIT", "RETURN", "TRUE", "FALSE", "VAR", "VAR_INPUT",
          "VAR_OUTPUT", "VAR_IN_OUT", "VAR_GLOBAL", "VAR_EXTERNAL", "VAR_TEMP", "END_VAR", "PROGRAM", "FUNCTION",
          "FUNCTION_BLOCK", "CONFIGURATION", "RESOURCE", "TASK", "WITH", "ON", "AT", "STEP", "TRANSITION", "ACTION",
          "INITIAL_STEP", "FROM", "RETAIN", "CONSTANT", "END_FOR", "END_WHILE", "END_REPEAT", "END_PROGRAM",
          "END_FUNCTION_BLOCK", "END_FUNCTION", "END_CONFIGURATION", "END_RESOURCE", "END_STEP", "END_TRANSITION",
          "END_ACTION", "R_EDGE", "F_EDGE", "EN", "ENO", "SINGLE", "INTERVAL", "PRIORITY", "NIL", "REF", "REF_TO",
          "THIS", "SUPER", "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL",
          "STRING", "WSTRING", "TIME", "DATE", "TOD", "TIME_OF_DAY", "DT", "DATE_AND_TIME", "BYTE", "WORD",
          "DWORD", "LWORD", "ANY", "ANY_INT", "ANY_NUM", "ANY_BIT", "TON", "TOF", "TP", "CTU", "R_TRIG", "F_TRIG"}) {
        INFO(word);
        CHECK(isIecKeyword(word));
        std::string lower(word);
        for (char& c : lower)
            c = static_cast<char>(c >= 'A' && c <= 'Z' ? c + 32 : c);
        CHECK(isIecKeyword(lower));
        CHECK(identifierProblem(word) == IdentifierProblem::Keyword);
    }
    for (const char* word : {"Start", "ANDY", "NOTIFY", "ORDER", "IFF", "VAR_", "VARX", "END", "A", "Z", "ZZZ", "_"})
        CHECK_FALSE(isIecKeyword(word));
}

TEST_CASE("names the generator uses", "[iectypes]")
{
    for (const char* word :
         {"GEMMA", "gemma", "State", "STATE", "entry", "Initialization", "COMPLETE", "GVL", "gvl",
          "GemmaConfiguration", "GEMMARESOURCE", "MainTask", "GemmaInstance", "Stop_F1_3_MEM", "stop_f1_12_mem",
          "X_A7_1_MEM", "My_Var_D3_2_Mem"}) {
        INFO(word);
        CHECK(isGeneratorName(word));
    }
    // The step instances and function blocks depend on the model (core/model/stepnames.h).
    for (const char* word : {"A1", "a7", "F1", "d3", "A1_FB", "f4_fb", "A8", "F7", "D0", "A", "A1_FB2", "F1_3_MEM",
                             "Stop_F1_MEM", "Stop_X1_3_MEM",
                             "Stop_F1_x_MEM", "Stop_F1_3_MEMO", "Gemma2", "Start", "_F1_3_MEM"}) {
        INFO(word);
        CHECK_FALSE(isGeneratorName(word));
    }
}

TEST_CASE("identifier problem messages name the identifier", "[iectypes]")
{
    CHECK(identifierProblemMessage(IdentifierProblem::None, "x").empty());
    CHECK_FALSE(identifierProblemMessage(IdentifierProblem::Empty, "").empty());
    for (IdentifierProblem problem :
         {IdentifierProblem::InvalidCharacter, IdentifierProblem::DoubleUnderscore,
          IdentifierProblem::TrailingUnderscore, IdentifierProblem::Keyword, IdentifierProblem::GeneratorName}) {
        const std::string message = identifierProblemMessage(problem, "Bad_Name");
        CHECK(message.find("'Bad_Name'") != std::string::npos);
    }
    CHECK(identifierProblemMessage(IdentifierProblem::Keyword, "IF") == "'IF' is an IEC 61131-3 keyword or type name");
}

TEST_CASE("ASCII case helpers", "[iectypes]")
{
    CHECK(equalsIgnoreCase("Motor_On", "MOTOR_ON"));
    CHECK_FALSE(equalsIgnoreCase("Motor", "Motor_"));
    CHECK_FALSE(equalsIgnoreCase("a_", "a-"));
    CHECK(toUpperAscii("abc_Z9é") == "ABC_Z9é");
    CHECK(equalsIgnoreCase("", ""));
}

} // namespace test_iectypes
