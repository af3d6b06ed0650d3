#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/grafcet.h"

#include <QCoreApplication>

namespace editor {

// "Add action 3 to F1 step 3": inserts the action at `index` of the step's
// list (its place from 1 in the text); undo removes it.
class AddGrafcetActionCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(AddGrafcetActionCommand)

public:
    AddGrafcetActionCommand(Document& document, const QString& stepId, int step, int index,
                            core::GrafcetAction action);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    int m_step;
    int m_index;
    core::GrafcetAction m_action;
};

} // namespace editor
