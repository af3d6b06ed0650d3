#include "editor/commands/packml/addmodecommand.h"

#include "editor/commands/commandids.h"
#include "editor/commands/packml/modenamerule.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"

namespace editor {

AddModeCommand::AddModeCommand(Document& document, int mode, const QString& name)
    : ModelCommand(document, [=] { return tr("Add mode %1 %2").arg(mode).arg(name).trimmed(); })
    , m_mode(mode)
    , m_name(toStdString(name))
{
}

int AddModeCommand::id() const
{
    return AddModeId;
}

int AddModeCommand::firstFreeUserMode(const core::Model& model)
{
    const core::packml::Configuration* configuration = model.packml();
    if (!configuration)
        return 0;
    for (int number = core::packml::kFirstUserMode; number <= core::packml::kMaxModeNumber; ++number)
        if (!configuration->mode(number))
            return number;
    return 0;
}

QString AddModeCommand::suggestedName(const core::Model& model, int mode)
{
    QString name = QStringLiteral("Mode%1").arg(mode);
    for (int suffix = 2; !modeNameProblem(model, mode, toStdString(name)); ++suffix)
        name = QStringLiteral("Mode%1_%2").arg(mode).arg(suffix);
    return name;
}

core::Status AddModeCommand::apply()
{
    if (m_mode >= core::packml::kFirstUserMode) {
        if (core::Status problem = modeNameProblem(model(), m_mode, m_name); !problem)
            return problem;
    }
    return model().addMode(m_mode, m_name);
}

core::Status AddModeCommand::revert()
{
    return model().removeMode(m_mode);
}

} // namespace editor
