#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Move action 2 of F1 step 3 up" (or down): actions run and are drawn in
// their list's order. Undo moves it back.
class MoveGrafcetActionCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(MoveGrafcetActionCommand)

public:
    MoveGrafcetActionCommand(Document& document, const QString& stepId, int step, int from, int to);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    int m_step;
    int m_from;
    int m_to;
};

} // namespace editor
