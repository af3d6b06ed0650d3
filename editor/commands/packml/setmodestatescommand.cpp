#include "editor/commands/packml/setmodestatescommand.h"

#include "editor/commands/commandids.h"
#include "editor/commands/packml/packmlcommandlabels.h"
#include "editor/document.h"

#include "core/model/model.h"

namespace editor {

namespace {

QString describe(const QString& mode, SetModeStatesCommand::List list)
{
    return list == SetModeStatesCommand::List::Disabled
        ? SetModeStatesCommand::tr("Change disabled states of mode %1").arg(mode)
        : SetModeStatesCommand::tr("Change mode-change states of mode %1").arg(mode);
}

} // namespace

SetModeStatesCommand::SetModeStatesCommand(Document& document, int mode, List list, core::packml::StateSet states)
    : ModelCommand(document, [title = modeTitleOf(document.model(), mode), list] { return describe(title, list); })
    , m_mode(mode)
    , m_list(list)
    , m_states(states)
{
}

int SetModeStatesCommand::id() const
{
    return m_list == List::Disabled ? SetModeDisabledId : SetModeChangeStatesId;
}

core::Status SetModeStatesCommand::apply()
{
    if (firstRun() && model().packml()) {
        if (const core::packml::Mode* mode = model().packml()->mode(m_mode))
            m_previous = m_list == List::Disabled ? mode->disabled : mode->modeChange;
    }
    return write(m_states);
}

core::Status SetModeStatesCommand::revert()
{
    return write(m_previous);
}

core::Status SetModeStatesCommand::write(const core::packml::StateSet& states)
{
    return m_list == List::Disabled ? model().setModeDisabled(m_mode, states)
                                    : model().setModeChangeStates(m_mode, states);
}

} // namespace editor
