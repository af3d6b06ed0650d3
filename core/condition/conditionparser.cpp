#include "core/condition/conditionparser.h"

#include "core/model/iectypes.h"

#include <algorithm>
#include <limits>

namespace core::cond {

namespace {

// Parentheses and unary operators recurse in the parser: bounded so that
// hostile input yields an error instead of a stack overflow. The two are
// counted apart because the printer writes a unary operator under another
// one as NOT (NOT x): whatever parses must still parse once printed.
constexpr int kMaxNesting = 200;
// Every consumer of the tree (printing, evaluation, checks) may recurse on it:
// long operator chains are bounded too.
constexpr int kMaxTreeHeight = 1000;

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isIdentifierStart(char c) { return isLetter(c) || c == '_'; }
bool isIdentifierChar(char c) { return isLetter(c) || isDigit(c) || c == '_'; }
bool isNonAscii(char c) { return static_cast<unsigned char>(c) >= 0x80; }
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// Characters that glue onto a number or word and make it something the
// language does not have (12abc, 1.5.3, 16#FF, T#5s, GVL.Start, Température).
bool isGlueChar(char c) { return isIdentifierChar(c) || c == '.' || c == '#' || isNonAscii(c); }

std::size_t skipGlue(std::string_view text, std::size_t pos)
{
    while (pos < text.size() && isGlueChar(text[pos]))
        ++pos;
    return pos;
}

TokenKind wordKind(std::string_view word)
{
    struct Keyword {
        std::string_view text;
        TokenKind kind;
    };
    static constexpr Keyword kConditionKeywords[] = {
        {"NOT", TokenKind::Not}, {"AND", TokenKind::And}, {"OR", TokenKind::Or},
        {"XOR", TokenKind::Xor}, {"MOD", TokenKind::Mod}, {"TRUE", TokenKind::True},
        {"FALSE", TokenKind::False},
    };
    if (word.size() <= 5) {
        for (const Keyword& keyword : kConditionKeywords) {
            if (equalsIgnoreCase(word, keyword.text))
                return keyword.kind;
        }
    }
    // Other reserved words can never be declared variables: say so precisely.
    return isIecKeyword(word) ? TokenKind::Invalid : TokenKind::Identifier;
}

Token makeToken(TokenKind kind, std::string_view text, std::size_t begin, std::size_t end)
{
    return Token{kind, Span{begin, end}, text.substr(begin, end - begin)};
}

Token scanWord(std::string_view text, std::size_t begin)
{
    std::size_t end = begin;
    while (end < text.size() && isIdentifierChar(text[end]))
        ++end;
    const bool glued = end < text.size()
        && (isNonAscii(text[end]) || text[end] == '#'
            || (text[end] == '.' && end + 1 < text.size() && isIdentifierStart(text[end + 1])));
    if (glued || end == begin)
        return makeToken(TokenKind::Invalid, text, begin, skipGlue(text, end));
    return makeToken(wordKind(text.substr(begin, end - begin)), text, begin, end);
}

Token scanNumber(std::string_view text, std::size_t begin)
{
    TokenKind kind = TokenKind::IntegerLiteral;
    std::size_t pos = scanIecDigits(text, begin);
    if (pos + 1 < text.size() && text[pos] == '.' && isDigit(text[pos + 1])) {
        pos = scanIecDigits(text, pos + 1);
        kind = TokenKind::RealLiteral;
    }
    if (pos < text.size() && (text[pos] == 'e' || text[pos] == 'E')) {
        std::size_t exponent = pos + 1;
        if (exponent < text.size() && (text[exponent] == '+' || text[exponent] == '-'))
            ++exponent;
        if (exponent < text.size() && isDigit(text[exponent])) {
            pos = scanIecDigits(text, exponent);
            kind = TokenKind::RealLiteral;
        }
    }
    if (pos < text.size() && isGlueChar(text[pos]))
        return makeToken(TokenKind::Invalid, text, begin, skipGlue(text, pos));
    return makeToken(kind, text, begin, pos);
}

// A comment is reported as one Invalid token: conditions have none, since
// the generated code is printed from the tree.
std::size_t commentEnd(std::string_view text, std::size_t begin)
{
    if (text[begin] == '/') {
        const std::size_t newline = text.find('\n', begin);
        return newline == std::string_view::npos ? text.size() : newline;
    }
    const std::size_t close = text.find("*)", begin + 2);
    return close == std::string_view::npos ? text.size() : close + 2;
}

Token scanSymbol(std::string_view text, std::size_t begin)
{
    const char c = text[begin];
    const char next = begin + 1 < text.size() ? text[begin + 1] : '\0';
    auto one = [&](TokenKind kind) { return makeToken(kind, text, begin, begin + 1); };
    auto two = [&](TokenKind kind) { return makeToken(kind, text, begin, begin + 2); };
    switch (c) {
    case '(':
        if (next == '*')
            return makeToken(TokenKind::Invalid, text, begin, commentEnd(text, begin));
        return one(TokenKind::LeftParen);
    case ')': return one(TokenKind::RightParen);
    case '+': return one(TokenKind::Plus);
    case '-': return one(TokenKind::Minus);
    case '*': return next == '*' ? two(TokenKind::Invalid) : one(TokenKind::Star);
    case '/':
        if (next == '/')
            return makeToken(TokenKind::Invalid, text, begin, commentEnd(text, begin));
        return one(TokenKind::Slash);
    case '&': return next == '&' ? two(TokenKind::Invalid) : one(TokenKind::And);
    case '=': return next == '=' ? two(TokenKind::Invalid) : one(TokenKind::Equal);
    case '<':
        if (next == '=')
            return two(TokenKind::LessEqual);
        return next == '>' ? two(TokenKind::NotEqual) : one(TokenKind::Less);
    case '>': return next == '=' ? two(TokenKind::GreaterEqual) : one(TokenKind::Greater);
    case ':':
    case '!': return next == '=' ? two(TokenKind::Invalid) : one(TokenKind::Invalid);
    case '|': return next == '|' ? two(TokenKind::Invalid) : one(TokenKind::Invalid);
    default: return one(TokenKind::Invalid);
    }
}

Token scanToken(std::string_view text, std::size_t begin)
{
    const char c = text[begin];
    if (isIdentifierStart(c) || isNonAscii(c))
        return scanWord(text, begin);
    if (isDigit(c))
        return scanNumber(text, begin);
    return scanSymbol(text, begin);
}

constexpr std::string_view kUpArrow = "\xE2\x86\x91";   // ↑
constexpr std::string_view kDownArrow = "\xE2\x86\x93"; // ↓

// What the Nested context adds: edges, durations.
Token scanNestedToken(std::string_view text, std::size_t begin)
{
    const std::string_view rest = text.substr(begin);
    if (rest.starts_with(kUpArrow) || rest.starts_with(kDownArrow))
        return makeToken(rest.starts_with(kUpArrow) ? TokenKind::RisingEdge : TokenKind::FallingEdge, text, begin,
                         begin + kUpArrow.size());
    Token token = scanToken(text, begin);
    if (token.kind == TokenKind::Identifier && (equalsIgnoreCase(token.text, "RE") || equalsIgnoreCase(token.text, "FE")))
        token.kind = equalsIgnoreCase(token.text, "RE") ? TokenKind::RisingEdge : TokenKind::FallingEdge;
    else if (token.kind == TokenKind::Invalid && parseDurationMs(token.text))
        token.kind = TokenKind::Duration;
    return token;
}

// X followed by digits, as stepActivityNumber reads them, X0 included.
bool isStepActivityName(std::string_view name)
{
    return name.size() >= 2 && name.size() <= 10 && (name[0] == 'X' || name[0] == 'x')
        && std::all_of(name.begin() + 1, name.end(), [](char c) { return isDigit(c); });
}

// `/faulted` then the word's end at `at` (spaces allowed around the slash).
bool followedByFaulted(std::string_view text, std::size_t at)
{
    const auto skipSpaces = [&] {
        while (at < text.size() && (text[at] == ' ' || text[at] == '\t'))
            ++at;
    };
    skipSpaces();
    if (at >= text.size() || text[at] != '/')
        return false;
    ++at;
    skipSpaces();
    constexpr std::string_view kWord = "faulted";
    if (!equalsIgnoreCase(text.substr(at, kWord.size()), kWord))
        return false;
    at += kWord.size();
    return at >= text.size() || !(isIdentifierStart(text[at]) || isDigit(text[at]) || isNonAscii(text[at]));
}

// What the Property context adds: `->`, `in`, `S.Xn`, `2s/faulted`.
Token scanPropertyToken(std::string_view text, std::size_t begin)
{
    if (text.substr(begin).starts_with("->"))
        return makeToken(TokenKind::Implies, text, begin, begin + 2);
    Token token = scanToken(text, begin);
    if (token.kind == TokenKind::Identifier && equalsIgnoreCase(token.text, "in"))
        token.kind = TokenKind::In;
    else if (token.kind == TokenKind::Invalid && token.text.find('#') == std::string_view::npos
             && parseDurationMs(token.text) && followedByFaulted(text, begin + token.text.size()))
        token.kind = TokenKind::Duration; // `2s/faulted` (verification with single faults)
    else if (token.kind == TokenKind::Invalid) {
        // S.Xn with any n, 0 included: a GRAFCET without step n is the
        // property checker's to name (GP005), not "a qualified name".
        const std::size_t dot = token.text.find('.');
        if (dot != std::string_view::npos && dot > 0 && isStepActivityName(token.text.substr(dot + 1))
            && token.text.substr(0, dot).find_first_of("#") == std::string_view::npos)
            token.kind = TokenKind::NestedStep;
    }
    return token;
}

bool looksLikeDuration(std::string_view text)
{
    const std::size_t hash = text.find('#');
    if (hash == std::string_view::npos)
        return false;
    const std::string_view prefix = text.substr(0, hash);
    return equalsIgnoreCase(prefix, "T") || equalsIgnoreCase(prefix, "TIME");
}

struct DurationUnit {
    std::string_view name;
    std::int64_t milliseconds;
};

constexpr DurationUnit kDurationUnits[] = {
    {"d", 86'400'000}, {"h", 3'600'000}, {"ms", 1}, {"m", 60'000}, {"s", 1'000},
};

// The rank of a unit from the largest (0) to the smallest (4).
int unitRank(std::string_view name)
{
    static constexpr std::string_view kOrder[] = {"d", "h", "m", "s", "ms"};
    for (int i = 0; i < 5; ++i) {
        if (kOrder[i] == name)
            return i;
    }
    return -1;
}

std::optional<DurationUnit> scanUnit(std::string_view text, std::size_t& pos)
{
    for (const DurationUnit& unit : kDurationUnits) {
        if (pos + unit.name.size() <= text.size() && equalsIgnoreCase(text.substr(pos, unit.name.size()), unit.name)) {
            pos += unit.name.size();
            return unit;
        }
    }
    return std::nullopt;
}

// --- errors -------------------------------------------------------------------

using ErrorKind = ParseError::Kind;

bool isValidUtf8(std::string_view text)
{
    std::size_t i = 0;
    while (i < text.size()) {
        const auto lead = static_cast<unsigned char>(text[i]);
        std::size_t length = 1;
        if (lead >= 0xF0 && lead <= 0xF4)
            length = 4;
        else if (lead >= 0xE0)
            length = lead <= 0xEF ? 3 : 0;
        else if (lead >= 0xC2)
            length = 2;
        else if (lead >= 0x80)
            length = 0;
        if (length == 0 || i + length > text.size())
            return false;
        for (std::size_t k = 1; k < length; ++k) {
            if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80)
                return false;
        }
        i += length;
    }
    return true;
}

bool isTypeName(std::string_view upper)
{
    static constexpr std::string_view kOtherTypes[] = {
        "TIME", "LTIME", "DATE", "LDATE", "TIME_OF_DAY", "LTIME_OF_DAY", "TOD", "LTOD",
        "DATE_AND_TIME", "LDATE_AND_TIME", "DT", "LDT", "STRING", "WSTRING", "CHAR", "WCHAR",
        "BYTE", "WORD", "DWORD", "LWORD",
    };
    if (parseIecType(upper) || upper.starts_with("ANY"))
        return true;
    for (std::string_view type : kOtherTypes) {
        if (upper == type)
            return true;
    }
    return false;
}

ErrorKind keywordKind(std::string_view word)
{
    const std::string upper = toUpperAscii(word);
    if (upper == "IF" || upper == "THEN" || upper == "ELSIF" || upper == "ELSE" || upper == "END_IF")
        return ErrorKind::IfThen;
    return isTypeName(upper) ? ErrorKind::TypeName : ErrorKind::Keyword;
}

ErrorKind invalidWordKind(std::string_view text)
{
    bool nonAscii = false;
    for (char c : text)
        nonAscii = nonAscii || isNonAscii(c);
    if (nonAscii)
        return isValidUtf8(text) ? ErrorKind::NonAscii : ErrorKind::InvalidUtf8;
    if (text.find('#') != std::string_view::npos)
        return ErrorKind::TypedLiteral;
    if (text.find('.') != std::string_view::npos && !isDigit(text[0]))
        return ErrorKind::QualifiedName;
    if (isDigit(text[0]))
        return ErrorKind::InvalidNumber;
    return keywordKind(text);
}

ErrorKind invalidTokenKind(std::string_view text)
{
    struct Symbol {
        std::string_view text;
        ErrorKind kind;
    };
    static constexpr Symbol kSymbols[] = {
        {":=", ErrorKind::ColonEquals}, {"==", ErrorKind::DoubleEquals}, {"!=", ErrorKind::BangEquals},
        {"!", ErrorKind::Bang},         {"&&", ErrorKind::DoubleAmpersand}, {"||", ErrorKind::Pipe},
        {"|", ErrorKind::Pipe},         {"**", ErrorKind::Power},      {";", ErrorKind::Semicolon},
    };
    if (text.starts_with("(*") || text.starts_with("//"))
        return ErrorKind::Comment;
    for (const Symbol& symbol : kSymbols) {
        if (text == symbol.text)
            return symbol.kind;
    }
    const char c = text[0];
    if (isIdentifierStart(c) || isDigit(c) || isNonAscii(c))
        return invalidWordKind(text);
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
        return ErrorKind::ControlCharacter;
    return ErrorKind::UnexpectedCharacter;
}

std::optional<BinaryOp> binaryOperator(TokenKind kind)
{
    switch (kind) {
    case TokenKind::Or: return BinaryOp::Or;
    case TokenKind::Xor: return BinaryOp::Xor;
    case TokenKind::And: return BinaryOp::And;
    case TokenKind::Equal: return BinaryOp::Equal;
    case TokenKind::NotEqual: return BinaryOp::NotEqual;
    case TokenKind::Less: return BinaryOp::Less;
    case TokenKind::Greater: return BinaryOp::Greater;
    case TokenKind::LessEqual: return BinaryOp::LessEqual;
    case TokenKind::GreaterEqual: return BinaryOp::GreaterEqual;
    case TokenKind::Plus: return BinaryOp::Add;
    case TokenKind::Minus: return BinaryOp::Subtract;
    case TokenKind::Star: return BinaryOp::Multiply;
    case TokenKind::Slash: return BinaryOp::Divide;
    case TokenKind::Mod: return BinaryOp::Modulo;
    case TokenKind::Implies: return BinaryOp::Implies;
    default: return std::nullopt;
    }
}

bool startsOperand(TokenKind kind)
{
    switch (kind) {
    case TokenKind::Identifier:
    case TokenKind::IntegerLiteral:
    case TokenKind::RealLiteral:
    case TokenKind::True:
    case TokenKind::False:
    case TokenKind::Not:
    case TokenKind::Minus:
    case TokenKind::RisingEdge:
    case TokenKind::FallingEdge:
    case TokenKind::Duration:
    case TokenKind::In:
    case TokenKind::NestedStep:
    case TokenKind::LeftParen: return true;
    default: return false;
    }
}

// Recursive descent with precedence climbing over the token list.
class Parser {
public:
    Parser(std::string_view text, std::vector<Token> tokens, Context context)
        : m_text(text)
        , m_tokens(std::move(tokens))
        , m_nested(context == Context::Nested)
        , m_property(context == Context::Property)
        , m_lowestPrecedence(context == Context::Property ? precedence(BinaryOp::Implies) : 1)
    {
    }

