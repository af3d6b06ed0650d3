#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

#include <vector>

namespace editor {

// "Rename variable Stop to Halt": a refactoring, every condition and token
// that uses the variable follows. The model matches names ignoring case, so
// renaming back would not restore a condition that spelled the name
// differently ("STOP AND NOT stop"): undo restores the exact texts and
// tokens kept before the rename. A new name that is no valid identifier is
// refused (core::Model::renameVariable), with the reason in the UI language.
class RenameVariableCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(RenameVariableCommand)

public:
    RenameVariableCommand(Document& document, const QString& oldName, const QString& newName);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;
    core::Status inUiLanguage(core::Status status) const;

    struct TransitionText {
        std::string id;
        std::string condition;
        std::vector<std::string> tokens;
    };

    std::string m_oldName; // as declared before the rename
    std::string m_newName;
    std::vector<TransitionText> m_before;
};

} // namespace editor
