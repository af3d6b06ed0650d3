#include "editor/text/conditiontypeerrortext.h"

#include "editor/stdstring.h"
#include "editor/text/displaytext.h"

#include <QCoreApplication>

namespace editor {

namespace {

// The translation context of the texts.
class ConditionTypeErrorText {
    Q_DECLARE_TR_FUNCTIONS(ConditionTypeErrorText)
};

using TypeErrorKind = core::cond::TypeError::Kind;

// "'Speed' is INT": a whole clause, so that each language can word a type
// name and a kind of value differently.
QString operandText(const core::cond::TypeError::Operand& operand)
{
    using core::cond::TypeError;
    const QString text = elidedText(fromStd(operand.text)); // quoted: never the width of a panel
    if (operand.type == TypeError::kIntegerValue)
        //: %1: a subexpression of the condition
        return ConditionTypeErrorText::tr("'%1' is an integer").arg(text);
    if (operand.type == TypeError::kRealValue)
        return ConditionTypeErrorText::tr("'%1' is a real number").arg(text);
    if (operand.type == TypeError::kUnknownValue)
        return ConditionTypeErrorText::tr("'%1' is of unknown type").arg(text);
    //: %1: a subexpression of the condition; %2: its IEC type (INT, BOOL)
    return ConditionTypeErrorText::tr("'%1' is %2").arg(text, fromStd(operand.type));
}

} // namespace

QString conditionTypeErrorText(const core::cond::TypeError& error)
{
    const QString op = fromStd(error.op);
    const QString first = operandText(error.first);
    switch (error.kind) {
    case TypeErrorKind::NotBoolCondition:
        //: %1: the condition and what it is ("'Speed + 1' is an integer")
        return ConditionTypeErrorText::tr("a condition must be BOOL, but %1").arg(first);
    case TypeErrorKind::NotBoolOperand:
        //: %1: NOT; %2: its operand and what it is ("'Speed' is INT")
        return ConditionTypeErrorText::tr("%1 needs a BOOL operand, but %2").arg(op, first);
    case TypeErrorKind::NotNumericOperand:
        //: %1: '-' (negation); %2: its operand and what it is ("'Start' is BOOL")
        return ConditionTypeErrorText::tr("unary %1 needs a numeric operand, but %2").arg(op, first);
    case TypeErrorKind::BoolOperands:
        //: %1: AND, OR or XOR; %2: the operand at fault and what it is ("'Speed' is INT")
        return ConditionTypeErrorText::tr("%1 needs BOOL operands, but %2").arg(op, first);
    case TypeErrorKind::NumericOperands:
        //: %1: a comparison or arithmetic operator ('<', '+'); %2: the operand at fault and what it is
        return ConditionTypeErrorText::tr("%1 needs numeric operands, but %2").arg(op, first);
    case TypeErrorKind::IntegerOperands:
        //: %1: MOD; %2: the operand at fault and what it is ("'Temp' is REAL")
        return ConditionTypeErrorText::tr("%1 needs integer operands, but %2").arg(op, first);
    case TypeErrorKind::SameKindOperands:
        //: %1: '=' or '<>'; %2, %3: each operand and what it is ("'Start' is BOOL", "'Speed' is INT")
        return ConditionTypeErrorText::tr("%1 needs two operands of the same kind, but %2 and %3")
            .arg(op, first, operandText(error.second));
    case TypeErrorKind::IntegerLiteralRange:
        return ConditionTypeErrorText::tr(
                   "'%1' is out of range: integer literals go up to 9223372036854775807 (LINT)")
            .arg(fromStd(error.first.text));
    case TypeErrorKind::RealLiteralRange:
        return ConditionTypeErrorText::tr("'%1' is out of range for LREAL (-1.8E308..1.8E308)")
            .arg(fromStd(error.first.text));
    }
    return {};
}

} // namespace editor
