#include "core/condition/actionparser.h"

#include "core/condition/conditionparser.h"
#include "core/model/iectypes.h"

#include <vector>

namespace core::cond {

namespace {

using ErrorKind = ParseError::Kind;


// The IEC 60848 / 61131-3 qualifiers GG Studio does not implement: named as
// such rather than taken for a variable followed by junk.
bool isUnsupportedQualifier(std::string_view word)
{
    static constexpr std::string_view kQualifiers[] = {"P", "P0", "P1", "L", "D", "SD", "DS", "SL"};
    for (std::string_view qualifier : kQualifiers) {
        if (equalsIgnoreCase(word, qualifier))
            return true;
    }
    return false;
}

bool isWord(const Token& token, std::string_view word)
{
    return token.kind == TokenKind::Invalid && equalsIgnoreCase(token.text, word);
}

bool isAssignment(const Token& token)
{
    return token.kind == TokenKind::Invalid && token.text == ":=";
}

class ActionParser {
public:
    explicit ActionParser(std::string_view text)
        : m_text(text)
        , m_tokens(tokenize(text, kNestedOptions))
    {
    }

    ActionParseResult run()
    {
        if (peek().kind == TokenKind::End)
            fail(ErrorKind::EmptyAction, Span{0, m_text.size()});
        else if (readQualifier() && readTarget())
            readRest();
        if (m_result.error)
            m_result.action = ActionSyntax{}; // a failed parse holds no half action
        return std::move(m_result);
    }

private:
    const Token& peek(std::size_t ahead = 0) const
    {
        return m_tokens[std::min(m_position + ahead, m_tokens.size() - 1)];
    }

    void fail(ErrorKind kind, Span span, std::string_view found = {})
    {
        if (!m_result.error)
            m_result.error = makeParseError(kind, span, found);
    }

    void fail(ErrorKind kind, const Token& token)
    {
        fail(kind, token.span, token.kind == TokenKind::End ? std::string_view() : token.text);
    }

    // N, S, R followed by a name; anything else is the target itself (so
    // `S := 1` assigns a variable S and a lone `S` drives it).
    bool readQualifier()
    {
        const Token& first = peek();
        const Token& next = peek(1);
        if (first.kind != TokenKind::Identifier)
            return true;
        const bool set = equalsIgnoreCase(first.text, "S");
        const bool reset = equalsIgnoreCase(first.text, "R");
        const bool qualifier = set || reset || equalsIgnoreCase(first.text, "N");
        if (qualifier && isLiteral(next.kind)) {
            fail(ErrorKind::ActionTargetNotVariable, next);
            return false;
        }
        if (next.kind != TokenKind::Identifier)
            return true;
        if (isUnsupportedQualifier(first.text)) {
            fail(ErrorKind::UnsupportedQualifier, first);
            return false;
        }
        if (!qualifier)
            return true;
        m_qualifier = first;
        m_result.action.qualifierWritten = true;
        m_result.action.form = set ? ActionForm::Set : reset ? ActionForm::Reset : ActionForm::Continuous;
        ++m_position;
        return true;
    }

    static bool isLiteral(TokenKind kind)
    {
        return kind == TokenKind::True || kind == TokenKind::False || kind == TokenKind::IntegerLiteral
            || kind == TokenKind::RealLiteral;
    }

    bool readTarget()
    {
        const Token& target = peek();
        if (target.kind != TokenKind::Identifier || stepActivityNumber(target.text) > 0) {
            fail(ErrorKind::ActionTargetNotVariable, target);
            return false;
        }
        m_result.action.target.assign(target.text);
        m_result.action.targetSpan = target.span;
        m_result.action.targetIsComplete = equalsIgnoreCase(target.text, "Complete");
        ++m_position;
        return true;
    }

    void readRest()
    {
        const Token& next = peek();
        if (next.kind == TokenKind::End)
            return;
        if (isAssignment(next)) {
            readAssignment();
            return;
        }
        if (isWord(next, "IF")) {
            readCondition();
            return;
        }
        if (next.kind == TokenKind::Equal) {
            fail(ErrorKind::EqualsForAssignment, next);
            return;
        }
        fail(ErrorKind::AfterAction, next);
    }

    // `S V := <expr>` is the case study's spelling of a stored assignment:
    // S says "stored", which every assignment is. N and R contradict it.
    void readAssignment()
    {
        if (m_result.action.qualifierWritten && m_result.action.form != ActionForm::Set) {
            fail(ErrorKind::QualifierWithAssignment, m_qualifier);
            return;
        }
        const Token& assign = peek();
        ++m_position;
        if (peek().kind == TokenKind::End) {
            fail(ErrorKind::AssignmentWithoutValue, assign.span, assign.text);
            return;
        }
        m_result.action.form = ActionForm::Assign;
        readExpression(m_result.action.value);
    }

    void readCondition()
    {
        const ActionForm form = m_result.action.form;
        if (form == ActionForm::Set || form == ActionForm::Reset) {
            fail(ErrorKind::StoredWithCondition, m_qualifier);
            return;
        }
        const Token& keyword = peek();
        ++m_position;
        if (peek().kind == TokenKind::End) {
            fail(ErrorKind::ConditionMissing, keyword.span, keyword.text);
            return;
        }
        readExpression(m_result.action.condition);
    }

    void readExpression(Expression& into)
    {
        ParseResult parsed = parseTokens(m_text, m_tokens, m_position, m_tokens.size() - 1, kNestedOptions);
        if (!parsed.ok()) {
            m_result.error = std::move(parsed.error);
            return;
        }
        into = std::move(parsed.expression);
    }

    std::string_view m_text;
    std::vector<Token> m_tokens;
    std::size_t m_position = 0;
    Token m_qualifier;
    ActionParseResult m_result;
};

} // namespace

ActionParseResult parseAction(std::string_view text)
{
    return ActionParser(text).run();
}

} // namespace core::cond
