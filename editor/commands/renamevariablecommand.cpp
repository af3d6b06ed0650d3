#include "editor/commands/renamevariablecommand.h"

#include "editor/commands/commandids.h"
#include "editor/text/diagnostictext.h"

#include "core/model/model.h"

namespace editor {

RenameVariableCommand::RenameVariableCommand(Document& document, const QString& oldName, const QString& newName)
    : ModelCommand(document, [=] { return tr("Rename variable %1 to %2").arg(oldName, newName); })
    , m_oldName(toStdString(oldName))
    , m_newName(toStdString(newName))
{
}

int RenameVariableCommand::id() const
{
    return RenameVariableId;
}

core::Status RenameVariableCommand::apply()
{
    if (firstRun()) {
        if (const core::Variable* variable = model().variable(m_oldName))
            m_oldName = variable->name;
        for (const core::Transition& transition : model().transitions())
            m_before.push_back({transition.id, transition.condition, transition.tokens});
    }
    return inUiLanguage(model().renameVariable(m_oldName, m_newName));
}

// The core refuses in English (for the CLI); the reasons a user meets while
// typing a name are worded again in the UI language.
core::Status RenameVariableCommand::inUiLanguage(core::Status status) const
{
    if (status.code == "invalid-name") {
        status.message = toStdString(identifierProblemText(toQString(m_newName)));
    } else if (status.code == "duplicate-name") {
        if (const core::Variable* clash = model().variable(m_newName))
            status.message = toStdString(tr("a variable named '%1' already exists (IEC names ignore case)")
                                             .arg(toQString(clash->name)));
    }
    return status;
}

core::Status RenameVariableCommand::revert()
{
    core::Status status = model().renameVariable(m_newName, m_oldName);
    for (const TransitionText& before : m_before) {
        if (!status)
            break;
        const core::Transition* now = model().transition(before.id);
        if (!now)
            continue;
        if (now->condition != before.condition)
            status = model().setCondition(before.id, before.condition);
        if (status && now->tokens != before.tokens)
            status = model().setTokens(before.id, before.tokens);
    }
    return status;
}

} // namespace editor
