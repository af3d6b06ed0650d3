#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

#include <memory>

namespace editor {

// "Reset to template": back to the template defaults, variables and
// settings included. Keeps a copy of the whole model for undo.
class ResetModelCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(ResetModelCommand)

public:
    explicit ResetModelCommand(Document& document);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::unique_ptr<core::Model> m_snapshot;
};

} // namespace editor
