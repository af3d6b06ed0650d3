#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/grafcet.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <QCoreApplication>

#include <optional>

namespace editor {

// What runs in a state of a mode (spec packml.md §4): its own GRAFCET (a
// new, empty one when it had none), the same as mode k's, or none. Leaving
// Own removes the GRAFCET; undo brings it back as it was.
class SetGrafcetChoiceCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetGrafcetChoiceCommand)

public:
    SetGrafcetChoiceCommand(Document& document, int mode, core::packml::State state,
                            core::packml::GrafcetChoice choice);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    int m_mode;
    core::packml::State m_state;
    core::packml::GrafcetChoice m_choice;
    core::packml::GrafcetChoice m_previous;
    std::optional<core::Grafcet> m_previousGrafcet; // the own GRAFCET the choice removes
};

} // namespace editor
