#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Negate F1->D1" / "Remove negation of F1->D1".
class SetNegatedCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetNegatedCommand)

public:
    SetNegatedCommand(Document& document, const QString& transitionId, bool negated);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_transitionId;
    bool m_negated;
};

} // namespace editor