    ParseResult run()
    {
        ParseResult result;
        if (m_tokens.front().kind == TokenKind::End) {
            result.error = makeParseError(ErrorKind::Empty, Span{0, m_text.size()});
            return result;
        }
        m_expression.nodes.reserve(m_tokens.size());
        const Parsed root = parseExpression(m_lowestPrecedence);
        if (root.node >= 0 && peek().kind != TokenKind::End)
            failAfterCondition();
        if (m_error) {
            result.error = std::move(m_error);
            return result;
        }
        m_expression.root = root.node;
        result.expression = std::move(m_expression);
        return result;
    }

private:
    // A parsed subexpression; `extent` also covers its own parentheses.
    struct Parsed {
        int node = -1;
        Span extent;
        int height = 0; // of the subtree, to bound it
    };

    const Token& peek() const { return m_tokens[m_position]; }
    const Token& advance() { return m_tokens[m_position++]; }

    Parsed fail(ErrorKind kind, const Token& found, std::size_t number = 0)
    {
        return fail(kind, found.span, found.kind == TokenKind::End ? std::string_view() : found.text, {}, number);
    }

    Parsed fail(ErrorKind kind, Span span, std::string_view found = {}, std::string_view previous = {},
                std::size_t number = 0)
    {
        if (!m_error)
            m_error = makeParseError(kind, span, found, previous, number);
        return {};
    }

