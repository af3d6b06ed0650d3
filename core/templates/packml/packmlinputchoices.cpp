#include "core/templates/packml/packmlinputchoices.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/iectypes.h"
#include "core/templates/packml/packmlsimulator.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>

namespace core::packml {

namespace {

// More private inputs than this and a condition is enumerated as shared:
// finding its TRUE and FALSE assignments would cost 2^n evaluations.
constexpr std::size_t kMaxPrivateInputs = 12;

void addOnce(std::vector<int>& list, int value)
{
    if (value >= 0 && std::find(list.begin(), list.end(), value) == list.end())
        list.push_back(value);
}

bool divides(const cond::Expression& expression)
{
    return std::any_of(expression.nodes.begin(), expression.nodes.end(), [](const cond::Node& node) {
        return node.kind == cond::NodeKind::Binary
               && (node.binaryOp == cond::BinaryOp::Divide || node.binaryOp == cond::BinaryOp::Modulo);
    });
}

void collectConstants(const cond::Expression& expression, std::set<std::int64_t>& constants)
{
    for (const cond::Node& node : expression.nodes) {
        if (node.kind != cond::NodeKind::IntegerLiteral && node.kind != cond::NodeKind::RealLiteral)
            continue;
        const auto value = cond::parseValue(node.kind == cond::NodeKind::IntegerLiteral ? IecType::Lint : IecType::Lreal,
                                            node.text);
        if (!value)
            continue;
        const std::int64_t whole = std::holds_alternative<double>(*value)
                                       ? static_cast<std::int64_t>(std::get<double>(*value))
                                       : std::get<std::int64_t>(*value);
        constants.insert(whole);
        constants.insert(-whole);
    }
}

void setValue(InputChoice& choice, int slot, const cond::Value& value)
{
    for (InputValue& entry : choice)
        if (entry.slot == slot) {
            entry.value = value;
            return;
        }
    choice.push_back({slot, value});
}

} // namespace

InputChoices::InputChoices(const PackmlProgram& program, const std::vector<std::string>& alwaysRead)
    : m_program(program)
{
    m_cntrlCmd = program.slotOf("CntrlCmd");
    m_cmdChangeRequest = program.slotOf("CmdChangeRequest");
    m_unitMode = program.slotOf("UnitMode");
    m_unitModeChangeRequest = program.slotOf("UnitModeChangeRequest");
    classify(alwaysRead);
}

void InputChoices::noteReads(const cond::Expression& expression, std::vector<int>& into) const
{
    for (int node : cond::variableNodes(expression)) {
        const int slot = m_program.slotOf(expression.at(node).text);
        if (slot >= 0 && m_program.variables[static_cast<std::size_t>(slot)].kind == VariableKind::Input)
            addOnce(into, slot);
    }
}

void InputChoices::classify(const std::vector<std::string>& alwaysRead)
{
    const auto makeCondition = [&](const ProgramCondition& condition) {
        Condition c;
        c.condition = &condition;
        c.nodeSlots.assign(condition.parsed.expression.nodes.size(), -1);
        if (condition.usable) {
            for (int node : cond::variableNodes(condition.parsed.expression))
                c.nodeSlots[static_cast<std::size_t>(node)] = m_program.slotOf(condition.parsed.expression.at(node).text);
            noteReads(condition.parsed.expression, c.inputs);
        }
        return c;
    };
    for (const ProgramCommand& command : m_program.commands) {
        m_commands.push_back(makeCondition(command.condition));
        m_commands.back().command = command.command;
    }
    for (std::size_t m = 0; m < m_program.modes.size(); ++m) {
        if (!m_program.modes[m].requestGenerated)
            continue;
        m_requests.push_back(makeCondition(m_program.modes[m].request));
        m_requests.back().modeIndex = static_cast<int>(m);
    }

    // How many readers each input has; GRAFCETs, edges and properties count as many.
    std::map<int, int> readers;
    for (const Condition& c : m_commands)
        for (int slot : c.inputs)
            ++readers[slot];
    for (const Condition& c : m_requests)
        for (int slot : c.inputs)
            ++readers[slot];
    std::vector<int> shared;
    for (const std::string& name : alwaysRead) {
        const int slot = m_program.slotOf(name);
        if (slot >= 0 && m_program.variables[static_cast<std::size_t>(slot)].kind == VariableKind::Input)
            addOnce(shared, slot);
    }
    for (const std::string& name : m_program.edgeVariables)
        addOnce(shared, m_program.slotOf(name));
    std::set<std::int64_t> constants{0};
    for (const ProgramGrafcet& g : m_program.grafcets)
        m_reads.push_back(grafcetReads(g.grafcet));
    for (const ProgramInstance& instance : m_program.instances) {
        if (instance.isSkeleton())
            continue;
        const NestedGrafcet& grafcet = m_program.grafcets[static_cast<std::size_t>(instance.grafcet)].grafcet;
        for (const std::string& name : grafcet.readVariables) {
            const int slot = m_program.slotOf(name);
            if (slot >= 0 && m_program.variables[static_cast<std::size_t>(slot)].kind == VariableKind::Input)
                addOnce(m_grafcetReads[static_cast<std::size_t>(instance.state)], slot);
        }
        for (const NestedTransition& transition : grafcet.transitions)
            if (transition.usable)
                collectConstants(transition.receptivity.expression, constants);
    }
    for (Condition* c : [&] {
             std::vector<Condition*> all;
             for (Condition& x : m_commands)
                 all.push_back(&x);
             for (Condition& x : m_requests)
                 all.push_back(&x);
             return all;
         }()) {
        if (c->condition->usable)
            collectConstants(c->condition->parsed.expression, constants);
        const bool privateInputs = std::all_of(c->inputs.begin(), c->inputs.end(), [&](int slot) {
            const bool inGrafcet = std::any_of(m_grafcetReads.begin(), m_grafcetReads.end(), [&](const std::vector<int>& r) {
                return std::find(r.begin(), r.end(), slot) != r.end();
            });
            return readers[slot] == 1 && !inGrafcet && std::find(shared.begin(), shared.end(), slot) == shared.end()
                   && m_program.variables[static_cast<std::size_t>(slot)].type == IecType::Bool && slot != m_cmdChangeRequest
                   && slot != m_unitModeChangeRequest;
        });
        c->collapsible = privateInputs && c->inputs.size() <= kMaxPrivateInputs
                         && !(c->condition->usable && divides(c->condition->parsed.expression));
        if (!c->collapsible)
            for (int slot : c->inputs)
                addOnce(shared, slot);
    }
    m_alwaysEnumerated = shared;

    // What the PackTags requests may do in each state.
    for (const ProgramMode& mode : m_program.modes) {
        for (const ProgramState& state : mode.states)
            for (const ModeTransition& transition : state.transitions)
                if (transition.transition.trigger == Trigger::Command) {
                    auto& accepted = m_accepted[static_cast<std::size_t>(state.state)];
                    if (std::find(accepted.begin(), accepted.end(), transition.transition.command) == accepted.end())
                        accepted.push_back(transition.transition.command);
                }
        for (const ModeGrant& grant : mode.grants)
            for (State state : grant.states.list())
                for (std::size_t r = 0; r < m_program.modes.size(); ++r)
                    if (m_program.modes[r].number == grant.targetMode)
                        addOnce(m_grantable[static_cast<std::size_t>(state)], static_cast<int>(r));
    }

    // Numbers: the values around the constants the model compares with.
    m_values.resize(m_program.variables.size());
    bool numbersRead = false;
    for (std::size_t slot = 0; slot < m_program.variables.size(); ++slot) {
        const IecType type = m_program.variables[slot].type;
        if (type == IecType::Bool) {
            m_values[slot] = {cond::Value{false}, cond::Value{true}};
            continue;
        }
        if (static_cast<int>(slot) == m_cntrlCmd || static_cast<int>(slot) == m_unitMode)
            continue;
        const bool read = std::find(shared.begin(), shared.end(), static_cast<int>(slot)) != shared.end()
                          || std::any_of(m_grafcetReads.begin(), m_grafcetReads.end(), [&](const std::vector<int>& r) {
                                 return std::find(r.begin(), r.end(), static_cast<int>(slot)) != r.end();
                             });
        numbersRead = numbersRead || read;
        const cond::IntegerRange range = cond::integerRange(type);
        std::set<std::int64_t> around;
        for (std::int64_t c : constants)
            for (std::int64_t d : {-1, 0, 1})
                if ((d < 0 && c > range.low) || (d > 0 && c < range.high) || d == 0)
                    around.insert(std::clamp(c + d, range.low, range.high));
        for (std::int64_t v : around)
            m_values[slot].push_back(isRealType(type) ? cond::Value{static_cast<double>(v)} : cond::Value{v});
    }
    if (numbersRead)
        m_abstractions.push_back("numeric inputs take only the values around the constants the model compares with");
    for (int packtag : {m_cntrlCmd, m_cmdChangeRequest, m_unitMode, m_unitModeChangeRequest})
        if (std::find(shared.begin(), shared.end(), packtag) != shared.end()
            || std::any_of(m_grafcetReads.begin(), m_grafcetReads.end(), [&](const std::vector<int>& r) {
                   return std::find(r.begin(), r.end(), packtag) != r.end();
               })) {
            m_abstractions.push_back("a condition or GRAFCET reads a PackTags request input: it takes only the values "
                                     "the requests give it");
            break;
        }
}

bool InputChoices::requestCollapsed(std::size_t modeIndex) const
{
    return std::any_of(m_requests.begin(), m_requests.end(), [&](const Condition& c) {
        return c.modeIndex == static_cast<int>(modeIndex) && c.collapsible;
    });
}

InputChoices::GrafcetReads InputChoices::grafcetReads(const NestedGrafcet& grafcet) const
{
    GrafcetReads reads;
    reads.untilStable = grafcet.rule == EvolutionRule::UntilStable;
    for (const NestedStep& step : grafcet.steps) {
        std::vector<int>& list = reads.step[step.number];
        if (step.initial)
            reads.initialSteps.push_back(step.number);
        for (const auto* actions : {&step.continuous, &step.onActivation, &step.onDeactivation})
            for (const NestedAction& action : *actions)
                if (action.usable) {
                    noteReads(action.parsed.action.condition, list);
                    noteReads(action.parsed.action.value, list);
                }
        for (int slot : list)
            addOnce(reads.all, slot);
    }
    for (const NestedTransition& transition : grafcet.transitions) {
        reads.transitions.emplace_back();
        if (transition.usable)
            noteReads(transition.receptivity.expression, reads.transitions.back());
        for (int slot : reads.transitions.back())
            addOnce(reads.all, slot);
    }
    return reads;
}

// The inputs the call of (mode, the state) may read in the next scan: what
// its enabled transitions and the steps they lead to read (everything under
// *until stable*, where a call may evolve further).
void InputChoices::addInstanceReads(const PackmlSimulator& simulator, int mode, std::vector<int>& into) const
{
    const ProgramInstance* instance = m_program.instance(mode, simulator.state());
    if (!instance || instance->isSkeleton())
        return;
    const GrafcetReads& reads = m_reads[static_cast<std::size_t>(instance->grafcet)];
    const NestedGrafcet& grafcet = m_program.grafcets[static_cast<std::size_t>(instance->grafcet)].grafcet;
    const NestedEngine* engine = simulator.engine(static_cast<int>(instance - m_program.instances.data()));
    const bool resumes = simulator.state() == State::Execute && simulator.resume();
    const bool fresh = mode != simulator.mode() || (simulator.entry() && !resumes) || !engine;
    if (reads.untilStable) {
        for (int slot : reads.all)
            addOnce(into, slot);
        return;
    }
    const std::vector<int> active = fresh ? reads.initialSteps : engine->activeSteps();
    const auto isActive = [&](int step) { return std::find(active.begin(), active.end(), step) != active.end(); };
    const auto addStep = [&](int step) {
        const auto found = reads.step.find(step);
        if (found != reads.step.end())
            for (int slot : found->second)
                addOnce(into, slot);
    };
    for (int step : active)
        addStep(step);
    for (std::size_t t = 0; t < grafcet.transitions.size(); ++t) {
        const NestedTransition& transition = grafcet.transitions[t];
        if (!std::all_of(transition.upstream.begin(), transition.upstream.end(), isActive))
            continue;
        for (int slot : reads.transitions[t])
            addOnce(into, slot);
        for (int step : transition.downstream)
            addStep(step);
    }
}

InputChoices::Assignments InputChoices::assignments(const Condition& c, const PackmlSimulator& simulator) const
{
    Assignments result;
    const std::size_t n = c.inputs.size();
    for (std::uint32_t bits = 0; bits < (1u << n) && !(result.canBeTrue && result.canBeFalse); ++bits) {
        InputChoice assignment;
        for (std::size_t i = 0; i < n; ++i)
            assignment.push_back({c.inputs[i], cond::Value{((bits >> i) & 1u) != 0}});
        bool value = false;
        if (c.condition->usable) {
            value = cond::isTrue(cond::evaluate(c.condition->parsed.expression, [&](int node) {
                const int slot = c.nodeSlots[static_cast<std::size_t>(node)];
                for (const InputValue& v : assignment)
                    if (v.slot == slot)
                        return v.value;
                return slot < 0 ? cond::Value{false} : simulator.value(slot);
            }));
        }
        if (value && !result.canBeTrue) {
            result.canBeTrue = true;
            result.whenTrue = assignment;
        }
        if (!value && !result.canBeFalse) {
            result.canBeFalse = true;
            result.whenFalse = assignment;
        }
    }
    return result;
}

std::vector<InputChoice> InputChoices::choices(const PackmlSimulator& simulator, bool* truncated) const
{
    if (truncated)
        *truncated = false;
    const State state = simulator.state();
    const auto& accepted = m_accepted[static_cast<std::size_t>(state)];
    const auto& grantable = m_grantable[static_cast<std::size_t>(state)];
    const auto isAccepted = [&](Command command) {
        return std::find(accepted.begin(), accepted.end(), command) != accepted.end();
    };

    // The values every choice starts from, and the events it may add.
    InputChoice base;
    setValue(base, m_cmdChangeRequest, cond::Value{false});
    setValue(base, m_cntrlCmd, cond::Value{std::int64_t{0}});
    setValue(base, m_unitModeChangeRequest, cond::Value{false});
    setValue(base, m_unitMode, cond::Value{std::int64_t{simulator.mode()}});
    std::vector<InputChoice> commandEvents{{}};
    std::vector<InputChoice> modeEvents{{}};
    const auto collapse = [&](const Condition& c, bool memory, bool mayAct, std::vector<InputChoice>& events) {
        const Assignments a = assignments(c, simulator);
        for (const InputValue& v : a.canBeFalse ? a.whenFalse : a.whenTrue)
            setValue(base, v.slot, v.value);
        if (!memory && mayAct && a.canBeTrue && a.canBeFalse)
            events.push_back(a.whenTrue);
    };
    for (std::size_t i = 0; i < m_commands.size(); ++i)
        if (m_commands[i].collapsible)
            collapse(m_commands[i], simulator.commandMemory(i), isAccepted(m_commands[i].command), commandEvents);
    for (const Condition& c : m_requests)
        if (c.collapsible) {
            const bool mayAct = c.modeIndex >= 0 && m_program.modes[static_cast<std::size_t>(c.modeIndex)].number != simulator.mode()
                                && std::find(grantable.begin(), grantable.end(), c.modeIndex) != grantable.end();
            collapse(c, simulator.requestMemory(static_cast<std::size_t>(c.modeIndex)), mayAct, modeEvents);
        }
    if (!simulator.cmdChangeMemory())
        for (const ProgramCommand& command : m_program.commands)
            if (isAccepted(command.command))
                commandEvents.push_back({{m_cmdChangeRequest, cond::Value{true}},
                                         {m_cntrlCmd, cond::Value{std::int64_t{static_cast<int>(command.command)}}}});
    if (!simulator.modeChangeMemory())
        for (int r : grantable)
            if (m_program.modes[static_cast<std::size_t>(r)].number != simulator.mode())
                modeEvents.push_back({{m_unitModeChangeRequest, cond::Value{true}},
                                      {m_unitMode, cond::Value{std::int64_t{m_program.modes[static_cast<std::size_t>(r)].number}}}});

    // The shared inputs this scan reads, every combination.
    std::vector<int> enumerated = m_alwaysEnumerated;
    addInstanceReads(simulator, simulator.mode(), enumerated);
    for (int r : grantable)
        addInstanceReads(simulator, m_program.modes[static_cast<std::size_t>(r)].number, enumerated);
    std::vector<InputChoice> shared{{}};
    for (int slot : enumerated) {
        const auto& values = m_values[static_cast<std::size_t>(slot)];
        if (values.empty())
            continue; // CntrlCmd, UnitMode: the requests set them
        std::vector<InputChoice> next;
        for (const InputChoice& partial : shared)
            for (const cond::Value& value : values) {
                if (next.size() == kMaxChoices) {
                    if (truncated)
                        *truncated = true;
                    break;
                }
                next.push_back(partial);
                next.back().push_back({slot, value});
            }
        shared = std::move(next);
    }

    std::vector<InputChoice> result;
    for (const InputChoice& command : commandEvents)
        for (const InputChoice& mode : modeEvents)
            for (const InputChoice& inputs : shared) {
                if (result.size() == kMaxChoices) {
                    if (truncated)
                        *truncated = true;
                    return result;
                }
                InputChoice choice = base;
                for (const InputChoice* part : {&command, &mode, &inputs})
                    for (const InputValue& v : *part)
                        setValue(choice, v.slot, v.value);
                result.push_back(std::move(choice));
            }
    return result;
}

} // namespace core::packml
