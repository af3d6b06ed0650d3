#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/grafcet.h"

#include <QCoreApplication>

namespace editor {

// "Set action 2 of F1 step 3" (the action's place in the step's list,
// counted from 1): its timing and text at once. Consecutive edits of the
// same action merge, so typing in one of its cells undoes as a whole.
class SetGrafcetActionCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetGrafcetActionCommand)

public:
    SetGrafcetActionCommand(Document& document, const QString& stepId, int step, int index, core::GrafcetAction action);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    int m_step;
    int m_index;
    core::GrafcetAction m_action;
    core::GrafcetAction m_previous;
};

} // namespace editor
