// The inputs of a scan in the PackML Promela model, chosen as the explorer's
// InputChoices chooses them (packmlinputchoices.h).

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/templates/packml/packmlpromelawriter.h"

#include <algorithm>

namespace core::packml::promela {

namespace {

// The input slots a condition reads.
std::vector<int> inputsOf(const PackmlProgram& program, const ProgramCondition& condition)
{
    std::vector<int> inputs;
    if (!condition.usable)
        return inputs;
    for (int node : cond::variableNodes(condition.parsed.expression)) {
        const int slot = program.slotOf(condition.parsed.expression.at(node).text);
        if (slot >= 0 && program.variables[static_cast<std::size_t>(slot)].kind == VariableKind::Input)
            addOnce(inputs, slot);
    }
    return inputs;
}

} // namespace

std::vector<State> Writer::acceptingStates(Command command) const
{
    std::vector<State> accepting;
    for (const StateInfo& info : states()) {
        const auto& accepted = m_accepted[static_cast<std::size_t>(info.state)];
        if (std::find(accepted.begin(), accepted.end(), command) != accepted.end())
            accepting.push_back(info.state);
    }
    return accepting;
}

std::pair<bool, bool> Writer::collapsedValues(const ProgramCondition& c) const
{
    if (!c.usable)
        return {false, true};
    const std::vector<int> inputs = inputsOf(m_program, c);
    bool canBeTrue = false, canBeFalse = false;
    for (std::uint32_t bits = 0; bits < (1u << inputs.size()); ++bits) {
        const cond::Value value = cond::evaluate(c.parsed.expression, [&](int node) {
            const int slot = m_program.slotOf(c.parsed.expression.at(node).text);
            const auto at = std::find(inputs.begin(), inputs.end(), slot);
            if (at == inputs.end())
                throw Unsupported("the condition " + c.text + " reads a stored variable beside its own inputs");
            return cond::Value{((bits >> (at - inputs.begin())) & 1u) != 0};
        });
        (cond::isTrue(value) ? canBeTrue : canBeFalse) = true;
    }
    return {canBeTrue, canBeFalse};
}

// Spec §8 inputs as InputChoices gives them: the other inputs any value,
// then at most one command event and one mode event.
void Writer::writeInputs()
{
    Lines& p = m_process;
    p.line("/* the inputs of this scan */");
    std::vector<int> collapsedInputs;
    for (std::size_t i = 0; i < m_program.commands.size(); ++i)
        if (m_choices.commandCollapsed(i))
            for (int slot : inputsOf(m_program, m_program.commands[i].condition))
                addOnce(collapsedInputs, slot);
    for (std::size_t r = 0; r < m_program.modes.size(); ++r)
        if (m_program.modes[r].requestGenerated && m_choices.requestCollapsed(r))
            for (int slot : inputsOf(m_program, m_program.modes[r].request))
                addOnce(collapsedInputs, slot);
    for (std::size_t slot = 0; slot < m_program.variables.size(); ++slot) {
        const int s = static_cast<int>(slot);
        const Variable& variable = m_program.variables[slot];
        if (variable.kind != VariableKind::Input || s == m_cntrlCmd || s == m_unitMode || s == m_cmdChangeRequest
            || s == m_unitModeChangeRequest || !m_names.holds(variable)
            || std::find(collapsedInputs.begin(), collapsedInputs.end(), s) != collapsedInputs.end())
            continue; // an input of a type the model does not hold is read by nothing: Names refuses the reads
        std::string options;
        for (const cond::Value& value : m_choices.values(s))
            options += ":: " + Names::input(s) + " = " + valueText(value) + "; ";
        if (!options.empty())
            p.line("if " + options + "fi;");
    }
    p.line(Names::input(m_unitMode) + " = gMode;");
    writeCommandEvent();
    writeModeEvent();
}

void Writer::writeCommandEvent()
{
    Lines& p = m_process;
    std::vector<std::string> options;
    for (std::size_t i = 0; i < m_program.commands.size(); ++i) {
        if (!m_choices.commandCollapsed(i))
            continue;
        const auto [canBeTrue, canBeFalse] = collapsedValues(m_program.commands[i].condition);
        const std::string value = "cv" + std::to_string(i);
        p.line(value + " = " + (canBeFalse ? "0" : "1") + ";");
        const std::vector<State> accepting = acceptingStates(m_program.commands[i].command);
        if (canBeTrue && canBeFalse && !accepting.empty())
            options.push_back(":: !mc" + std::to_string(i) + " && " + stateIn(accepting) + " -> " + value + " = 1;");
        if (!accepting.empty())
            options.push_back(":: !mCmd && " + stateIn(accepting) + " -> " + Names::input(m_cmdChangeRequest) + " = 1; "
                              + Names::input(m_cntrlCmd) + " = "
                              + std::to_string(static_cast<int>(m_program.commands[i].command)) + ";");
    }
    for (std::size_t i = 0; i < m_program.commands.size(); ++i) {
        if (m_choices.commandCollapsed(i))
            continue;
        const std::vector<State> accepting = acceptingStates(m_program.commands[i].command);
        if (!accepting.empty())
            options.push_back(":: !mCmd && " + stateIn(accepting) + " -> " + Names::input(m_cmdChangeRequest) + " = 1; "
                              + Names::input(m_cntrlCmd) + " = "
                              + std::to_string(static_cast<int>(m_program.commands[i].command)) + ";");
    }
    p.line("if");
    p.line(":: skip; /* no command event */");
    for (const std::string& option : options)
        p.line(option);
    p.line("fi;");
}

void Writer::writeModeEvent()
{
    Lines& p = m_process;
    std::vector<std::string> options;
    for (std::size_t r = 0; r < m_program.modes.size(); ++r) {
        const ProgramMode& mode = m_program.modes[r];
        std::vector<State> grantable;
        for (const StateInfo& info : states()) {
            const auto& list = m_grantable[static_cast<std::size_t>(info.state)];
            if (std::find(list.begin(), list.end(), static_cast<int>(r)) != list.end())
                grantable.push_back(info.state);
        }
        const std::string where = "gMode != " + std::to_string(mode.number) + " && " + stateIn(grantable);
        if (mode.requestGenerated && m_choices.requestCollapsed(r)) {
            const auto [canBeTrue, canBeFalse] = collapsedValues(mode.request);
            p.line("rv" + std::to_string(r) + " = " + (canBeFalse ? "0" : "1") + ";");
            if (canBeTrue && canBeFalse && !grantable.empty())
                options.push_back(":: !mr" + std::to_string(r) + " && " + where + " -> rv" + std::to_string(r) + " = 1;");
        }
        if (!grantable.empty())
            options.push_back(":: !mMode && " + where + " -> " + Names::input(m_unitModeChangeRequest) + " = 1; "
                              + Names::input(m_unitMode) + " = " + std::to_string(mode.number) + ";");
    }
    p.line("if");
    p.line(":: skip; /* no mode event */");
    for (const std::string& option : options)
        p.line(option);
    p.line("fi;");
}

} // namespace core::packml::promela
