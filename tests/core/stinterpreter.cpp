#include "stinterpreter.h"

#include "core/condition/conditionparser.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <cctype>
#include <functional>

namespace sttest {

using core::cond::Value;

struct StInterpreter::Statement {
    enum class Kind { Assign, Call, If, Case, Repeat };
    Kind kind = Kind::Assign;
    StReference target;  // Assign: the variable written
    int callee = -1;     // Call: the FB instance (program) or the TON (FB body)
    bool calleeIsTon = false;
    std::vector<std::pair<std::string, StExpression>> arguments; // Call: upper-case parameter -> value
    StExpression value;  // Assign: right side; Case: selector; Repeat: the UNTIL condition
    std::vector<std::pair<StExpression, std::vector<Statement>>> branches; // If: IF/ELSIF branches
    std::vector<Statement> elseBranch; // If: ELSE; Repeat: the body
    std::vector<std::pair<std::int64_t, std::vector<Statement>>> cases;   // Case: label -> statements
};

// A FUNCTION_BLOCK type: its variables (inputs, outputs, locals) by slot,
// its TONs, the globals it declares VAR_EXTERNAL and its body.
struct StInterpreter::Pou {
    std::string name; // upper case: "F1_FB"
    bool skeleton = false;
    bool risingEdge = false; // the standard R_TRIG: CLK in, Q out, M memory
    struct Slot {
        std::string name; // as declared
        core::IecType type = core::IecType::Bool;
        Value initial;
        bool output = false;
    };
    std::vector<Slot> slots;
    std::map<std::string, int> slotOf; // upper-case name
    std::vector<std::string> tons;
    std::map<std::string, int> tonOf;
    std::map<std::string, int> externals; // upper-case name -> global slot
    std::vector<Statement> body;
    int initialization = -1;
    int complete = -1;
};

namespace {

// IEC 61131-3 TON, as matiec's standard library writes it.
struct Ton {
    bool in = false;
    bool previousIn = false;
    bool q = false;
    int state = 0; // 0 idle, 1 timing, 2 elapsed
    std::int64_t pt = 0;
    std::int64_t et = 0;
    std::int64_t start = 0;

