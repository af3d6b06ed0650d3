#include "core/templates/packml/packtags.h"

#include <algorithm>
#include <array>
#include <string>

namespace core::packml {

namespace {

constexpr std::array kPackTags{
    PackTag{"CntrlCmd", IecType::Dint, true, "command number, issued at a rising edge of CmdChangeRequest"},
    PackTag{"CmdChangeRequest", IecType::Bool, true, "rising edge: issue CntrlCmd"},
    PackTag{"UnitMode", IecType::Dint, true, "requested unit mode"},
    PackTag{"UnitModeChangeRequest", IecType::Bool, true, "rising edge: request UnitMode"},
    PackTag{"StateCurrent", IecType::Dint, false, "the state at the end of the scan"},
    PackTag{"UnitModeCurrent", IecType::Dint, false, "the unit mode at the end of the scan"},
};

std::string initialValue(const PackTag& tag, const Configuration& configuration)
{
    if (tag.name == "UnitMode" || tag.name == "UnitModeCurrent")
        return std::to_string(configuration.initialMode);
    if (tag.name == "StateCurrent")
        return std::to_string(static_cast<int>(configuration.initialState));
    return tag.type == IecType::Bool ? "FALSE" : "0";
}

} // namespace

std::span<const PackTag> packTags()
{
    return kPackTags;
}

std::vector<Variable> packTagVariables(const Configuration& configuration)
{
    std::vector<Variable> variables;
    for (const PackTag& tag : kPackTags) {
        Variable variable;
        variable.name = std::string(tag.name);
        variable.type = tag.type;
        variable.defaultValue = initialValue(tag, configuration);
        variable.comment = std::string(tag.meaning);
        variable.kind = tag.input ? VariableKind::Input : VariableKind::Output;
        variables.push_back(std::move(variable));
    }
    return variables;
}

bool isPackTagName(std::string_view name)
{
    return std::any_of(kPackTags.begin(), kPackTags.end(),
                       [&](const PackTag& tag) { return equalsIgnoreCase(tag.name, name); });
}

} // namespace core::packml
