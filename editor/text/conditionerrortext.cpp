#include "editor/text/conditionerrortext.h"

#include "editor/text/displaytext.h"

#include <QCoreApplication>

namespace editor {

namespace {

// The translation context of the texts.
class ConditionErrorText {
    Q_DECLARE_TR_FUNCTIONS(ConditionErrorText)
};

using ParseErrorKind = core::cond::ParseError::Kind;

// A token or character the language does not have.
QString invalidTokenText(const core::cond::ParseError& error, const QString& found)
{
    switch (error.kind) {
    case ParseErrorKind::Comment: return ConditionErrorText::tr("comments are not allowed in a condition");
    case ParseErrorKind::ColonEquals: return ConditionErrorText::tr("use = to compare; := is assignment");
    case ParseErrorKind::DoubleEquals: return ConditionErrorText::tr("use = to compare; == is not Structured Text");
    case ParseErrorKind::BangEquals: return ConditionErrorText::tr("use <> for 'not equal'");
    case ParseErrorKind::Bang: return ConditionErrorText::tr("use NOT for negation");
    case ParseErrorKind::DoubleAmpersand: return ConditionErrorText::tr("use AND (or &) for 'and'");
    case ParseErrorKind::Pipe: return ConditionErrorText::tr("use OR for 'or'");
    case ParseErrorKind::Power: return ConditionErrorText::tr("'**' (power) is not supported in a condition");
    case ParseErrorKind::Semicolon: return ConditionErrorText::tr("';' is not allowed in a condition: write only the expression");
    case ParseErrorKind::InvalidUtf8: return ConditionErrorText::tr("the text contains bytes that are not valid UTF-8");
    case ParseErrorKind::NonAscii:
        return ConditionErrorText::tr("'%1' contains a non-ASCII character: names use ASCII letters, digits and _ only")
            .arg(found);
    case ParseErrorKind::TypedLiteral:
        return ConditionErrorText::tr("'%1' is not supported: write plain decimal numbers, TRUE or FALSE (no typed, "
                                      "based or time literals)")
            .arg(found);
    case ParseErrorKind::QualifiedName:
        return ConditionErrorText::tr("'%1': qualified names are not allowed, write the variable name alone")
            .arg(found);
    case ParseErrorKind::InvalidNumber: return ConditionErrorText::tr("'%1' is not a valid number").arg(found);
    case ParseErrorKind::IfThen:
        //: %1: IF, THEN, ELSE... as written
        return ConditionErrorText::tr("'%1' is not allowed in a condition: write only the boolean expression, "
                                      "without IF ... THEN")
            .arg(found);
    case ParseErrorKind::TypeName:
        return ConditionErrorText::tr("'%1' is not allowed in a condition: it is a type name").arg(found);
    case ParseErrorKind::Keyword:
        return ConditionErrorText::tr("'%1' is not allowed in a condition: it is an IEC 61131-3 keyword").arg(found);
    case ParseErrorKind::ControlCharacter: {
        const QString byte = QString::number(error.number & 0xFF, 16).rightJustified(2, QLatin1Char('0')).toUpper();
        //: %1: the byte in hexadecimal (0x1B)
        return ConditionErrorText::tr("unexpected control character (byte %1)").arg(QStringLiteral("0x") + byte);
    }
    case ParseErrorKind::UnexpectedCharacter: return ConditionErrorText::tr("unexpected character '%1'").arg(found);
    default: return {};
    }
}

// The receptivities and actions of nested GRAFCETs.
QString nestedText(const core::cond::ParseError& error, const QString& found)
{
    switch (error.kind) {
    case ParseErrorKind::EdgeOperand:
        if (error.found.empty())
            return ConditionErrorText::tr("an edge (RE, FE, ↑, ↓) applies to a variable name");
        //: %1: what follows RE, FE, ↑ or ↓ instead of a variable name
        return ConditionErrorText::tr("an edge (RE, FE, ↑, ↓) applies to a variable name, not to '%1'").arg(found);
    case ParseErrorKind::DurationWithoutStep:
        //: %1: a duration such as 5s; X3 is step 3's activity, keep it as is
        return ConditionErrorText::tr("the duration '%1' must be followed by /X<step>, as in %1/X3").arg(found);
    case ParseErrorKind::DurationStepExpected:
        if (error.found.empty())
            return ConditionErrorText::tr("expected a step activity X<step> after '/' of the duration");
        return ConditionErrorText::tr("expected a step activity X<step> after '/' of the duration, found '%1'")
            .arg(found);
    case ParseErrorKind::ZeroDuration:
        return ConditionErrorText::tr("the duration '%1' is zero: write a positive duration").arg(found);
    case ParseErrorKind::InvalidDuration:
        return ConditionErrorText::tr("'%1' is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s "
                                      "(units d, h, m, s, ms, largest first)")
            .arg(found);
    case ParseErrorKind::EmptyAction:
        return ConditionErrorText::tr(
            "empty action: write for example Valve, S Valve, R Valve or Count := Count + 1");
    case ParseErrorKind::ActionTargetNotVariable:
        return ConditionErrorText::tr("an action writes a variable: '%1' is not a variable name").arg(found);
    case ParseErrorKind::UnsupportedQualifier:
        return ConditionErrorText::tr(
                   "the qualifier '%1' is not supported: use N (or none), S, R or an assignment V := value")
            .arg(found);
    case ParseErrorKind::QualifierWithAssignment:
        return ConditionErrorText::tr("an assignment takes no qualifier: write V := value, without '%1'").arg(found);
    case ParseErrorKind::StoredWithCondition:
        //: %1: the qualifier S or R
        return ConditionErrorText::tr(
                   "a stored action (%1) takes no IF condition: only continuous actions are conditional")
            .arg(found);
    case ParseErrorKind::AssignmentWithoutValue: return ConditionErrorText::tr("expected a value after ':='");
    case ParseErrorKind::ConditionMissing: return ConditionErrorText::tr("expected a condition after IF");
    case ParseErrorKind::EqualsForAssignment: return ConditionErrorText::tr("use := to assign a value; = compares");
    case ParseErrorKind::AfterAction: return ConditionErrorText::tr("unexpected '%1' after a complete action").arg(found);
    case ParseErrorKind::PropertyQuantifier:
        return found.isEmpty() ? ConditionErrorText::tr("a property starts with never or always")
                               : ConditionErrorText::tr("a property starts with never or always, not '%1'").arg(found);
    case ParseErrorKind::StepAfterIn:
        return found.isEmpty() ? ConditionErrorText::tr("expected a GEMMA step after 'in'")
                               : ConditionErrorText::tr("expected a GEMMA step after 'in', found '%1'").arg(found);
    default: return invalidTokenText(error, found);
    }
}

QString structureText(const core::cond::ParseError& error, const QString& found)
{
    const QString number = QString::number(error.number);
    switch (error.kind) {
    case ParseErrorKind::Empty:
        return ConditionErrorText::tr("empty condition: write when the transition fires (TRUE if it is always "
                                      "ready), or hide the transition if the machine does not need it");
    case ParseErrorKind::TooComplex:
        return ConditionErrorText::tr("condition too complex: operators nested more than %1 levels deep").arg(number);
    case ParseErrorKind::TooDeepParentheses:
        return ConditionErrorText::tr("condition nested too deeply: more than %1 levels of parentheses").arg(number);
    case ParseErrorKind::TooDeepUnary:
        return ConditionErrorText::tr("condition nested too deeply: more than %1 levels of unary operators")
            .arg(number);
    case ParseErrorKind::UnmatchedClose: return ConditionErrorText::tr("unmatched ')': no '(' opens it");
    case ParseErrorKind::OperandBefore:
        //: %1: an operator the condition starts with
        return ConditionErrorText::tr("expected an operand before '%1'").arg(found);
    case ParseErrorKind::EmptyParentheses: return ConditionErrorText::tr("empty parentheses: expected an expression inside '( )'");
    case ParseErrorKind::OperandAfter:
        if (error.found.empty())
            //: %1: the operator or '(' the condition ends with
            return ConditionErrorText::tr("expected an operand after '%1'").arg(QString::fromStdString(error.previous));
        //: %1: an operator or '('; %2: what follows it instead of an operand
        return ConditionErrorText::tr("expected an operand after '%1', found '%2'")
            .arg(QString::fromStdString(error.previous), found);
    case ParseErrorKind::UnclosedAtEnd:
        //: %1: a column number
        return ConditionErrorText::tr("unmatched '(' at column %1: missing ')'").arg(number);
    case ParseErrorKind::Unclosed:
        //: %1: what was found; %2: the column of the '('
        return ConditionErrorText::tr("unexpected '%1': expected an operator or ')' to close the '(' at column %2")
            .arg(found, number);
    case ParseErrorKind::AfterCondition:
        return ConditionErrorText::tr("unexpected '%1' after a complete condition").arg(found);
    case ParseErrorKind::MissingOperator:
        return ConditionErrorText::tr("unexpected '%1' after a complete condition (missing operator?)").arg(found);
    default: return nestedText(error, found);
    }
}

} // namespace

QString conditionErrorText(const core::cond::ParseError& error)
{
    // The user's text quoted: a word of 50,000 letters would widen the panel showing it.
    return structureText(error, elidedText(QString::fromStdString(error.found)));
}

} // namespace editor
