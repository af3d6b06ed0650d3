#include "stinterpreter.h"

#include "core/condition/conditionparser.h"
#include "core/model/iectypes.h"

#include <cctype>

namespace sttest {

using core::cond::Value;

struct StInterpreter::Statement {
    enum class Kind { Assign, Call, If, Case };
    Kind kind = Kind::Assign;
    std::string target;     // Assign: variable; Call: instance (upper case)
    StExpression value;     // Assign: right side; Call: the Initialization argument; Case: selector
    std::vector<std::pair<StExpression, std::vector<Statement>>> branches; // If: IF/ELSIF branches
    std::vector<Statement> elseBranch;
    std::vector<std::pair<std::int64_t, std::vector<Statement>>> cases;   // Case: label -> statements
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

class BodyParser {
public:
    BodyParser(const std::string& text, std::string& error)
        : m_text(text), m_lexemes(lex(text)), m_error(error)
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
        if (m_error.empty())
            m_error = "at offset " + std::to_string(peek().begin) + ": " + message;
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
        for (const char* stop : {"ELSIF", "ELSE", "END_IF", "END_CASE"}) {
            if (isWord(l, stop))
                return true;
        }
        // A CASE label: an integer followed by ':'.
        return l.kind == Lexeme::Kind::Number && peek(1).text == ":";
    }

    // The text up to (not including) the word or symbol `until`.
    StExpression expressionUntil(std::string_view until)
    {
        const std::size_t first = m_next;
        while (peek().kind != Lexeme::Kind::End && !core::equalsIgnoreCase(peek().text, until))
            ++m_next;
        if (m_next == first) {
            fail("expected an expression before '" + std::string(until) + "'");
            return {};
        }
        StExpression expression;
        expression.text = rewriteMembers(m_text.substr(m_lexemes[first].begin, m_lexemes[m_next - 1].end - m_lexemes[first].begin));
        core::cond::ParseResult parsed = core::cond::parse(expression.text);
        if (!parsed.ok())
            fail("cannot parse '" + expression.text + "': " + parsed.error->message);
        expression.parsed = std::move(parsed.expression);
        take(until);
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
            StExpression condition = expressionUntil("THEN");
            s.branches.emplace_back(std::move(condition), statements());
            while (m_error.empty() && isWord(peek(), "ELSIF")) {
                ++m_next;
                StExpression next = expressionUntil("THEN");
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
            s.value = expressionUntil("OF");
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
        if (peek().kind != Lexeme::Kind::Word) {
            fail("expected a statement, found '" + peek().text + "'");
            return s;
        }
        s.target = upper(peek().text);
        ++m_next;
        if (peek().text == "(") {
            ++m_next;
            s.kind = Statement::Kind::Call;
            if (!isWord(peek(), "Initialization")) {
                fail("expected Initialization := in the call of " + s.target);
                return s;
            }
            ++m_next;
            take(":=");
            s.value = expressionUntil(")");
            take(";");
            return s;
        }
        s.kind = Statement::Kind::Assign;
        take(":=");
        s.value = expressionUntil(";");
        return s;
    }

    const std::string& m_text;
    std::vector<Lexeme> m_lexemes;
    std::size_t m_next = 0;
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

} // namespace

StInterpreter::StInterpreter(std::string_view programText, std::string_view globalsText)
{
    const std::string globals = stripComments(globalsText);
    const std::string program = stripComments(programText);
    std::vector<Declaration> declarations;
    readDeclarations(globals, declarations, m_error);
    const std::size_t bodyStart = readDeclarations(program, declarations, m_error);
    if (!m_error.empty())
        return;
    for (const Declaration& d : declarations) {
        if (d.block == "VAR_EXTERNAL")
            continue;
        const std::string name = upper(d.name);
        if (const auto type = core::parseIecType(d.type)) {
            const auto value = core::cond::parseValue(*type, d.initial);
            if (!value) {
                m_error = "cannot read the initial value of " + d.name;
                return;
            }
            m_values[name] = *value;
            if (*type == core::IecType::Bool && d.block == "VAR" && name.size() > 4
                && name.compare(name.size() - 4, 4, "_MEM") == 0)
                m_tokenNames.push_back(d.name);
        } else if (d.type == d.name + "_FB") {
            m_instances.push_back(d.name);
            m_values[name + "__COMPLETE"] = false;
        } else {
            m_error = "unknown type " + d.type + " of " + d.name;
            return;
        }
    }
    const std::size_t bodyEnd = program.rfind("END_PROGRAM");
    if (bodyEnd == std::string::npos || bodyEnd < bodyStart) {
        m_error = "no END_PROGRAM after the declarations";
        return;
    }
    const std::string body = program.substr(bodyStart, bodyEnd - bodyStart);
    m_body = BodyParser(body, m_error).parse();
}

StInterpreter::~StInterpreter() = default;

void StInterpreter::setInput(std::string_view name, const Value& value)
{
    auto found = m_values.find(upper(name));
    if (found == m_values.end()) {
        m_error = "no global named " + std::string(name);
        return;
    }
    found->second = value;
}

void StInterpreter::setManualComplete(std::string_view instance, std::optional<bool> value)
{
    m_manual[upper(instance)] = value;
}

Value StInterpreter::evaluate(const StExpression& expression) const
{
    return core::cond::evaluate(expression.parsed, [&](int node) -> Value {
        const std::string name = upper(expression.parsed.at(node).text);
        auto found = m_values.find(name);
        if (found == m_values.end()) {
            m_runtimeError = "unknown name " + name + " in '" + expression.text + "'";
            return false;
        }
        return found->second;
    });
}

bool StInterpreter::truth(const StExpression& expression) const
{
    return core::cond::isTrue(evaluate(expression));
}

void StInterpreter::execute(const std::vector<Statement>& statements)
{
    for (const Statement& s : statements) {
        switch (s.kind) {
        case Statement::Kind::Assign: {
            auto found = m_values.find(s.target);
            if (found == m_values.end())
                m_runtimeError = "assignment to undeclared " + s.target;
            else
                found->second = evaluate(s.value);
            break;
        }
        case Statement::Kind::Call: {
            // The skeleton FB: IF Initialization THEN Complete := FALSE; END_IF; Complete := TRUE (or manual).
            Value& complete = m_values[s.target + "__COMPLETE"];
            if (truth(s.value))
                complete = false;
            auto manual = m_manual.find(s.target);
            const bool body = manual == m_manual.end() || !manual->second ? true : *manual->second;
            complete = body;
            break;
        }
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
        }
    }
}

void StInterpreter::scan()
{
    execute(m_body);
}

Value StInterpreter::value(std::string_view name) const
{
    auto found = m_values.find(upper(name));
    return found == m_values.end() ? Value{false} : found->second;
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
    return core::cond::isTrue(value(std::string(instance) + "__COMPLETE"));
}

} // namespace sttest
