#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/grafcet.h"

#include <QCoreApplication>

namespace editor {

// "Remove action 2 of F1 step 3". Keeps the action, so undo puts it back
// where it was.
class RemoveGrafcetActionCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(RemoveGrafcetActionCommand)

public:
    RemoveGrafcetActionCommand(Document& document, const QString& stepId, int step, int index);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    int m_step;
    int m_index;
    core::GrafcetAction m_removed;
};

} // namespace editor
