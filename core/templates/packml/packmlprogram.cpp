#include "core/templates/packml/packmlprogram.h"

#include "core/codegen/nestedgrafcetset.h"
#include "core/condition/blanktext.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparseerror.h"
#include "core/condition/symboltable.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlprogramname.h"
#include "core/templates/packml/packtags.h"

#include <algorithm>

namespace core::packml {

namespace {

// The names of spec §5.3 (PM018) and the IEC rules (GG301-GG303). The six
// PackTags are the program's own globals: reading them is what they are for,
// unless a user variable took one of their names.
class PackmlUnusableNames final : public UnusableNames {
public:
    PackmlUnusableNames(const Model& model, std::string programName)
        : m_programName(std::move(programName))
        , m_modeNames(modeNames(*model.packml()))
    {
        for (const PackTag& tag : packTags())
            if (model.variableIndex(tag.name) >= 0)
                m_takenTags.emplace_back(tag.name);
    }

    const char* code(std::string_view name) const override
    {
        if (isPackTagName(name) && !isTakenTag(name))
            return nullptr;
        switch (identifierProblem(name)) {
        case IdentifierProblem::None: return isReservedName(name, m_programName, m_modeNames) ? "PM018" : nullptr;
        case IdentifierProblem::Keyword: return "GG302";
        case IdentifierProblem::GeneratorName: return "GG303";
        default: return "GG301";
        }
    }

    std::string detail(std::string_view name) const override
    {
        if (!code(name))
            return {};
        if (const IdentifierProblem problem = identifierProblem(name); problem != IdentifierProblem::None)
            return identifierProblemMessage(problem, name);
        return "'" + std::string(name) + "' is a name the generated PackML code uses";
    }

    std::vector<std::string> arguments(const Variable& variable) const override
    {
        return {variable.name, detail(variable.name)};
    }

private:
    bool isTakenTag(std::string_view name) const
    {
        return std::any_of(m_takenTags.begin(), m_takenTags.end(),
                           [&](const std::string& taken) { return equalsIgnoreCase(taken, name); });
    }

