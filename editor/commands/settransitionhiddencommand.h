#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Hide transition A1->F2" / "Show transition A1->F2".
class SetTransitionHiddenCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetTransitionHiddenCommand)

public:
    SetTransitionHiddenCommand(Document& document, const QString& transitionId, bool hidden);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_transitionId;
    bool m_hidden;
};

} // namespace editor
