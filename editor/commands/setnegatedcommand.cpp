#include "editor/commands/setnegatedcommand.h"

#include "editor/commands/commandids.h"
#include "editor/text/elementlabels.h"

#include "core/model/model.h"

namespace editor {

SetNegatedCommand::SetNegatedCommand(Document& document, const QString& transitionId, bool negated)
    : ModelCommand(document,
        [=] {
            return negated ? tr("Negate %1").arg(transitionLabel(transitionId))
                           : tr("Remove negation of %1").arg(transitionLabel(transitionId));
        })
    , m_transitionId(toStdString(transitionId))
    , m_negated(negated)
{
}

int SetNegatedCommand::id() const
{
    return SetNegatedId;
}

// A first run that finds the flag already set changes nothing and is
// dropped, so the inverse is always the opposite flag.
core::Status SetNegatedCommand::apply()
{
    return model().setNegated(m_transitionId, m_negated);
}

core::Status SetNegatedCommand::revert()
{
    return model().setNegated(m_transitionId, !m_negated);
}

} // namespace editor
