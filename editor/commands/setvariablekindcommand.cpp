#include "editor/commands/setvariablekindcommand.h"

#include "editor/commands/commandids.h"

namespace editor {

namespace {

// Whole sentences, so that translators can inflect the kind.
QString commandText(const QString& name, core::VariableKind kind)
{
    switch (kind) {
    case core::VariableKind::Output:
        return SetVariableKindCommand::tr("Set kind of %1 to output").arg(name);
    case core::VariableKind::Internal:
        return SetVariableKindCommand::tr("Set kind of %1 to internal").arg(name);
    case core::VariableKind::Input:
        break;
    }
    return SetVariableKindCommand::tr("Set kind of %1 to input").arg(name);
}

} // namespace

SetVariableKindCommand::SetVariableKindCommand(Document& document, const QString& name, core::VariableKind kind)
    : ModelCommand(document, [=] { return commandText(name, kind); })
    , m_name(toStdString(name))
    , m_kind(kind)
{
}

int SetVariableKindCommand::id() const
{
    return SetVariableKindId;
}

core::Status SetVariableKindCommand::apply()
{
    if (firstRun()) {
        if (const core::Variable* variable = model().variable(m_name))
            m_previous = variable->kind;
    }
    return model().setVariableKind(m_name, m_kind);
}

core::Status SetVariableKindCommand::revert()
{
    return model().setVariableKind(m_name, m_previous);
}

} // namespace editor