    Parsed failInvalid(const Token& token)
    {
        if (m_nested && looksLikeDuration(token.text))
            return fail(ErrorKind::InvalidDuration, token);
        const ErrorKind kind = invalidTokenKind(token.text);
        const std::size_t byte = static_cast<unsigned char>(token.text[0]);
        return fail(kind, token, kind == ErrorKind::ControlCharacter ? byte : 0);
    }

    // Appends a node built in place (no copy of its text) and bounds the tree height.
    Node* newNode(NodeKind kind, Span span, int height, std::size_t tokenForError)
    {
        if (height > kMaxTreeHeight) {
            fail(ErrorKind::TooComplex, m_tokens[tokenForError], kMaxTreeHeight);
            return nullptr;
        }
        Node& node = m_expression.nodes.emplace_back();
        node.kind = kind;
        node.span = span;
        return &node;
    }

    Parsed lastNode(int height) const
    {
        const int index = static_cast<int>(m_expression.nodes.size()) - 1;
        return {index, m_expression.nodes.back().span, height};
    }

    Parsed parseExpression(int minimumPrecedence)
    {
        Parsed left = parseUnary();
        while (left.node >= 0) {
            const auto op = binaryOperator(peek().kind);
            if (!op || precedence(*op) < minimumPrecedence)
                break;
            const std::size_t operatorToken = m_position;
            advance();
            // `->` groups to the right: a -> b -> c is a -> (b -> c).
            const Parsed right = parseExpression(precedence(*op) + (*op == BinaryOp::Implies ? 0 : 1));
            if (right.node < 0)
                return {};
            const int height = 1 + std::max(left.height, right.height);
            Node* node = newNode(NodeKind::Binary, Span{left.extent.begin, right.extent.end}, height, operatorToken);
            if (!node)
                return {};
            node->binaryOp = *op;
            node->left = left.node;
            node->right = right.node;
            left = lastNode(height);
        }
        return left;
    }

