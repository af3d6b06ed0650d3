#include "editor/commands/setsteptypecommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

namespace {

QString typeText(core::StepType type)
{
    switch (type) {
    case core::StepType::Macro:
        return SetStepTypeCommand::tr("macro-step");
    case core::StepType::Enclosing:
        return SetStepTypeCommand::tr("enclosing step");
    case core::StepType::Simple:
        break;
    }
    return SetStepTypeCommand::tr("simple step");
}

} // namespace

SetStepTypeCommand::SetStepTypeCommand(Document& document, const QString& stepId, core::StepType type)
    : ModelCommand(document, [=] { return tr("Set %1 to %2").arg(stepId, typeText(type)); })
    , m_stepId(toStdString(stepId))
    , m_type(type)
{
}

int SetStepTypeCommand::id() const
{
    return SetStepTypeId;
}

core::Status SetStepTypeCommand::apply()
{
    if (firstRun()) {
        if (const core::Step* step = model().step(m_stepId))
            m_previous = step->type;
    }
    return model().setStepType(m_stepId, m_type);
}

core::Status SetStepTypeCommand::revert()
{
    return model().setStepType(m_stepId, m_previous);
}

} // namespace editor
