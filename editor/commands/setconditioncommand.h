#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit condition of F1->A2". Consecutive edits of the same transition's
// condition merge into one undo step, so typing undoes as a whole.
class SetConditionCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetConditionCommand)

public:
    SetConditionCommand(Document& document, const QString& transitionId, const QString& condition);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_transitionId;
    std::string m_condition;
    std::string m_previous;
};

} // namespace editor