    std::string m_programName;
    std::vector<std::string> m_modeNames;
    std::vector<std::string> m_takenTags; // PackTags a user variable also names (PM018)
};

// How messages name a mode's GRAFCET of a state: "Manual Execute".
std::string grafcetLabel(std::string_view modeName, State state)
{
    return std::string(modeName) + " " + std::string(stateName(state));
}

struct BuildContext {
    const Model& model;
    const Configuration& configuration;
    PackmlProgram& program;
    const SymbolTable& symbols;
    const PackmlUnusableNames& names;
};

ProgramProblem conditionProblem(std::string code, const std::string& element, std::string message,
                              std::vector<std::string> arguments)
{
    ProgramProblem problem;
    problem.code = std::move(code);
    problem.element = element;
    problem.message = std::move(message);
    problem.arguments = std::move(arguments);
    return problem;
}

// Parses and type-checks a command or request condition (the GEMMA
// language: no step activity, edge or step duration, PM019) and says why it
// cannot be used. `element` locates the problems, `label` names the place.
ProgramCondition analyseCondition(const BuildContext& context, const std::string& text, const std::string& element,
                                  const std::string& label)
{
    ProgramCondition condition;
    condition.text = text;
    std::vector<ProgramProblem>& problems = context.program.problems;
    if (isBlank(text))
        return condition; // FALSE; a command's is GG202 (addCommands), a request's means "none"
    condition.parsed = cond::parse(text);
    if (!condition.parsed.ok()) {
        const cond::ParseError& error = *condition.parsed.error;
        std::vector<std::string> arguments{label, excerpt(text, error.span), error.message};
        cond::appendArguments(error, arguments);
        problems.push_back(conditionProblem("GG201", element, "syntax error in " + label + ": " + error.message,
                                            std::move(arguments)));
        return condition;
    }
    std::vector<cond::TypeIssue> issues = cond::typeCheck(condition.parsed.expression, context.symbols);
    for (cond::TypeIssue& issue : issues) {
        std::vector<std::string> arguments{label, excerpt(text, issue.span), issue.message};
        if (issue.error)
            cond::appendArguments(*issue.error, arguments);
        problems.push_back(conditionProblem(std::move(issue.code), element, "in " + label + ": " + issue.message,
                                            std::move(arguments)));
    }
    condition.usable = issues.empty();
    for (int node : cond::variableNodes(condition.parsed.expression)) {
        const Variable* variable = context.symbols.find(condition.parsed.expression.at(node).text);
        const char* code = variable ? context.names.code(variable->name) : nullptr;
        if (!code)
            continue;
        problems.push_back(conditionProblem(code, element,
                                            "in " + label + ": invalid variable name: " + context.names.detail(variable->name),
                                            context.names.arguments(*variable)));
        condition.usable = false;
    }
    return condition;
}

void addCommands(const BuildContext& context, std::span<const StateSet> enabledPerMode)
{
    for (const Command command : generatedCommands(enabledPerMode, context.configuration.options)) {
        ProgramCommand generated;
        generated.command = command;
        generated.name = std::string(commandName(command));
        const std::string label = "the condition of the " + generated.name + " command";
        const std::string& text = context.configuration.command(command).condition;
        generated.condition = analyseCondition(context, text, generated.name, label);
        if (isBlank(text)) // as the checks say (GG202): FALSE is written for a command that only CntrlCmd gives
            context.program.problems.push_back(conditionProblem(
                "GG202", generated.name, label + " is empty: write FALSE for a command that comes only through CntrlCmd",
                {generated.name}));
        context.program.commands.push_back(std::move(generated));
    }
}

std::vector<ModeGrant> grantsOf(const Mode& current, const Configuration& configuration,
                                std::span<const StateSet> enabledPerMode)
{
    std::vector<ModeGrant> grants;
    for (std::size_t r = 0; r < configuration.modes.size(); ++r) {
        const Mode& requested = configuration.modes[r];
        if (requested.number == current.number)
            continue;
        const StateSet states = modeChangeStates(current.modeChange, requested.modeChange, enabledPerMode[r]);
        if (!states.empty())
            grants.push_back({requested.number, states});
    }
    return grants;
}

// Which own GRAFCET an instance of (mode, state) runs: the mode's own, or
// the one of the mode it is the same as when that mode has its own (PM015
// otherwise: the skeleton runs).
int ownerModeOf(const Configuration& configuration, const Mode& mode, State state)
{
    const GrafcetChoice& choice = mode.grafcetChoice(state);
    if (choice.kind == GrafcetChoice::Kind::Own)
        return mode.number;
    if (choice.kind != GrafcetChoice::Kind::SameAs || choice.sameAsMode == mode.number)
        return 0;
    const Mode* owner = configuration.mode(choice.sameAsMode);
    return owner && owner->grafcetChoice(state).kind == GrafcetChoice::Kind::Own ? owner->number : 0;
}

int grafcetIndex(const BuildContext& context, int ownerMode, State state)
{
    std::vector<ProgramGrafcet>& grafcets = context.program.grafcets;
    for (std::size_t i = 0; i < grafcets.size(); ++i) {
        if (grafcets[i].ownerMode == ownerMode && grafcets[i].state == state)
            return static_cast<int>(i);
    }
    const Grafcet* grafcet = context.model.grafcet(grafcetKey(ownerMode, state));
    if (!grafcet)
        return -1;
    const std::string ownerName(context.configuration.mode(ownerMode)->displayName());
    ProgramGrafcet built;
    built.ownerMode = ownerMode;
    built.state = state;
    built.key = grafcetKey(ownerMode, state);
    built.typeName = grafcetTypeName(ownerName, state);
    const NestedScope scope{built.key, grafcetLabel(ownerName, state), context.program.variables,
                            context.symbols, context.names};
    built.grafcet = buildNestedGrafcet(context.model, scope, *grafcet, context.program.problems);
    grafcets.push_back(std::move(built));
    return static_cast<int>(grafcets.size() - 1);
}

int addInstance(const BuildContext& context, const Mode& mode, State state)
{
    ProgramInstance instance;
    instance.mode = mode.number;
    instance.state = state;
    instance.name = instanceName(mode.displayName(), state);
    instance.ownerMode = ownerModeOf(context.configuration, mode, state);
    if (instance.ownerMode != 0)
        instance.grafcet = grafcetIndex(context, instance.ownerMode, state);
    if (instance.grafcet < 0) {
        instance.ownerMode = 0;
        instance.typeName = skeletonTypeName(state);
    } else {
        instance.typeName = context.program.grafcets[static_cast<std::size_t>(instance.grafcet)].typeName;
    }
    context.program.instances.push_back(std::move(instance));
    return static_cast<int>(context.program.instances.size() - 1);
}

ProgramMode makeMode(const BuildContext& context, const Mode& mode, const StateSet& enabled,
                     std::span<const StateSet> enabledPerMode)
{
    ProgramMode result;
    result.number = mode.number;
    result.name = std::string(mode.displayName());
    result.enabled = enabled;
    for (const State state : enabled.list()) {
        ProgramState programState;
        programState.state = state;
        programState.transitions = modeTransitionsFrom(state, enabled, context.configuration.options);
        if (holdsGrafcet(state))
            programState.instance = addInstance(context, mode, state);
        result.states.push_back(std::move(programState));
    }
    result.grants = grantsOf(mode, context.configuration, enabledPerMode);
    return result;
}

// Spec §6.2: a request condition is generated when some other mode may
// grant a change to its mode.
void addRequests(const BuildContext& context)
{
    std::vector<ProgramMode>& modes = context.program.modes;
    for (ProgramMode& mode : modes) {
        const Mode& configured = *context.configuration.mode(mode.number);
        const bool grantable = std::any_of(modes.begin(), modes.end(), [&](const ProgramMode& other) {
            return std::any_of(other.grants.begin(), other.grants.end(),
                               [&](const ModeGrant& grant) { return grant.targetMode == mode.number; });
        });
        if (!grantable || isBlank(configured.request)) {
            mode.request.text = configured.request;
            continue;
        }
        mode.request = analyseCondition(context, configured.request, std::to_string(mode.number),
                                        "the request condition of mode " + mode.name);
        mode.requestGenerated = true;
    }
}

void addSkeletonsAndEdges(PackmlProgram& program)
{
    StateSet skeletons;
    for (const ProgramInstance& instance : program.instances)
        if (instance.isSkeleton())
            skeletons.insert(instance.state);
    program.skeletons = skeletons.list();

    std::vector<OwnedGrafcet> owned;
    std::vector<const NestedGrafcet*> built;
    for (ProgramGrafcet& grafcet : program.grafcets) {
        const std::string ownerName = program.mode(grafcet.ownerMode)->name;
        owned.push_back({grafcet.key, grafcetLabel(ownerName, grafcet.state), &grafcet.grafcet});
        built.push_back(&grafcet.grafcet);
    }
    rejectStoredWritesOfContinuousOutputs(owned, program.problems);
    program.edgeVariables = edgeVariablesOf(program.variables, built);
}

} // namespace

const ProgramState* ProgramMode::state(State wanted) const
{
    for (const ProgramState& s : states)
        if (s.state == wanted)
            return &s;
    return nullptr;
}

const ProgramMode* PackmlProgram::mode(int number) const
{
    for (const ProgramMode& m : modes)
        if (m.number == number)
            return &m;
    return nullptr;
}

const ProgramCommand* PackmlProgram::command(Command wanted) const
{
    for (const ProgramCommand& c : commands)
        if (c.command == wanted)
            return &c;
    return nullptr;
}

const ProgramInstance* PackmlProgram::instance(int modeNumber, State state) const
{
    for (const ProgramInstance& i : instances)
        if (i.mode == modeNumber && i.state == state)
            return &i;
    return nullptr;
}

int PackmlProgram::slotOf(std::string_view name) const
{
    for (std::size_t i = 0; i < variables.size(); ++i)
        if (equalsIgnoreCase(variables[i].name, name))
            return static_cast<int>(i);
    return -1;
}

std::string instanceName(std::string_view modeName, State state)
{
    return std::string(modeName) + "_" + std::string(stateName(state));
}

std::string skeletonTypeName(State state)
{
    return std::string(stateName(state)) + "_FB";
}

std::string grafcetTypeName(std::string_view ownerModeName, State state)
{
    return instanceName(ownerModeName, state) + "_FB";
}

PackmlProgram buildPackmlProgram(const Model& model)
{
    const Configuration& configuration = *model.packml();
    PackmlProgram program;
    program.programName = programName(model);
    program.options = configuration.options;
    program.initialState = configuration.initialState;
    program.initialMode = configuration.initialMode;
    program.evolution = model.settings().evolution;
    program.variables = model.variables();
    for (Variable& tag : packTagVariables(configuration))
        program.variables.push_back(std::move(tag));

    const SymbolTable symbols(program.variables);
    const PackmlUnusableNames names(model, program.programName);
    const BuildContext context{model, configuration, program, symbols, names};
    std::vector<StateSet> enabledPerMode;
    for (const Mode& mode : configuration.modes)
        enabledPerMode.push_back(enabledStates(mode.disabled).enabled);

    addCommands(context, enabledPerMode);
    for (std::size_t m = 0; m < configuration.modes.size(); ++m)
        program.modes.push_back(makeMode(context, configuration.modes[m], enabledPerMode[m], enabledPerMode));
    addRequests(context);
    addSkeletonsAndEdges(program);
    return program;
}

} // namespace core::packml