    Parsed parseUnary()
    {
        const TokenKind kind = peek().kind;
        if (kind == TokenKind::RisingEdge || kind == TokenKind::FallingEdge)
            return parseEdge();
        if (kind != TokenKind::Not && kind != TokenKind::Minus)
            return parsePrimary();
        const std::size_t operatorToken = m_position;
        if (!enter(m_unaryNesting, ErrorKind::TooDeepUnary))
            return {};
        advance();
        const Parsed operand = parseUnary();
        --m_unaryNesting;
        if (operand.node < 0)
            return {};
        const int height = 1 + operand.height;
        Node* node = newNode(NodeKind::Unary, Span{m_tokens[operatorToken].span.begin, operand.extent.end}, height,
                             operatorToken);
        if (!node)
            return {};
        node->unaryOp = kind == TokenKind::Not ? UnaryOp::Not : UnaryOp::Negate;
        node->operand = operand.node;
        return lastNode(height);
    }

    // RE a, ↑a: the operand is a variable name, nothing else.
    Parsed parseEdge()
    {
        const std::size_t operatorToken = m_position;
        const Token& edge = advance();
        const Token& operand = peek();
        if (operand.kind == TokenKind::Invalid)
            return failInvalid(operand);
        if (operand.kind != TokenKind::Identifier || stepActivityNumber(operand.text) > 0
            || equalsIgnoreCase(operand.text, "Complete"))
            return operand.kind == TokenKind::End ? fail(ErrorKind::EdgeOperand, edge.span)
                                                  : fail(ErrorKind::EdgeOperand, operand);
        const Parsed variable = leaf(NodeKind::Variable);
        Node* node = newNode(NodeKind::Unary, Span{edge.span.begin, variable.extent.end}, 2, operatorToken);
        if (!node)
            return {};
        node->unaryOp = edge.kind == TokenKind::RisingEdge ? UnaryOp::RisingEdge : UnaryOp::FallingEdge;
        node->operand = variable.node;
        return lastNode(2);
    }

