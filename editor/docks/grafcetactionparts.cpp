#include "editor/docks/grafcetactionparts.h"

#include <QRegularExpression>

namespace editor {

namespace {

// "V IF condition" at its IF word: {V, condition}; "IF condition", written
// before the variable, is {"", condition}; {text, ""} without one.
std::pair<QString, QString> splitAtIf(const QString& text)
{
    static const QRegularExpression ifWord(QStringLiteral(R"((^|\s+)IF(\s+|$))"),
                                           QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch match = ifWord.match(text);
    if (!match.hasMatch())
        return {text, QString()};
    return {text.left(match.capturedStart()).trimmed(), text.mid(match.capturedEnd()).trimmed()};
}

bool isStored(core::ActionTiming timing)
{
    return timing != core::ActionTiming::Continuous;
}

} // namespace

GrafcetActionParts GrafcetActionParts::of(const core::GrafcetAction& action)
{
    GrafcetActionParts parts;
    parts.timing = action.timing;
    const QString text = QString::fromStdString(action.text).trimmed();
    // As the action parser reads it: N, S or R is a qualifier when a name
    // follows (`S := 1` assigns a variable S, `N IF c` drives a variable N).
    static const QRegularExpression leadingQualifier(QStringLiteral(R"(^([NSR])\s+(?!IF\b)([A-Z_].*)$)"),
                                                     QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch qualified = leadingQualifier.match(text);
    QString rest = text;
    if (qualified.hasMatch()) {
        parseQualifier(qualified.captured(1), &parts.qualifier);
        rest = qualified.captured(2).trimmed();
    } else if (const qsizetype assign = text.indexOf(QLatin1String(":=")); assign >= 0) {
        parts.qualifier = Qualifier::Assign;
        parts.variable = text.left(assign).trimmed();
        parts.operand = text.mid(assign + 2).trimmed();
        return parts;
    } else {
        parts.qualifierWritten = text.isEmpty(); // a new action gets the N written
    }
    std::tie(parts.variable, parts.operand) = splitAtIf(rest);
    // A stored action whose variable is not written yet: its qualifier
    // cannot be written alone (`S` is an action on a variable S).
    if (parts.variable.isEmpty() && !qualified.hasMatch() && isStored(parts.timing)) {
        parts.qualifier = Qualifier::S;
        parts.qualifierWritten = true;
    }
    return parts;
}

core::GrafcetAction GrafcetActionParts::action() const
{
    QString text;
    if (variable.isEmpty() && qualifier != Qualifier::Assign) {
        // A qualifier alone would be read as the variable (a lone `S`
        // drives a variable S): it waits for the variable, with the table.
        if (!operand.isEmpty())
            text = QStringLiteral("IF ") + operand;
        return {timing, text.toStdString()};
    }
    switch (qualifier) {
    case Qualifier::N:
        text = (qualifierWritten ? QStringLiteral("N ") : QString()) + variable;
        if (!operand.isEmpty())
            text += QStringLiteral(" IF ") + operand;
        break;
    case Qualifier::S:
    case Qualifier::R:
        // An operand here is wrong, but shown so that it can be corrected rather than lost.
        text = qualifierText(qualifier) + QLatin1Char(' ') + variable;
        if (!operand.isEmpty())
            text += QStringLiteral(" IF ") + operand;
        break;
    case Qualifier::Assign:
        text = variable + QStringLiteral(" := ") + operand;
        break;
    }
    return {timing, text.trimmed().toStdString()};
}

void GrafcetActionParts::setTiming(core::ActionTiming newTiming)
{
    timing = newTiming;
    if (isStored(timing) && qualifier == Qualifier::N)
        qualifier = Qualifier::S;
    else if (!isStored(timing) && qualifier != Qualifier::N)
        qualifier = Qualifier::N;
    qualifierWritten = true;
}

void GrafcetActionParts::setQualifier(Qualifier newQualifier)
{
    qualifier = newQualifier;
    qualifierWritten = true;
    if (qualifier == Qualifier::N)
        timing = core::ActionTiming::Continuous;
    else if (!isStored(timing))
        timing = core::ActionTiming::OnActivation;
}

QString GrafcetActionParts::qualifierText(Qualifier qualifier)
{
    switch (qualifier) {
    case Qualifier::N: return QStringLiteral("N");
    case Qualifier::S: return QStringLiteral("S");
    case Qualifier::R: return QStringLiteral("R");
    case Qualifier::Assign: return QStringLiteral(":=");
    }
    return {};
}

bool GrafcetActionParts::parseQualifier(const QString& text, Qualifier* qualifier)
{
    for (Qualifier candidate : {Qualifier::N, Qualifier::S, Qualifier::R, Qualifier::Assign}) {
        if (text.trimmed().compare(qualifierText(candidate), Qt::CaseInsensitive) == 0) {
            *qualifier = candidate;
            return true;
        }
    }
    return false;
}

} // namespace editor
