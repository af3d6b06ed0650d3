#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Rename model". Consecutive edits merge, so typing undoes as a whole.
class SetModelNameCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetModelNameCommand)

public:
    SetModelNameCommand(Document& document, const QString& name);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_name;
    std::string m_previous;
};

} // namespace editor
