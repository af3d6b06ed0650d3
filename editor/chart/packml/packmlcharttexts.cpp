#include "editor/chart/packml/packmlcharttexts.h"

#include "editor/text/packmltexts.h"

namespace editor {

namespace {

using core::packml::Command;
using core::packml::State;
using core::packml::Trigger;

QString line(const QString& text)
{
    return QStringLiteral("<br/>") + text.toHtmlEscaped();
}

QString commandPart(const core::packml::TemplateTransition& transition)
{
    return transition.trigger == Trigger::StateComplete ? QStringLiteral("SC")
                                                        : packmltext::commandName(transition.command);
}

} // namespace

QString PackmlChartTexts::modeTitle(int number, const QString& name)
{
    return QStringLiteral("%1 %2").arg(number).arg(name);
}

QString PackmlChartTexts::modeTitle(const core::packml::Mode& mode)
{
    const std::string_view name = mode.displayName();
    return modeTitle(mode.number, QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
}

QStringList PackmlChartTexts::transitionLabels(const core::packml::TemplateTransition& transition,
                                               const std::optional<core::packml::Destination>& destination)
{
    const QString label = commandPart(transition);
    if (!destination || !destination->skipped)
        return {label};
    const QString leadsTo = QStringLiteral("→ ") + packmltext::stateName(destination->state);
    return {label + QLatin1Char(' ') + leadsTo, leadsTo};
}

QStringList PackmlChartTexts::frameLabels(Command command, const QString& condition, bool defaultCondition,
                                          const std::optional<core::packml::Destination>& destination)
{
    QString label = packmltext::commandName(command);
    if (destination && destination->skipped)
        label += QStringLiteral(" → ") + packmltext::stateName(destination->state);
    if (!defaultCondition && !condition.trimmed().isEmpty())
        return {label + QStringLiteral(": ") + condition.simplified()}; // elided: the condition is the point
    return {label};
}

QString PackmlChartTexts::stateToolTip(State state, const QString& displayName, bool disabled, const QString& mode,
                                       const std::optional<core::packml::GrafcetChoice>& grafcet)
{
    const core::packml::StateInfo& info = core::packml::stateInfo(state);
    QString text = QStringLiteral("<b>%1</b> (%2)").arg(displayName.toHtmlEscaped()).arg(static_cast<int>(state));
    text += QStringLiteral("<br/><i>%1</i>").arg(packmltext::stateKindName(info.kind).toHtmlEscaped());
    text += line(packmltext::stateMeaning(state));
    if (disabled)
        //: %1: the unit mode the chart shows ("3 Manual")
        text += line(tr("Disabled in mode %1: never active there.").arg(mode));
    else if (grafcet && core::packml::holdsGrafcet(state)) {
        using Kind = core::packml::GrafcetChoice::Kind;
        switch (grafcet->kind) {
        case Kind::Own: text += line(tr("Runs its own nested GRAFCET in this mode.")); break;
        case Kind::SameAs:
            //: %1: the number of the unit mode whose GRAFCET runs
            text += line(tr("Runs the nested GRAFCET of mode %1 for this state.").arg(grafcet->sameAsMode));
            break;
        case Kind::None:
            text += line(state == State::Execute ? tr("No nested GRAFCET in this mode: it waits for a command.")
                                                 : tr("No nested GRAFCET in this mode: it completes at once."));
            break;
        }
    }
    return text;
}

QString PackmlChartTexts::transitionToolTip(const core::packml::TemplateTransition& transition,
                                            const std::optional<core::packml::Destination>& destination,
                                            const QString& mode)
{
    QString text = QStringLiteral("<b>%1 → %2</b>")
                       .arg(packmltext::stateName(transition.source), packmltext::stateName(transition.target));
    if (transition.trigger == Trigger::StateComplete)
        //: %1: a PackML state ("Starting")
        text += line(tr("SC (State Complete): %1 has done its work.").arg(packmltext::stateName(transition.source)));
    else
        text += line(packmltext::commandMeaning(transition.command));
    if (transition.optional)
        text += line(tr("Optional: exists only under an option of Model Settings."));
    if (destination && destination->skipped)
        //: %1: the unit mode ("3 Manual"), %2: the disabled state, %3: where the transition leads instead
        text += line(tr("In mode %1, %2 is disabled: this transition leads to %3.")
                         .arg(mode, packmltext::stateName(*destination->skipped),
                              packmltext::stateName(destination->state)));
    return text;
}

QString PackmlChartTexts::frameToolTip(Command command, const QString& condition,
                                       const std::optional<core::packml::Destination>& destination, const QString& mode)
{
    QString text = QStringLiteral("<b>%1</b>").arg(packmltext::commandName(command));
    text += line(packmltext::commandMeaning(command));
    text += line(command == Command::Abort ? tr("Accepted by every state in the Abort frame, before their own transitions.")
                                           : tr("Accepted by every state in the Stop frame, before their own transitions."));
    if (!condition.trimmed().isEmpty())
        text += QStringLiteral("<br/>") + tr("Condition:").toHtmlEscaped()
              + QStringLiteral(" <tt>%1</tt>").arg(condition.trimmed().toHtmlEscaped());
    if (destination && destination->skipped)
        text += line(tr("In mode %1, %2 is disabled: this transition leads to %3.")
                         .arg(mode, packmltext::stateName(*destination->skipped),
                              packmltext::stateName(destination->state)));
    return text;
}

} // namespace editor
