#include "editor/commands/pastevariablescommand.h"

#include "editor/commands/commandids.h"

#include <utility>

namespace editor {

namespace {

QString describe(const std::vector<core::Variable>& variables)
{
    if (variables.size() == 1)
        return PasteVariablesCommand::tr("Paste variable %1").arg(toQString(variables.front().name));
    return PasteVariablesCommand::tr("Paste %n variables", nullptr, static_cast<int>(variables.size()));
}

// "Start_12" -> "Start"; names without a numeric suffix stay.
std::string withoutNumberSuffix(const std::string& name)
{
    const std::size_t underscore = name.find_last_of('_');
    if (underscore == std::string::npos || underscore == 0 || underscore + 1 == name.size())
        return name;
    for (std::size_t i = underscore + 1; i < name.size(); ++i) {
        if (name[i] < '0' || name[i] > '9')
            return name;
    }
    return name.substr(0, underscore);
}

} // namespace

PasteVariablesCommand::PasteVariablesCommand(Document& document, std::vector<core::Variable> variables, int index)
    : ModelCommand(document, [=] { return describe(variables); })
    , m_variables(std::move(variables))
    , m_index(index)
{
}

int PasteVariablesCommand::id() const
{
    return PasteVariablesId;
}

std::string PasteVariablesCommand::freeName(const core::Model& model, const std::string& name)
{
    if (name.empty() || !model.variable(name))
        return name;
    const std::string base = withoutNumberSuffix(name);
    for (int n = 2;; ++n) {
        std::string candidate = base + "_" + std::to_string(n);
        if (!model.variable(candidate))
            return candidate;
    }
}

core::Status PasteVariablesCommand::apply()
{
    for (std::size_t i = 0; i < m_variables.size(); ++i) {
        core::Variable& variable = m_variables[i];
        if (firstRun())
            variable.name = freeName(model(), variable.name);
        const int index = m_index < 0 ? -1 : m_index + static_cast<int>(i);
        core::Status status = model().addVariable(variable, index);
        if (!status) {
            removeFirst(i);
            return status;
        }
    }
    return core::Status::success();
}

core::Status PasteVariablesCommand::revert()
{
    removeFirst(m_variables.size());
    return core::Status::success();
}

void PasteVariablesCommand::removeFirst(std::size_t count)
{
    for (std::size_t i = count; i > 0; --i)
        model().removeVariable(m_variables[i - 1].name);
}

} // namespace editor
