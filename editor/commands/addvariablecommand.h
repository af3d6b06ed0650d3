#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

namespace editor {

// "Add variable Start", at the given position of the variable list (-1: at the end).
class AddVariableCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(AddVariableCommand)

public:
    AddVariableCommand(Document& document, core::Variable variable, int index = -1);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    core::Variable m_variable;
    int m_index;
};

} // namespace editor
