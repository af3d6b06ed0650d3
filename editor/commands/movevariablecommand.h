#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Move variable Speed": to another position (0-based) of the variable list.
class MoveVariableCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(MoveVariableCommand)

public:
    MoveVariableCommand(Document& document, const QString& name, int index);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_name;
    int m_index;
    int m_previous = -1;
};

} // namespace editor
