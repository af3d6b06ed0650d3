#pragma once

#include "editor/commands/modelcommand.h"

#include "core/templates/packml/packmltemplate.h"

#include <QCoreApplication>

namespace editor {

// One of a unit mode's state lists (spec packml.md §3.2, §3.4) set as a
// whole: its disabled states or the states where it allows a mode change.
// The caller gives the list it wants (the Modes dock keeps the disabled
// listing consistent with packml::consistentListing).
class SetModeStatesCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetModeStatesCommand)

public:
    enum class List { Disabled, ModeChange };

    SetModeStatesCommand(Document& document, int mode, List list, core::packml::StateSet states);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;
    core::Status write(const core::packml::StateSet& states);

    int m_mode;
    List m_list;
    core::packml::StateSet m_states;
    core::packml::StateSet m_previous;
};

} // namespace editor