    Parsed identifier()
    {
        if (!m_nested)
            return leaf(NodeKind::Variable);
        const Token& token = peek();
        if (const int number = stepActivityNumber(token.text); number > 0) {
            const Parsed parsed = leaf(NodeKind::StepActivity);
            m_expression.nodes.back().number = number;
            return parsed;
        }
        return leaf(equalsIgnoreCase(token.text, "Complete") ? NodeKind::Complete : NodeKind::Variable);
    }

    // 5s/X3: the time step 3 has been active.
    Parsed parseStepDuration()
    {
        const std::size_t durationToken = m_position;
        const Token& duration = advance();
        if (peek().kind != TokenKind::Slash)
            return fail(ErrorKind::DurationWithoutStep, duration);
        advance();
        const Token& step = peek();
        // In a property, `2s/faulted`: a fault has been in effect that long (number 0).
        const bool faulted = m_property && step.kind == TokenKind::Identifier
            && equalsIgnoreCase(step.text, "faulted");
        const int number = step.kind == TokenKind::Identifier ? stepActivityNumber(step.text) : 0;
        if (number <= 0 && !faulted)
            return fail(ErrorKind::DurationStepExpected, step);
        const std::int64_t milliseconds = *parseDurationMs(duration.text);
        if (milliseconds <= 0)
            return fail(ErrorKind::ZeroDuration, duration);
        advance();
        const Span span{duration.span.begin, step.span.end};
        Node* node = newNode(NodeKind::StepDuration, span, 1, durationToken);
        node->text.assign(m_text.substr(span.begin, span.end - span.begin));
        node->number = number;
        node->durationMs = milliseconds;
        return lastNode(1);
    }

