#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

namespace editor {

// "Set kind of Valve to output": input, output or internal (spec
// grafcet-layer.md §2). The checks report a kind that does not fit its use.
class SetVariableKindCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableKindCommand)

public:
    SetVariableKindCommand(Document& document, const QString& name, core::VariableKind kind);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_name;
    core::VariableKind m_kind;
    core::VariableKind m_previous = core::VariableKind::Input;
};

} // namespace editor
