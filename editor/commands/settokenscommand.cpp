#include "editor/commands/settokenscommand.h"

#include "editor/commands/commandids.h"
#include "editor/text/elementlabels.h"

#include "core/model/model.h"

namespace editor {

SetTokensCommand::SetTokensCommand(Document& document, const QString& transitionId, const QStringList& tokens)
    : ModelCommand(document, [=] { return tr("Set tokens of %1").arg(transitionLabel(transitionId)); })
    , m_transitionId(toStdString(transitionId))
{
    for (const QString& token : tokens)
        m_tokens.push_back(toStdString(token));
}

int SetTokensCommand::id() const
{
    return SetTokensId;
}

core::Status SetTokensCommand::apply()
{
    if (firstRun()) {
        if (const core::Transition* transition = model().transition(m_transitionId))
            m_previous = transition->tokens;
    }
    return model().setTokens(m_transitionId, m_tokens);
}

core::Status SetTokensCommand::revert()
{
    return model().setTokens(m_transitionId, m_previous);
}

} // namespace editor
