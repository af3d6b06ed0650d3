#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/iectypes.h"

#include <QCoreApplication>

namespace editor {

// "Set type of Speed to INT".
class SetVariableTypeCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableTypeCommand)

public:
    SetVariableTypeCommand(Document& document, const QString& name, core::IecType type);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_name;
    core::IecType m_type;
    core::IecType m_previous = core::IecType::Bool;
};

} // namespace editor