    Parsed parsePrimary()
    {
        const Token& token = peek();
        switch (token.kind) {
        case TokenKind::Identifier: return identifier();
        case TokenKind::Duration: return parseStepDuration();
        case TokenKind::IntegerLiteral: return leaf(NodeKind::IntegerLiteral);
        case TokenKind::RealLiteral: return leaf(NodeKind::RealLiteral);
        case TokenKind::True:
        case TokenKind::False: return leaf(NodeKind::BoolLiteral);
        case TokenKind::LeftParen: return parseParenthesised();
        case TokenKind::In: return parseInStep();
        case TokenKind::NestedStep: return parseNestedStep();
        default: return failMissingOperand();
        }
    }

    // in F1: the GEMMA step F1 is the active one.
    Parsed parseInStep()
    {
        const std::size_t inToken = m_position;
        const Token& in = advance();
        const Token& step = peek();
        if (step.kind == TokenKind::Invalid)
            return failInvalid(step);
        if (step.kind != TokenKind::Identifier)
            return fail(ErrorKind::StepAfterIn, step.span, step.kind == TokenKind::End ? std::string_view() : step.text);
        advance();
        Node* node = newNode(NodeKind::InStep, Span{in.span.begin, step.span.end}, 1, inToken);
        if (!node)
            return {};
        node->text.assign(step.text);
        return lastNode(1);
    }

