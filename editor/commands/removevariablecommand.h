#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

namespace editor {

// "Remove variable Start". Keeps the variable and its position, so undo
// puts it back where it was. Conditions that use it are left as they are
// (the checks then report the unknown name).
class RemoveVariableCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(RemoveVariableCommand)

public:
    RemoveVariableCommand(Document& document, const QString& name);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_name;
    core::Variable m_removed;
    int m_index = -1;
};

} // namespace editor
