#include "editor/commands/setevolutionrulecommand.h"

#include "editor/commands/commandids.h"

namespace editor {

namespace {

QString commandText(core::EvolutionRule rule)
{
    return rule == core::EvolutionRule::UntilStable
        ? SetEvolutionRuleCommand::tr("Set evolution rule to until stable")
        : SetEvolutionRuleCommand::tr("Set evolution rule to one evolution per scan");
}

} // namespace

SetEvolutionRuleCommand::SetEvolutionRuleCommand(Document& document, core::EvolutionRule rule)
    : ModelCommand(document, [=] { return commandText(rule); })
    , m_rule(rule)
{
}

int SetEvolutionRuleCommand::id() const
{
    return SetEvolutionRuleId;
}

core::Status SetEvolutionRuleCommand::apply()
{
    if (firstRun())
        m_previous = model().settings().evolution;
    model().setEvolutionRule(m_rule);
    return core::Status::success();
}

core::Status SetEvolutionRuleCommand::revert()
{
    model().setEvolutionRule(m_previous);
    return core::Status::success();
}

} // namespace editor
