#include "editor/commands/settransitionhiddencommand.h"

#include "editor/commands/commandids.h"
#include "editor/text/elementlabels.h"

#include "core/model/model.h"

namespace editor {

SetTransitionHiddenCommand::SetTransitionHiddenCommand(Document& document, const QString& transitionId, bool hidden)
    : ModelCommand(document,
        [=] {
            return hidden ? tr("Hide transition %1").arg(transitionLabel(transitionId))
                          : tr("Show transition %1").arg(transitionLabel(transitionId));
        })
    , m_transitionId(toStdString(transitionId))
    , m_hidden(hidden)
{
}

int SetTransitionHiddenCommand::id() const
{
    return SetTransitionHiddenId;
}

// A first run that finds the transition already so changes nothing and is
// dropped, so the inverse is always the opposite flag.
core::Status SetTransitionHiddenCommand::apply()
{
    return model().setTransitionHidden(m_transitionId, m_hidden);
}

core::Status SetTransitionHiddenCommand::revert()
{
    return model().setTransitionHidden(m_transitionId, !m_hidden);
}

} // namespace editor