    // F1.X6: step 6 of F1's nested GRAFCET is active.
    Parsed parseNestedStep()
    {
        const Token& token = advance();
        Node* node = newNode(NodeKind::NestedStepActivity, token.span, 1, m_position - 1);
        if (!node)
            return {};
        const std::size_t dot = token.text.find('.');
        node->text.assign(token.text.substr(0, dot));
        node->number = stepActivityNumber(token.text.substr(dot + 1));
        return lastNode(1);
    }

    Parsed leaf(NodeKind kind)
    {
        const Token& token = advance();
        Node* node = newNode(kind, token.span, 1, m_position - 1);
        node->text.assign(token.text);
        return lastNode(1);
    }

    Parsed parseParenthesised()
    {
        const Token& open = peek();
        if (!enter(m_parenNesting, ErrorKind::TooDeepParentheses))
            return {};
        advance();
        Parsed inner = parseExpression(m_lowestPrecedence);
        --m_parenNesting;
        if (inner.node < 0)
            return {};
        const Token& close = peek();
        if (close.kind != TokenKind::RightParen)
            return failUnclosed(open, close);
        advance();
        inner.extent = Span{open.span.begin, close.span.end};
        return inner;
    }

    bool enter(int& nesting, ErrorKind tooDeep)
    {
        if (++nesting <= kMaxNesting)
            return true;
        fail(tooDeep, peek(), kMaxNesting);
        return false;
    }

    Parsed failMissingOperand()
    {
        const Token& found = peek();
        if (found.kind == TokenKind::Invalid)
            return failInvalid(found);
        if (m_position == 0)
            return fail(found.kind == TokenKind::RightParen ? ErrorKind::UnmatchedClose : ErrorKind::OperandBefore,
                        found);
        const Token& previous = m_tokens[m_position - 1];
        if (previous.kind == TokenKind::LeftParen && found.kind == TokenKind::RightParen)
            return fail(ErrorKind::EmptyParentheses, Span{previous.span.begin, found.span.end});
        const std::string_view text = found.kind == TokenKind::End ? std::string_view() : found.text;
        return fail(ErrorKind::OperandAfter, found.span, text, previous.text);
    }

    Parsed failUnclosed(const Token& open, const Token& found)
    {
        if (found.kind == TokenKind::Invalid)
            return failInvalid(found);
        const std::size_t column = open.span.begin + 1;
        if (found.kind == TokenKind::End)
            return fail(ErrorKind::UnclosedAtEnd, open.span, {}, {}, column);
        return fail(ErrorKind::Unclosed, found, column);
    }

    void failAfterCondition()
    {
        const Token& found = peek();
        if (found.kind == TokenKind::Invalid) {
            failInvalid(found);
        } else if (found.kind == TokenKind::RightParen) {
            fail(ErrorKind::UnmatchedClose, found);
        } else {
            fail(startsOperand(found.kind) ? ErrorKind::MissingOperator : ErrorKind::AfterCondition, found);
        }
    }

    std::string_view m_text;
    std::vector<Token> m_tokens;
    bool m_nested = false;
    bool m_property = false;
    int m_lowestPrecedence = 1;
    std::size_t m_position = 0;
    int m_parenNesting = 0;
    int m_unaryNesting = 0;
    Expression m_expression;
    std::optional<ParseError> m_error;
};

bool isRenamable(const Token& token)
{
    if (token.kind == TokenKind::Identifier)
        return true;
    // A reserved word used as a (badly named) variable still follows a rename.
    if (token.kind != TokenKind::Invalid || token.text.empty() || !isIdentifierStart(token.text[0]))
        return false;
    for (char c : token.text) {
        if (!isIdentifierChar(c))
            return false;
    }
    return true;
}

} // namespace

