#include "editor/commands/packml/packmlcommandtextcommands.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"

namespace editor {

namespace {

using core::packml::Command;

core::Status unknownCommand(const std::string& name)
{
    return core::Status::failure("unknown-command", "there is no PackML command '" + name + "'");
}

const core::packml::CommandSetting* commandSetting(const core::Model& model, const std::string& name)
{
    const auto command = core::packml::findCommand(name);
    return command && model.packml() ? &model.packml()->command(*command) : nullptr;
}

} // namespace

SetCommandConditionCommand::SetCommandConditionCommand(Document& document, const QString& command,
                                                       const QString& condition)
    : TextFieldCommand(
        document, [=] { return tr("Edit condition of command %1").arg(command); }, command, condition)
{
}

int SetCommandConditionCommand::id() const
{
    return SetCommandConditionId;
}

std::string SetCommandConditionCommand::read(const std::string& element) const
{
    const core::packml::CommandSetting* setting = commandSetting(model(), element);
    return setting ? setting->condition : std::string();
}

core::Status SetCommandConditionCommand::write(const std::string& element, const std::string& value)
{
    const auto command = core::packml::findCommand(element);
    return command ? model().setCommandCondition(*command, value) : unknownCommand(element);
}

SetCommandCommentCommand::SetCommandCommentCommand(Document& document, const QString& command, const QString& comment)
    : TextFieldCommand(
        document, [=] { return tr("Edit comment of command %1").arg(command); }, command, comment)
{
}

int SetCommandCommentCommand::id() const
{
    return SetCommandCommentId;
}

std::string SetCommandCommentCommand::read(const std::string& element) const
{
    const core::packml::CommandSetting* setting = commandSetting(model(), element);
    return setting ? setting->comment : std::string();
}

core::Status SetCommandCommentCommand::write(const std::string& element, const std::string& value)
{
    const auto command = core::packml::findCommand(element);
    return command ? model().setCommandComment(*command, value) : unknownCommand(element);
}

} // namespace editor
