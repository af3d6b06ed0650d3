#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>
#include <QStringList>

#include <vector>

namespace editor {

// "Set tokens of F1->A2": the BOOL variables of the condition that get a
// token (spec §6.4).
class SetTokensCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetTokensCommand)

public:
    SetTokensCommand(Document& document, const QString& transitionId, const QStringList& tokens);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_transitionId;
    std::vector<std::string> m_tokens;
    std::vector<std::string> m_previous;
};

} // namespace editor