std::vector<Token> tokenize(std::string_view text, const ParseOptions& options)
{
    std::vector<Token> tokens;
    tokens.reserve(text.size() / 4 + 2);
    std::size_t position = 0;
    while (true) {
        while (position < text.size() && isSpace(text[position]))
            ++position;
        if (position >= text.size())
            break;
        switch (options.context) {
        case Context::Gemma: tokens.push_back(scanToken(text, position)); break;
        case Context::Nested: tokens.push_back(scanNestedToken(text, position)); break;
        case Context::Property: tokens.push_back(scanPropertyToken(text, position)); break;
        }
        position = tokens.back().span.end;
    }
    tokens.push_back(Token{TokenKind::End, Span{text.size(), text.size()}, text.substr(text.size())});
    return tokens;
}

ParseResult parse(std::string_view text, const ParseOptions& options)
{
    return Parser(text, tokenize(text, options), options.context).run();
}

ParseResult parseTokens(std::string_view text, const std::vector<Token>& tokens, std::size_t first,
                        std::size_t last, const ParseOptions& options)
{
    std::vector<Token> range(tokens.begin() + static_cast<std::ptrdiff_t>(first),
                             tokens.begin() + static_cast<std::ptrdiff_t>(last));
    range.push_back(Token{TokenKind::End, Span{text.size(), text.size()}, text.substr(text.size())});
    return Parser(text, std::move(range), options.context).run();
}

std::optional<std::int64_t> parseDurationMs(std::string_view text)
{
    if (const std::size_t hash = text.find('#'); hash != std::string_view::npos) {
        if (!looksLikeDuration(text))
            return std::nullopt;
        text.remove_prefix(hash + 1);
    }
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    std::int64_t total = 0;
    int previousRank = -1;
    bool fractionSeen = false;
    bool saturated = false; // well-formed so far, but beyond 64 bits
    std::size_t pos = 0;
    if (text.empty())
        return std::nullopt;
    while (pos < text.size()) {
        if (fractionSeen || !isDigit(text[pos]))
            return std::nullopt; // only the last part may have a fraction
        std::int64_t whole = 0;
        for (; pos < text.size() && isDigit(text[pos]); ++pos) {
            if (whole > (kMax - 9) / 10)
                saturated = true;
            else
                whole = whole * 10 + (text[pos] - '0');
        }
        double fraction = 0;
        if (pos < text.size() && text[pos] == '.') {
            const std::size_t start = ++pos;
            double scale = 0.1;
            for (; pos < text.size() && isDigit(text[pos]); ++pos, scale /= 10)
                fraction += (text[pos] - '0') * scale;
            if (pos == start)
                return std::nullopt;
            fractionSeen = true;
        }
        const std::optional<DurationUnit> unit = scanUnit(text, pos);
        if (!unit || unitRank(unit->name) <= previousRank)
            return std::nullopt;
        previousRank = unitRank(unit->name);
        if (saturated || whole > (kMax - total) / unit->milliseconds - 1)
            saturated = true;
        else
            total += whole * unit->milliseconds
                + static_cast<std::int64_t>(fraction * static_cast<double>(unit->milliseconds) + 0.5);
    }
    return saturated ? kMax : total;
}

int stepActivityNumber(std::string_view name)
{
    if (name.size() < 2 || name.size() > 10 || (name[0] != 'X' && name[0] != 'x'))
        return 0;
    int number = 0;
    for (char c : name.substr(1)) {
        if (!isDigit(c))
            return 0;
        number = number * 10 + (c - '0');
    }
    return number;
}

std::string renameIdentifier(std::string_view text, std::string_view oldName, std::string_view newName,
                             const ParseOptions& options)
{
    std::string result;
    result.reserve(text.size() + newName.size());
    std::size_t copied = 0;
    for (const Token& token : tokenize(text, options)) {
        if (!isRenamable(token) || !equalsIgnoreCase(token.text, oldName))
            continue;
        result.append(text.substr(copied, token.span.begin - copied));
        result.append(newName);
        copied = token.span.end;
    }
    result.append(text.substr(copied));
    return result;
}

} // namespace core::cond