    void call(bool input, std::int64_t preset, std::int64_t now)
    {
        in = input;
        pt = preset;
        if (state == 0 && !previousIn && in) {
            state = 1;
            q = false;
            start = now;
        } else if (!in) {
            et = 0;
            q = false;
            state = 0;
        } else if (state == 1) {
            if (start + pt <= now) {
                state = 2;
                q = true;
                et = pt;
            } else {
                et = now - start;
            }
        }
        previousIn = in;
    }
};

} // namespace

struct StInterpreter::Instance {
    std::string name;
    const Pou* pou = nullptr;
    std::vector<Value> values; // by Pou slot
    std::vector<Ton> tons;
    std::optional<bool> manual; // skeleton only
};

namespace {

std::string upper(std::string_view text)
{
    return core::toUpperAscii(text);
}

// Comments become spaces, so offsets stay meaningful.
std::string stripComments(std::string_view text)
{
    std::string out(text);
    std::size_t at = 0;
    while ((at = out.find("(*", at)) != std::string::npos) {
        const std::size_t end = out.find("*)", at + 2);
        const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
        for (std::size_t i = at; i < stop; ++i) {
            if (out[i] != '\n')
                out[i] = ' ';
        }
        at = stop;
    }
    return out;
}

struct Lexeme {
    enum class Kind { Word, Number, Symbol, End };
    Kind kind = Kind::End;
    std::string text;
    std::size_t begin = 0;
    std::size_t end = 0;
};

std::vector<Lexeme> lex(const std::string& text)
{
    std::vector<Lexeme> out;
    std::size_t i = 0;
    auto isWordChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    while (i < text.size()) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        Lexeme lexeme;
        lexeme.begin = i;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            while (i < text.size() && isWordChar(text[i]))
                ++i;
            lexeme.kind = Lexeme::Kind::Word;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            // Integers and reals: digits, '.', exponent with sign, '_'.
            while (i < text.size()
                   && (isWordChar(text[i]) || text[i] == '.'
                       || ((text[i] == '+' || text[i] == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E'))))
                ++i;
            lexeme.kind = Lexeme::Kind::Number;
        } else {
            static const char* const twoChar[] = {":=", "<>", "<=", ">="};
            lexeme.kind = Lexeme::Kind::Symbol;
            bool two = false;
            for (const char* symbol : twoChar) {
                if (text.compare(i, 2, symbol) == 0)
                    two = true;
            }
            i += two ? 2 : 1;
        }
        lexeme.end = i;
        lexeme.text = text.substr(lexeme.begin, lexeme.end - lexeme.begin);
        out.push_back(std::move(lexeme));
    }
    Lexeme end;
    end.begin = end.end = text.size();
    out.push_back(end);
    return out;
}

// "F1.Complete" -> "F1__Complete", which the condition parser reads as one identifier.
std::string rewriteMembers(std::string text)
{
    std::size_t at = 0;
    while ((at = text.find('.', at)) != std::string::npos) {
        const bool member = at > 0 && at + 1 < text.size()
            && (std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_')
            && (std::isalpha(static_cast<unsigned char>(text[at + 1])) || text[at + 1] == '_');
        // A digit before the dot with only digits before it is a real literal.
        std::size_t start = at;
        while (start > 0 && (std::isalnum(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '_'))
            --start;
        const bool number = std::isdigit(static_cast<unsigned char>(text[start]));
        if (member && !number) {
            text.replace(at, 1, "__");
            at += 2;
        } else {
            ++at;
        }
    }
    return text;
}


// How the names of one POU resolve (IEC scoping).
struct Scope {
    // An identifier of an expression or an assignment target (upper case,
    // "F1__COMPLETE" for F1.Complete); nullopt with `why` set when it is not declared.
    std::function<std::optional<StReference>(const std::string& name, std::string& why)> resolve;
    // The instance called: index of an FB instance (program) or of a TON
    // (FB body), -1 when the name is neither.
    std::function<int(const std::string& name)> callee;
    bool calleesAreTons = false;
};

class BodyParser {
public:
    BodyParser(const std::string& text, const Scope& scope, std::string& error)
        : m_text(text), m_lexemes(lex(text)), m_scope(scope), m_error(error)
    {
    }

    std::vector<StInterpreter::Statement> parse()
    {
        std::vector<StInterpreter::Statement> body = statements();
        if (m_error.empty() && peek().kind != Lexeme::Kind::End)
            fail("unexpected '" + peek().text + "'");
        return body;
    }

private:
    const Lexeme& peek(std::size_t ahead = 0) const
    {
        return m_lexemes[std::min(m_next + ahead, m_lexemes.size() - 1)];
    }
    bool isWord(const Lexeme& lexeme, std::string_view word) const
    {
        return lexeme.kind == Lexeme::Kind::Word && core::equalsIgnoreCase(lexeme.text, word);
    }
    void fail(const std::string& message)
    {
        if (m_error.empty()) {
            const std::size_t at = peek().begin;
            const std::size_t lineStart = m_text.rfind('\n', at == 0 ? 0 : at - 1);
            const std::size_t from = lineStart == std::string::npos ? 0 : lineStart + 1;
            const std::size_t lineEnd = m_text.find('\n', at);
            m_error = message + " (in the line '" + m_text.substr(from, lineEnd == std::string::npos ? std::string::npos : lineEnd - from) + "')";
        }
        m_next = m_lexemes.size() - 1;
    }
    bool take(std::string_view text)
    {
        if (core::equalsIgnoreCase(peek().text, text) && peek().kind != Lexeme::Kind::End) {
            ++m_next;
            return true;
        }
        fail("expected '" + std::string(text) + "', found '" + peek().text + "'");
        return false;
    }

    bool atStop() const
    {
        const Lexeme& l = peek();
        if (l.kind == Lexeme::Kind::End)
            return true;
        for (const char* stop : {"ELSIF", "ELSE", "END_IF", "END_CASE", "UNTIL", "END_REPEAT"}) {
            if (isWord(l, stop))
                return true;
        }
        // A CASE label: an integer followed by ':'.
        return l.kind == Lexeme::Kind::Number && peek(1).text == ":";
    }

    // Binds the identifiers of a parsed expression to what they denote.
    void bind(StExpression& expression)
    {
        expression.references.assign(expression.parsed.nodes.size(), StReference{});
        for (std::size_t i = 0; i < expression.parsed.nodes.size(); ++i) {
            const core::cond::Node& node = expression.parsed.nodes[i];
            switch (node.kind) {
            case core::cond::NodeKind::Variable: {
                std::string why;
                if (const std::optional<StReference> reference = m_scope.resolve(upper(node.text), why))
                    expression.references[i] = *reference;
                else
                    fail(why + " in '" + expression.text + "'");
                break;
            }
            case core::cond::NodeKind::StepActivity:
            case core::cond::NodeKind::StepDuration:
            case core::cond::NodeKind::Complete:
                fail("a nested-GRAFCET construct in the generated text '" + expression.text + "'");
                break;
            default: break;
            }
        }
    }

    // The text up to (not including) the first of `stops` outside parentheses.
    StExpression expressionUntil(std::initializer_list<std::string_view> stops, bool allowDuration = false)
    {
        const std::size_t first = m_next;
        int depth = 0;
        const auto isStop = [&](const Lexeme& l) {
            for (std::string_view stop : stops) {
                if (core::equalsIgnoreCase(l.text, stop))
                    return true;
            }
            return false;
        };
        while (peek().kind != Lexeme::Kind::End && !(depth == 0 && isStop(peek()))) {
            if (peek().text == "(")
                ++depth;
            else if (peek().text == ")")
                --depth;
            ++m_next;
        }
        if (m_next == first) {
            fail("expected an expression before '" + peek().text + "'");
            return {};
        }
        StExpression expression;
        expression.text = m_text.substr(m_lexemes[first].begin, m_lexemes[m_next - 1].end - m_lexemes[first].begin);
        const std::string head = upper(expression.text.substr(0, 5));
        if (head.rfind("T#", 0) == 0 || head.rfind("TIME#", 0) == 0) {
            if (!allowDuration) {
                fail("a TIME literal where the generator writes none: '" + expression.text + "'");
                return expression;
            }
            expression.durationMs = core::cond::parseDurationMs(expression.text);
            if (!expression.durationMs)
                fail("cannot read the TIME literal '" + expression.text + "'");
            return expression;
        }
        expression.text = rewriteMembers(expression.text);
        core::cond::ParseResult parsed = core::cond::parse(expression.text);
        if (!parsed.ok()) {
            fail("cannot parse '" + expression.text + "': " + parsed.error->message);
            return expression;
        }
        expression.parsed = std::move(parsed.expression);
        bind(expression);
        return expression;
    }

    std::vector<StInterpreter::Statement> statements()
    {
        std::vector<StInterpreter::Statement> out;
        while (m_error.empty() && !atStop())
            out.push_back(statement());
        return out;
    }

    StInterpreter::Statement statement()
    {
        using Statement = StInterpreter::Statement;
        Statement s;
        if (isWord(peek(), "IF")) {
            ++m_next;
            s.kind = Statement::Kind::If;
            StExpression condition = expressionUntil({"THEN"});
            take("THEN");
            s.branches.emplace_back(std::move(condition), statements());
            while (m_error.empty() && isWord(peek(), "ELSIF")) {
                ++m_next;
                StExpression next = expressionUntil({"THEN"});
                take("THEN");
                s.branches.emplace_back(std::move(next), statements());
            }
            if (isWord(peek(), "ELSE")) {
                ++m_next;
                s.elseBranch = statements();
            }
            take("END_IF");
            take(";");
            return s;
        }
        if (isWord(peek(), "CASE")) {
            ++m_next;
            s.kind = Statement::Kind::Case;
            s.value = expressionUntil({"OF"});
            take("OF");
            while (m_error.empty() && peek().kind == Lexeme::Kind::Number) {
                const std::int64_t label = std::stoll(peek().text);
                ++m_next;
                take(":");
                s.cases.emplace_back(label, statements());
            }
            take("END_CASE");
            take(";");
            return s;
        }
        if (isWord(peek(), "REPEAT")) {
            ++m_next;
            s.kind = Statement::Kind::Repeat;
            s.elseBranch = statements();
            take("UNTIL");
            s.value = expressionUntil({"END_REPEAT"});
            take("END_REPEAT");
            take(";");
            return s;
        }
        if (peek().kind != Lexeme::Kind::Word) {
            fail("expected a statement, found '" + peek().text + "'");
            return s;
        }
        const std::string name = upper(peek().text);
        ++m_next;
        if (peek().text == "(") {
            ++m_next;
            s.kind = Statement::Kind::Call;
            s.callee = m_scope.callee(name);
            s.calleeIsTon = m_scope.calleesAreTons;
            if (s.callee < 0) {
                fail(name + " is not an instance this POU can call");
                return s;
            }
            while (m_error.empty() && peek().text != ")") {
                if (peek().kind != Lexeme::Kind::Word || peek(1).text != ":=") {
                    fail("expected a named argument 'NAME :=' in the call of " + name);
                    return s;
                }
                std::string parameter = upper(peek().text);
                m_next += 2;
                s.arguments.emplace_back(std::move(parameter), expressionUntil({",", ")"}, s.calleeIsTon));
                if (peek().text == ",")
                    ++m_next;
            }
            take(")");
            take(";");
            return s;
        }
        s.kind = Statement::Kind::Assign;
        std::string why;
        if (const std::optional<StReference> target = m_scope.resolve(name, why)) {
            if (target->kind != StReference::Kind::Global && target->kind != StReference::Kind::Local) {
                fail("assignment to " + name + ", which this POU cannot write");
                return s;
            }
            s.target = *target;
        } else {
            fail(why);
            return s;
        }
        take(":=");
        s.value = expressionUntil({";"});
        take(";");
        return s;
    }

    const std::string& m_text;
    std::vector<Lexeme> m_lexemes;
    std::size_t m_next = 0;
    const Scope& m_scope;
    std::string& m_error;
};

struct Declaration {
    std::string name;
    std::string type;
    std::string initial;
    std::string block; // VAR, VAR_EXTERNAL, VAR_GLOBAL, ...
};

// `name : TYPE [:= value];` lines inside VAR* ... END_VAR blocks; returns
// the offset just past the last END_VAR.
std::size_t readDeclarations(const std::string& text, std::vector<Declaration>& out, std::string& error)
{
    std::size_t lastEnd = 0;
    std::string block;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
            end = text.size();
        std::string line = text.substr(start, end - start);
        const std::size_t first = line.find_first_not_of(" \t\r");
        line = first == std::string::npos ? std::string() : line.substr(first);
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r' || line.back() == '\t'))
            line.pop_back();
        const std::string word = upper(line.substr(0, line.find(' ')));
        if (word.rfind("VAR", 0) == 0 && line.find(':') == std::string::npos) {
            block = word;
        } else if (word == "END_VAR") {
            block.clear();
            lastEnd = end;
        } else if (!block.empty() && !line.empty()) {
            const std::size_t colon = line.find(':');
            const std::size_t semicolon = line.find(';');
            if (colon == std::string::npos || semicolon == std::string::npos) {
                error = "cannot read the declaration '" + line + "'";
                return lastEnd;
            }
            Declaration d;
            d.block = block;
            d.name = line.substr(0, colon);
            while (!d.name.empty() && d.name.back() == ' ')
                d.name.pop_back();
            std::string rest = line.substr(colon + 1, semicolon - colon - 1);
            const std::size_t assign = rest.find(":=");
            d.type = rest.substr(0, assign);
            if (assign != std::string::npos)
                d.initial = rest.substr(assign + 2);
            auto trim = [](std::string& s) {
                const std::size_t a = s.find_first_not_of(' ');
                const std::size_t b = s.find_last_not_of(' ');
                s = a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
            };
            trim(d.type);
            trim(d.initial);
            out.push_back(std::move(d));
        }
        start = end + 1;
    }
    return lastEnd;
}

// The value as a variable of the IEC type stores it: integers wrap around,
// REAL rounds to 32 bits.
Value stored(core::IecType type, const Value& value)
{
    if (type == core::IecType::Bool)
        return core::cond::isTrue(value);
    if (core::isRealType(type)) {
        const double real = std::holds_alternative<double>(value) ? std::get<double>(value)
            : std::holds_alternative<std::int64_t>(value)        ? static_cast<double>(std::get<std::int64_t>(value))
                                                                 : (std::get<bool>(value) ? 1.0 : 0.0);
        return type == core::IecType::Real ? static_cast<double>(static_cast<float>(real)) : real;
    }
    std::int64_t integer = std::holds_alternative<std::int64_t>(value) ? std::get<std::int64_t>(value)
        : std::holds_alternative<bool>(value)                         ? std::int64_t{std::get<bool>(value)}
                                                                      : static_cast<std::int64_t>(std::get<double>(value));
    const core::cond::IntegerRange range = core::cond::integerRange(type);
    const auto width = static_cast<std::uint64_t>(range.high) - static_cast<std::uint64_t>(range.low) + 1;
    if (width != 0 && (integer < range.low || integer > range.high)) {
        const auto offset = (static_cast<std::uint64_t>(integer) - static_cast<std::uint64_t>(range.low)) % width;
        integer = static_cast<std::int64_t>(static_cast<std::uint64_t>(range.low) + offset);
    }
    return integer;
}

std::optional<Value> initialValue(core::IecType type, const std::string& text)
{
    return core::cond::parseValue(type, text);
}

// "FUNCTION_BLOCK F1_FB" -> "F1_FB" (upper case); empty when there is none.
std::string headerName(const std::string& text, std::string_view keyword)
{
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
            end = text.size();
        std::string line = text.substr(start, end - start);
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first != std::string::npos) {
            line = line.substr(first);
            const std::size_t space = line.find(' ');
            if (upper(line.substr(0, space)) == keyword && space != std::string::npos) {
                std::string name = line.substr(space + 1);
                while (!name.empty() && (name.back() == ' ' || name.back() == '\r'))
                    name.pop_back();
                return upper(name);
            }
        }
        start = end + 1;
    }
    return {};
}

} // namespace

StInterpreter::StInterpreter(std::string_view programText, std::string_view globalsText,
                             const std::vector<std::string>& functionBlockTexts)
{
    // The globals.
    const std::string globals = stripComments(globalsText);
    std::vector<Declaration> globalDeclarations;
    readDeclarations(globals, globalDeclarations, m_error);
    if (!m_error.empty())
        return;
    const auto addGlobal = [&](const Declaration& d) -> bool {
        const std::optional<core::IecType> type = core::parseIecType(d.type);
        if (!type) {
            m_error = "unknown type " + d.type + " of the global " + d.name;
            return false;
        }
        const std::optional<Value> value = initialValue(*type, d.initial);
        if (!value) {
            m_error = "cannot read the initial value of " + d.name;
            return false;
        }
        if (m_globalSlot.count(upper(d.name))) {
            m_error = d.name + " is declared twice";
            return false;
        }
        m_globalSlot[upper(d.name)] = static_cast<int>(m_globals.size());
        m_globals.push_back(*value);
        m_globalTypes.push_back(*type);
        return true;
    };
    for (const Declaration& d : globalDeclarations) {
        if (d.block != "VAR_GLOBAL") {
            m_error = "a " + d.block + " block among the globals";
            return;
        }
        if (!addGlobal(d))
            return;
    }
    const std::map<std::string, int> trueGlobals = m_globalSlot; // what VAR_EXTERNAL may name

    // The function block types.
    for (const std::string& fbText : functionBlockTexts) {
        const std::string text = stripComments(fbText);
        auto pou = std::make_unique<Pou>();
        pou->name = headerName(text, "FUNCTION_BLOCK");
        if (pou->name.empty()) {
            m_error = "no FUNCTION_BLOCK header in a function block text";
            return;
        }
        std::vector<Declaration> declarations;
        const std::size_t bodyStart = readDeclarations(text, declarations, m_error);
        if (!m_error.empty())
            return;
        for (const Declaration& d : declarations) {
            const std::string name = upper(d.name);
            if (pou->slotOf.count(name) || pou->tonOf.count(name) || pou->externals.count(name)) {
                m_error = d.name + " is declared twice in " + pou->name;
                return;
            }
            if (d.block == "VAR_EXTERNAL") {
                const auto global = trueGlobals.find(name);
                if (global == trueGlobals.end()) {
                    m_error = pou->name + " declares VAR_EXTERNAL " + d.name + ", which is no global";
                    return;
                }
                const std::optional<core::IecType> type = core::parseIecType(d.type);
                if (!type || *type != m_globalTypes[static_cast<std::size_t>(global->second)]) {
                    m_error = pou->name + " declares VAR_EXTERNAL " + d.name + " : " + d.type + ", not the global's type";
                    return;
                }
                pou->externals[name] = global->second;
                continue;
            }
            if (d.block != "VAR_INPUT" && d.block != "VAR_OUTPUT" && d.block != "VAR") {
                m_error = "a " + d.block + " block in " + pou->name;
                return;
            }
            if (upper(d.type) == "TON") {
                if (d.block != "VAR" || !d.initial.empty()) {
                    m_error = "the TON " + d.name + " of " + pou->name + " is not a plain local";
                    return;
                }
                pou->tonOf[name] = static_cast<int>(pou->tons.size());
                pou->tons.push_back(d.name);
                continue;
            }
            const std::optional<core::IecType> type = core::parseIecType(d.type);
            if (!type) {
                m_error = "unknown type " + d.type + " of " + d.name + " in " + pou->name;
                return;
            }
            const std::optional<Value> value = initialValue(*type, d.initial);
            if (!value) {
                m_error = "cannot read the initial value of " + d.name + " in " + pou->name;
                return;
            }
            pou->slotOf[name] = static_cast<int>(pou->slots.size());
            pou->slots.push_back({d.name, *type, *value, d.block == "VAR_OUTPUT"});
        }
        const auto inputs = pou->slotOf.find("INITIALIZATION");
        const auto complete = pou->slotOf.find("COMPLETE");
        if (inputs == pou->slotOf.end() || complete == pou->slotOf.end()
            || !pou->slots[static_cast<std::size_t>(complete->second)].output) {
            m_error = pou->name + " lacks the Initialization input or the Complete output";
            return;
        }
        pou->initialization = inputs->second;
        pou->complete = complete->second;
        const std::size_t bodyEnd = text.rfind("END_FUNCTION_BLOCK");
        if (bodyEnd == std::string::npos || bodyEnd < bodyStart) {
            m_error = "no END_FUNCTION_BLOCK after the declarations of " + pou->name;
            return;
        }
        const std::string body = text.substr(bodyStart, bodyEnd - bodyStart);
        Pou* const fb = pou.get();
        Scope scope;
        scope.calleesAreTons = true;
        scope.callee = [fb](const std::string& name) {
            const auto found = fb->tonOf.find(name);
            return found == fb->tonOf.end() ? -1 : found->second;
        };
        scope.resolve = [fb](const std::string& name, std::string& why) -> std::optional<StReference> {
            if (const std::size_t dot = name.find("__"); dot != std::string::npos) {
                const auto ton = fb->tonOf.find(name.substr(0, dot));
                const std::string member = name.substr(dot + 2);
                if (ton != fb->tonOf.end() && (member == "Q" || member == "ET"))
                    return StReference{member == "Q" ? StReference::Kind::TonQ : StReference::Kind::TonEt, ton->second, 0};
                why = "no TON output " + name + " in " + fb->name;
                return std::nullopt;
            }
            if (const auto local = fb->slotOf.find(name); local != fb->slotOf.end())
                return StReference{StReference::Kind::Local, local->second, 0};
            if (const auto external = fb->externals.find(name); external != fb->externals.end())
                return StReference{StReference::Kind::Global, external->second, 0};
            why = name + " is not declared in " + fb->name;
            return std::nullopt;
        };
        fb->body = BodyParser(body, scope, m_error).parse();
        if (!m_error.empty()) {
            m_error = fb->name + ": " + m_error;
            return;
        }
        m_pous.push_back(std::move(pou));
    }
    auto skeleton = std::make_unique<Pou>();
    skeleton->name = "(skeleton)";
    skeleton->skeleton = true;
    skeleton->slots = {{"Initialization", core::IecType::Bool, false, false}, {"Complete", core::IecType::Bool, false, true}};
    skeleton->slotOf = {{"INITIALIZATION", 0}, {"COMPLETE", 1}};
    skeleton->initialization = 0;
    skeleton->complete = 1;
    const Pou* const skeletonPou = skeleton.get();
    m_pous.push_back(std::move(skeleton));
    // IEC 61131-3's R_TRIG (PackML programs): Q := CLK AND NOT M; M := CLK.
    auto risingEdge = std::make_unique<Pou>();
    risingEdge->name = "R_TRIG";
    risingEdge->risingEdge = true;
    risingEdge->slots = {{"CLK", core::IecType::Bool, false, false}, {"Q", core::IecType::Bool, false, true},
                         {"M", core::IecType::Bool, false, false}};
    risingEdge->slotOf = {{"CLK", 0}, {"Q", 1}, {"M", 2}};
    const Pou* const risingEdgePou = risingEdge.get();
    m_pous.push_back(std::move(risingEdge));

    // The program: its own variables live beside the globals.
    const std::string program = stripComments(programText);
    if (headerName(program, "PROGRAM").empty()) {
        m_error = "no PROGRAM header";
        return;
    }
    std::vector<Declaration> declarations;
    const std::size_t bodyStart = readDeclarations(program, declarations, m_error);
    if (!m_error.empty())
        return;
    std::map<std::string, int> visible; // what the program body may name
    for (const Declaration& d : declarations) {
        const std::string name = upper(d.name);
        if (d.block == "VAR_EXTERNAL") {
            const auto global = trueGlobals.find(name);
            if (global == trueGlobals.end()) {
                m_error = "the program declares VAR_EXTERNAL " + d.name + ", which is no global";
                return;
            }
            visible[name] = global->second;
            continue;
        }
        if (d.block != "VAR") {
            m_error = "a " + d.block + " block in the program";
            return;
        }
        if (core::parseIecType(d.type)) {
            if (trueGlobals.count(name)) {
                m_error = "the program variable " + d.name + " hides a global";
                return;
            }
            if (!addGlobal(d))
                return;
            visible[name] = m_globalSlot[name];
            if (upper(d.type) == "BOOL" && name.size() > 4 && name.compare(name.size() - 4, 4, "_MEM") == 0)
                m_tokenNames.push_back(d.name);
            continue;
        }
        const std::string type = upper(d.type);
        const bool isRisingEdge = type == "R_TRIG";
        if (!isRisingEdge && (type.size() <= 3 || type.compare(type.size() - 3, 3, "_FB") != 0)) {
            m_error = "unknown type " + d.type + " of " + d.name;
            return;
        }
        Instance instance;
        instance.name = d.name;
        instance.pou = isRisingEdge ? risingEdgePou : skeletonPou;
        for (const std::unique_ptr<Pou>& pou : m_pous) {
            if (!isRisingEdge && pou->name == type)
                instance.pou = pou.get();
        }
        for (const Pou::Slot& slot : instance.pou->slots)
            instance.values.push_back(slot.initial);
        instance.tons.assign(instance.pou->tons.size(), Ton{});
        m_instances.push_back(std::move(instance));
        m_instanceNames.push_back(d.name);
    }
    const std::size_t bodyEnd = program.rfind("END_PROGRAM");
    if (bodyEnd == std::string::npos || bodyEnd < bodyStart) {
        m_error = "no END_PROGRAM after the declarations";
        return;
    }
    Scope scope;
    scope.callee = [this](const std::string& name) { return instanceIndex(name); };
    scope.resolve = [this, &visible](const std::string& name, std::string& why) -> std::optional<StReference> {
        if (const std::size_t dot = name.find("__"); dot != std::string::npos) {
            const int instance = instanceIndex(name.substr(0, dot));
            if (instance >= 0) {
                const Pou& pou = *m_instances[static_cast<std::size_t>(instance)].pou;
                const auto slot = pou.slotOf.find(name.substr(dot + 2));
                if (slot != pou.slotOf.end() && pou.slots[static_cast<std::size_t>(slot->second)].output)
                    return StReference{StReference::Kind::Member, instance, slot->second};
            }
            why = name + " is no output of an FB instance of the program";
            return std::nullopt;
        }
        if (const auto found = visible.find(name); found != visible.end())
            return StReference{StReference::Kind::Global, found->second, 0};
        why = name + " is not declared in the program (VAR or VAR_EXTERNAL)";
        return std::nullopt;
    };
    const std::string body = program.substr(bodyStart, bodyEnd - bodyStart);
    m_body = BodyParser(body, scope, m_error).parse();
    if (!m_error.empty())
        m_error = "PROGRAM: " + m_error;
}

StInterpreter::~StInterpreter() = default;
StInterpreter::StInterpreter(StInterpreter&&) noexcept = default;
StInterpreter& StInterpreter::operator=(StInterpreter&&) noexcept = default;

int StInterpreter::instanceIndex(std::string_view name) const
{
    for (std::size_t i = 0; i < m_instanceNames.size(); ++i) {
        if (core::equalsIgnoreCase(m_instanceNames[i], name))
            return static_cast<int>(i);
    }
    return -1;
}

void StInterpreter::setInput(std::string_view name, const Value& value)
{
    auto found = m_globalSlot.find(upper(name));
    if (found == m_globalSlot.end()) {
        m_error = "no global named " + std::string(name);
        return;
    }
    const auto slot = static_cast<std::size_t>(found->second);
    m_globals[slot] = stored(m_globalTypes[slot], value);
}

void StInterpreter::setManualComplete(std::string_view instance, std::optional<bool> value)
{
    const int index = instanceIndex(instance);
    if (index < 0 || !m_instances[static_cast<std::size_t>(index)].pou->skeleton) {
        m_error = "no skeleton FB instance named " + std::string(instance);
        return;
    }
    m_instances[static_cast<std::size_t>(index)].manual = value;
}

Value StInterpreter::read(const StReference& reference) const
{
    switch (reference.kind) {
    case StReference::Kind::Global: return m_globals[static_cast<std::size_t>(reference.index)];
    case StReference::Kind::Local: return m_running->values[static_cast<std::size_t>(reference.index)];
    case StReference::Kind::TonQ: return m_running->tons[static_cast<std::size_t>(reference.index)].q;
    case StReference::Kind::TonEt: return m_running->tons[static_cast<std::size_t>(reference.index)].et;
    case StReference::Kind::Member:
        return m_instances[static_cast<std::size_t>(reference.index)].values[static_cast<std::size_t>(reference.member)];
    }
    return false;
}

void StInterpreter::assign(const StReference& reference, const Value& value)
{
    if (reference.kind == StReference::Kind::Global) {
        const auto slot = static_cast<std::size_t>(reference.index);
        m_globals[slot] = stored(m_globalTypes[slot], value);
    } else if (reference.kind == StReference::Kind::Local) {
        const auto slot = static_cast<std::size_t>(reference.index);
        m_running->values[slot] = stored(m_running->pou->slots[slot].type, value);
    } else if (m_runtimeError.empty()) {
        m_runtimeError = "assignment to a name that cannot be written";
    }
}

Value StInterpreter::evaluate(const StExpression& expression)
{
    return core::cond::evaluate(expression.parsed, [&](int node) -> Value {
        return read(expression.references[static_cast<std::size_t>(node)]);
    });
}

bool StInterpreter::truth(const StExpression& expression)
{
    return core::cond::isTrue(evaluate(expression));
}

void StInterpreter::call(const Statement& s)
{
    if (s.calleeIsTon) {
        const StExpression* in = nullptr;
        const StExpression* pt = nullptr;
        for (const auto& [parameter, argument] : s.arguments) {
            if (parameter == "IN" && !in)
                in = &argument;
            else if (parameter == "PT" && !pt && argument.durationMs)
                pt = &argument;
            else if (m_runtimeError.empty())
                m_runtimeError = "a TON call with an argument other than IN and a TIME literal PT";
        }
        if (!in || !pt) {
            if (m_runtimeError.empty())
                m_runtimeError = "a TON call without IN or PT";
            return;
        }
        m_running->tons[static_cast<std::size_t>(s.callee)].call(truth(*in), *pt->durationMs, m_nowMs);
        return;
    }
    Instance& instance = m_instances[static_cast<std::size_t>(s.callee)];
    if (instance.pou->risingEdge) {
        if (s.arguments.size() != 1 || s.arguments[0].first != "CLK" || s.arguments[0].second.durationMs) {
            if (m_runtimeError.empty())
                m_runtimeError = "a call of the R_TRIG " + instance.name + " with other arguments than CLK";
            return;
        }
        const bool clk = truth(s.arguments[0].second);
        instance.values[1] = clk && !core::cond::isTrue(instance.values[2]);
        instance.values[2] = clk;
        return;
    }
    if (s.arguments.size() != 1 || s.arguments[0].first != "INITIALIZATION" || s.arguments[0].second.durationMs) {
        if (m_runtimeError.empty())
            m_runtimeError = "a call of " + instance.name + " with other arguments than Initialization";
        return;
    }
    const Pou& pou = *instance.pou;
    instance.values[static_cast<std::size_t>(pou.initialization)] = truth(s.arguments[0].second);
    if (pou.skeleton) {
        // IF Initialization THEN Complete := FALSE; END_IF; Complete := TRUE (or manual).
        Value& complete = instance.values[static_cast<std::size_t>(pou.complete)];
        if (core::cond::isTrue(instance.values[static_cast<std::size_t>(pou.initialization)]))
            complete = false;
        complete = instance.manual ? *instance.manual : true;
        return;
    }
    Instance* const caller = m_running;
    m_running = &instance;
    execute(pou.body);
    m_running = caller;
}

void StInterpreter::execute(const std::vector<Statement>& statements)
{
    for (const Statement& s : statements) {
        ++m_statementsRun;
        switch (s.kind) {
        case Statement::Kind::Assign: assign(s.target, evaluate(s.value)); break;
        case Statement::Kind::Call: call(s); break;
        case Statement::Kind::If: {
            bool done = false;
            for (const auto& [condition, branch] : s.branches) {
                if (truth(condition)) {
                    execute(branch);
                    done = true;
                    break;
                }
            }
            if (!done)
                execute(s.elseBranch);
            break;
        }
        case Statement::Kind::Case: {
            const Value selector = evaluate(s.value);
            const std::int64_t* number = std::get_if<std::int64_t>(&selector);
            for (const auto& [label, branch] : s.cases) {
                if (number && *number == label) {
                    execute(branch);
                    break;
                }
            }
            break;
        }
        case Statement::Kind::Repeat: {
            int rounds = 0;
            do {
                execute(s.elseBranch);
                if (++rounds > 100000) {
                    if (m_runtimeError.empty())
                        m_runtimeError = "a REPEAT loop that does not end";
                    break;
                }
            } while (!truth(s.value));
            break;
        }
        }
    }
}

void StInterpreter::scan()
{
    m_running = nullptr;
    execute(m_body);
}

Value StInterpreter::value(std::string_view name) const
{
    auto found = m_globalSlot.find(upper(name));
    return found == m_globalSlot.end() ? Value{false} : m_globals[static_cast<std::size_t>(found->second)];
}

int StInterpreter::state() const
{
    const Value v = value("State");
    const std::int64_t* number = std::get_if<std::int64_t>(&v);
    return number ? static_cast<int>(*number) : -1;
}

bool StInterpreter::entry() const
{
    return core::cond::isTrue(value("Entry"));
}

bool StInterpreter::complete(std::string_view instance) const
{
    const std::optional<Value> value = member(instance, "Complete");
    return value && core::cond::isTrue(*value);
}

bool StInterpreter::runsBody(std::string_view instance) const
{
    const int index = instanceIndex(instance);
    return index >= 0 && !m_instances[static_cast<std::size_t>(index)].pou->skeleton;
}

std::optional<Value> StInterpreter::member(std::string_view instance, std::string_view name) const
{
    const int index = instanceIndex(instance);
    if (index < 0)
        return std::nullopt;
    const Instance& i = m_instances[static_cast<std::size_t>(index)];
    const auto slot = i.pou->slotOf.find(upper(name));
    if (slot == i.pou->slotOf.end())
        return std::nullopt;
    return i.values[static_cast<std::size_t>(slot->second)];
}

int StInterpreter::globalIndex(std::string_view name) const
{
    const auto found = m_globalSlot.find(upper(name));
    return found == m_globalSlot.end() ? -1 : found->second;
}

int StInterpreter::memberIndex(int instance, std::string_view name) const
{
    if (instance < 0 || static_cast<std::size_t>(instance) >= m_instances.size())
        return -1;
    const Pou& pou = *m_instances[static_cast<std::size_t>(instance)].pou;
    const auto slot = pou.slotOf.find(upper(name));
    return slot == pou.slotOf.end() ? -1 : slot->second;
}

const Value& StInterpreter::memberAt(int instance, int member) const
{
    return m_instances[static_cast<std::size_t>(instance)].values[static_cast<std::size_t>(member)];
}

std::optional<StInterpreter::TonOutputs> StInterpreter::timer(std::string_view instance, std::string_view name) const
{
    const int index = instanceIndex(instance);
    if (index < 0)
        return std::nullopt;
    const Instance& i = m_instances[static_cast<std::size_t>(index)];
    const auto ton = i.pou->tonOf.find(upper(name));
    if (ton == i.pou->tonOf.end())
        return std::nullopt;
    const Ton& t = i.tons[static_cast<std::size_t>(ton->second)];
    return TonOutputs{t.q, t.et};
}

} // namespace sttest
