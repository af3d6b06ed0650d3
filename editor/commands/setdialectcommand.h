#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

namespace editor {

// "Set dialect to CODESYS": the flavour of the generated code (spec §7).
class SetDialectCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetDialectCommand)

public:
    SetDialectCommand(Document& document, core::Dialect dialect);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    core::Dialect m_dialect;
    core::Dialect m_previous = core::Dialect::Iec;
};

} // namespace editor
