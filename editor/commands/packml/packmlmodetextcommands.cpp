#include "editor/commands/packml/packmlmodetextcommands.h"

#include "editor/commands/commandids.h"
#include "editor/commands/packml/modenamerule.h"
#include "editor/commands/packml/packmlcommandlabels.h"
#include "editor/document.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"

namespace editor {

namespace {

const core::packml::Mode* modeOf(const core::Model& model, const std::string& element)
{
    return model.packml() ? model.packml()->mode(modeNumberOf(element)) : nullptr;
}

} // namespace

RenameModeCommand::RenameModeCommand(Document& document, int mode, const QString& name)
    : TextFieldCommand(
        document, [title = modeTitleOf(document.model(), mode)] { return tr("Rename mode %1").arg(title); },
        modeElement(mode), name)
{
}

int RenameModeCommand::id() const
{
    return RenameModeId;
}

std::string RenameModeCommand::read(const std::string& element) const
{
    const core::packml::Mode* mode = modeOf(model(), element);
    return mode ? mode->name : std::string();
}

core::Status RenameModeCommand::write(const std::string& element, const std::string& value)
{
    return model().renameMode(modeNumberOf(element), value);
}

core::Status RenameModeCommand::validate(const std::string& element, const std::string& value) const
{
    const int number = modeNumberOf(element);
    if (number < core::packml::kFirstUserMode)
        return core::Status::success(); // the model refuses it and says why
    return modeNameProblem(model(), number, value);
}

SetModeCommentCommand::SetModeCommentCommand(Document& document, int mode, const QString& comment)
    : TextFieldCommand(
        document, [title = modeTitleOf(document.model(), mode)] { return tr("Edit comment of mode %1").arg(title); },
        modeElement(mode), comment)
{
}

int SetModeCommentCommand::id() const
{
    return SetModeCommentId;
}

std::string SetModeCommentCommand::read(const std::string& element) const
{
    const core::packml::Mode* mode = modeOf(model(), element);
    return mode ? mode->comment : std::string();
}

core::Status SetModeCommentCommand::write(const std::string& element, const std::string& value)
{
    return model().setModeComment(modeNumberOf(element), value);
}

SetModeRequestCommand::SetModeRequestCommand(Document& document, int mode, const QString& condition)
    : TextFieldCommand(
        document,
        [title = modeTitleOf(document.model(), mode)] { return tr("Edit request condition of mode %1").arg(title); },
        modeElement(mode), condition)
{
}

int SetModeRequestCommand::id() const
{
    return SetModeRequestId;
}

std::string SetModeRequestCommand::read(const std::string& element) const
{
    const core::packml::Mode* mode = modeOf(model(), element);
    return mode ? mode->request : std::string();
}

core::Status SetModeRequestCommand::write(const std::string& element, const std::string& value)
{
    return model().setModeRequest(modeNumberOf(element), value);
}

} // namespace editor
