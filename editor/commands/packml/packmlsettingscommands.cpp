#include "editor/commands/packml/packmlsettingscommands.h"

#include "editor/commands/commandids.h"
#include "editor/commands/packml/packmlcommandlabels.h"
#include "editor/document.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"

namespace editor {

namespace {

using core::packml::Command;

} // namespace

SetPackmlOptionsCommand::SetPackmlOptionsCommand(Document& document, core::packml::Options options)
    : ModelCommand(document, [] { return tr("Change PackML edition and options"); })
    , m_options(options)
{
}

int SetPackmlOptionsCommand::id() const
{
    return SetPackmlOptionsId;
}

core::Status SetPackmlOptionsCommand::apply()
{
    if (!model().packml())
        return model().setPackMLOptions(m_options); // says why
    if (firstRun())
        m_previous = model().packml()->options;
    if (core::Status status = model().setPackMLOptions(m_options); !status)
        return status;
    if (m_options.edition == core::packml::Edition::Y2022 && m_previous.edition != m_options.edition)
        adoptCompleteCommand();
    return core::Status::success();
}

void SetPackmlOptionsCommand::adoptCompleteCommand()
{
    const core::packml::CommandInfo& info = core::packml::commandInfo(Command::Complete);
    const std::string input(info.defaultInput);
    if (firstRun()) {
        m_setCompleteCondition = model().packml()->command(Command::Complete).condition.empty();
        m_declaredCompleteInput = m_setCompleteCondition && model().variableIndex(input) < 0;
    }
    if (m_declaredCompleteInput) {
        core::Variable variable;
        variable.name = input;
        variable.comment = "The Complete command (PackTags CntrlCmd "
                           + std::to_string(static_cast<int>(Command::Complete)) + ")";
        model().addVariable(std::move(variable));
    }
    if (m_setCompleteCondition)
        model().setCommandCondition(Command::Complete, input);
}

core::Status SetPackmlOptionsCommand::revert()
{
    const core::packml::CommandInfo& info = core::packml::commandInfo(Command::Complete);
    if (m_setCompleteCondition)
        model().setCommandCondition(Command::Complete, {});
    if (m_declaredCompleteInput)
        model().removeVariable(info.defaultInput);
    return model().setPackMLOptions(m_previous);
}

SetPackmlInitialStateCommand::SetPackmlInitialStateCommand(Document& document, core::packml::State state)
    : ModelCommand(document,
                   [state] { return tr("Set initial state to %1").arg(toQString(core::packml::stateName(state))); })
    , m_state(state)
{
}

int SetPackmlInitialStateCommand::id() const
{
    return SetPackmlInitialStateId;
}

core::Status SetPackmlInitialStateCommand::apply()
{
    if (firstRun() && model().packml())
        m_previous = model().packml()->initialState;
    return model().setPackMLInitialState(m_state);
}

core::Status SetPackmlInitialStateCommand::revert()
{
    return model().setPackMLInitialState(m_previous);
}

SetPackmlInitialModeCommand::SetPackmlInitialModeCommand(Document& document, int mode)
    : ModelCommand(document, [title = modeTitleOf(document.model(), mode)] { return tr("Set initial mode to %1").arg(title); })
    , m_mode(mode)
{
}

int SetPackmlInitialModeCommand::id() const
{
    return SetPackmlInitialModeId;
}

core::Status SetPackmlInitialModeCommand::apply()
{
    if (!model().packml())
        return model().setPackMLInitialMode(m_mode); // says why
    if (!model().packml()->mode(m_mode))
        return core::Status::failure("unknown-mode", "there is no unit mode " + std::to_string(m_mode));
    if (firstRun())
        m_previous = model().packml()->initialMode;
    return model().setPackMLInitialMode(m_mode);
}

core::Status SetPackmlInitialModeCommand::revert()
{
    return model().setPackMLInitialMode(m_previous);
}

} // namespace editor
