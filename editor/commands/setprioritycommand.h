#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

#include <utility>
#include <vector>

namespace editor {

// "Set priority of A1->F5 to 1". Moving one transition renumbers its
// siblings, so undo restores the order of every outgoing transition of the
// source as it was.
class SetPriorityCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetPriorityCommand)

public:
    SetPriorityCommand(Document& document, const QString& transitionId, int priority);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_transitionId;
    int m_priority;
    std::vector<std::string> m_previousOrder; // the source's transitions, by their order before
};

} // namespace editor
