#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

namespace editor {

// "Set evolution rule to until stable": how a nested GRAFCET
// evolves in one scan (spec grafcet-layer.md §4.1).
class SetEvolutionRuleCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetEvolutionRuleCommand)

public:
    SetEvolutionRuleCommand(Document& document, core::EvolutionRule rule);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    core::EvolutionRule m_rule;
    core::EvolutionRule m_previous = core::EvolutionRule::OneEvolutionPerScan;
};

} // namespace editor
