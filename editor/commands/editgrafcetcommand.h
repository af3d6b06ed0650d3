#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/grafcet.h"

#include <QCoreApplication>

#include <functional>
#include <optional>

namespace editor {

// One structured edit of a nested GRAFCET ("Add step 7 to F1", "Renumber
// F1", "Create GRAFCET of F1"), named by the caller's wording, so that its
// undo text follows the UI language. Its first run applies
// the edit (a core/model/grafcetediting.h operation) to a copy of the
// GRAFCET (an empty one when the step has none) and keeps the GRAFCET
// before and after: redo and undo then set one or the other whole, so undo
// puts back exactly what was there whatever the edit did, and removes the
// GRAFCET the edit created. An edit that fails is reported like any refused
// command (Document::editFailed) and never enters the history.
class EditGrafcetCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(EditGrafcetCommand)

public:
    using Edit = std::function<core::Status(core::Grafcet&)>;
    using ModelCommand::Wording;

    EditGrafcetCommand(Document& document, const QString& stepId, Edit edit, Wording wording);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    Edit m_edit;
    core::Grafcet m_after;
    std::optional<core::Grafcet> m_before;
};

} // namespace editor
