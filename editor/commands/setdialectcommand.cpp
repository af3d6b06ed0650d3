#include "editor/commands/setdialectcommand.h"

#include "editor/commands/commandids.h"

namespace editor {

namespace {

QString dialectText(core::Dialect dialect)
{
    return dialect == core::Dialect::Codesys ? SetDialectCommand::tr("CODESYS") : SetDialectCommand::tr("IEC");
}

} // namespace

SetDialectCommand::SetDialectCommand(Document& document, core::Dialect dialect)
    : ModelCommand(document, [=] { return tr("Set dialect to %1").arg(dialectText(dialect)); })
    , m_dialect(dialect)
{
}

int SetDialectCommand::id() const
{
    return SetDialectId;
}

core::Status SetDialectCommand::apply()
{
    if (firstRun())
        m_previous = model().settings().dialect;
    model().setDialect(m_dialect);
    return core::Status::success();
}

core::Status SetDialectCommand::revert()
{
    model().setDialect(m_previous);
    return core::Status::success();
}

} // namespace editor
