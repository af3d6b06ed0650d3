#include "core/templates/packml/packmlchecks.h"

#include "core/checks/grafcetchecks.h"
#include "core/condition/blanktext.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/condition/valueproblem.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlconditionchecks.h"
#include "core/templates/packml/packmldiagnostics.h"
#include "core/templates/packml/packmlmodechecks.h"
#include "core/templates/packml/packmlpathchecks.h"
#include "core/templates/packml/packmlprogramname.h"
#include "core/templates/packml/packmlrules.h"

#include <algorithm>
#include <string>

namespace core::packml {

namespace {

void append(std::vector<Diagnostic>& result, std::vector<Diagnostic> more)
{
    for (Diagnostic& diagnostic : more)
        result.push_back(std::move(diagnostic));
}

// PM001, PM003.
void checkSettings(const Model& model, std::vector<Diagnostic>& result)
{
    const Configuration& configuration = *model.packml();
    if (configuration.modes.empty())
        result.push_back(modelDiagnostic({"PM001", Severity::Error, "modes", "the model has no unit mode", {}}));
    else if (configuration.mode(configuration.initialMode) == nullptr) {
        const std::string number = std::to_string(configuration.initialMode);
        result.push_back(modelDiagnostic({"PM001", Severity::Error, "initialMode",
                                          "the initial mode " + number + " is not a unit mode of the model",
                                          {number}}));
    }
    const State initial = configuration.initialState;
    if (initial != State::Stopped && initial != State::Idle && initial != State::Aborted) {
        const std::string name(stateName(initial));
        result.push_back(modelDiagnostic({"PM003", Severity::Error, "initialState",
                                          "the initial state " + name + " is not Stopped, Idle or Aborted",
                                          {name}}));
    }
    const std::string& name = model.settings().name;
    const std::string program = programName(model);
    if (program != name)
        result.push_back(modelDiagnostic(
            {"PM003", Severity::Warning, "name",
             "the model's name '" + name + "' cannot name the PROGRAM (it is no IEC identifier, or the generated "
                 + "code or a variable takes it): the PROGRAM is named " + program,
             {name, program}}));
}

// PM013, PM017.
void checkCommands(const Model& model, std::vector<Diagnostic>& result)
{
    const Configuration& configuration = *model.packml();
    std::vector<StateSet> enabledPerMode;
    for (const Mode& mode : configuration.modes)
        enabledPerMode.push_back(enabledStates(mode.disabled).enabled);
    for (const Command command : unacceptedCommands(enabledPerMode, configuration.options)) {
        const std::string name(commandName(command));
        result.push_back(commandDiagnostic(
            command, {"PM013", Severity::Info, "condition",
                      "no enabled state of any mode accepts the command " + name + ": it generates no code",
                      {name}}));
    }
    if (configuration.options.edition != Edition::Y2015)
        return;
    const CommandSetting& complete = configuration.command(Command::Complete);
    if (!isBlank(complete.condition) || !complete.comment.empty())
        result.push_back(commandDiagnostic(
            Command::Complete, {"PM017", Severity::Warning, "condition",
                                "the Complete command exists in the 2022 edition only: its setting is ignored in "
                                "this 2015 model",
                                {"Complete", "condition"}}));
    if (configuration.options.completeInSuspendedHeld)
        result.push_back(commandDiagnostic(
            Command::Complete, {"PM017", Severity::Warning, "completeInSuspendedHeld",
                                "the option completeInSuspendedHeld is for the 2022 edition only: it is ignored "
                                "in this 2015 model",
                                {"Complete", "completeInSuspendedHeld"}}));
}

// GG301, GG302, GG304 as for GEMMA models; PM018 for the names the PackML
// code takes (spec §5.3). GEMMA's generator names (GG303) are free here.
void checkVariable(const Variable& variable, const std::string& program, const std::vector<std::string>& modes,
                   std::vector<Diagnostic>& result)
{
    const IdentifierProblem problem = identifierProblem(variable.name);
    if (problem != IdentifierProblem::None && problem != IdentifierProblem::GeneratorName) {
        const std::string detail = identifierProblemMessage(problem, variable.name);
        result.push_back(variableDiagnostic(variable.name,
                                            {problem == IdentifierProblem::Keyword ? "GG302" : "GG301",
                                             Severity::Error, "name", "invalid variable name: " + detail,
                                             {variable.name, detail}}));
    } else if (isReservedName(variable.name, program, modes)) {
        result.push_back(variableDiagnostic(
            variable.name, {"PM018", Severity::Error, "name",
                            "the variable name '" + variable.name
                                + "' is one the generated PackML code uses (PackTags, the state machine, the "
                                  "function blocks or the program " + program + ")",
                            {variable.name, program}}));
    }
    if (const std::optional<ValueProblem> value = valueProblem(variable.type, variable.defaultValue)) {
        const std::string detail = toText(*value);
        std::vector<std::string> arguments{variable.name, variable.defaultValue, detail};
        appendArguments(*value, arguments);
        result.push_back(variableDiagnostic(variable.name,
                                            {"GG304", Severity::Error, "default",
                                             "the default value of variable '" + variable.name
                                                 + "' is invalid: " + detail,
                                             std::move(arguments)}));
    }
}

// Which variables (by declaration index) a text that generates code
// mentions: the conditions of the commands some enabled state accepts (in
// the model's edition), the mode requests and the effective GRAFCETs. A
// condition that does not parse yet still counts its identifiers, as GEMMA's
// GG305 does.
std::vector<bool> usedVariables(const Model& model)
{
    const Configuration& configuration = *model.packml();
    const SymbolTable symbols(model.variables());
    std::vector<bool> used(model.variables().size(), false);
    const auto use = [&](std::string_view name) {
        if (const Variable* variable = symbols.find(name))
            used[static_cast<std::size_t>(variable - model.variables().data())] = true;
    };
    const auto useTokens = [&](const std::string& text) {
        for (const cond::Token& token : cond::tokenize(text))
            if (token.kind == cond::TokenKind::Identifier)
                use(token.text);
    };
    std::vector<StateSet> enabledPerMode;
    for (const Mode& mode : configuration.modes)
        enabledPerMode.push_back(enabledStates(mode.disabled).enabled);
    const std::vector<Command> unaccepted = unacceptedCommands(enabledPerMode, configuration.options);
    for (const CommandInfo& info : allCommands()) {
        const bool generated = commandInEdition(info.command, configuration.options.edition)
            && std::find(unaccepted.begin(), unaccepted.end(), info.command) == unaccepted.end();
        if (generated)
            useTokens(configuration.command(info.command).condition);
    }
    for (const Mode& mode : configuration.modes)
        useTokens(mode.request);
    forEachNestedIdentifier(model, use);
    return used;
}

// GG305, as for GEMMA models.
Diagnostic unusedVariable(const std::string& name)
{
    return variableDiagnostic(name, {"GG305", Severity::Warning, "name",
                                     "variable '" + name
                                         + "' is used by no condition, receptivity or action that generates code",
                                     {name}});
}

} // namespace

std::vector<Diagnostic> checkPackMLModel(const Model& model)
{
    std::vector<Diagnostic> result;
    if (model.packml() == nullptr)
        return result;
    checkSettings(model, result);
    append(result, checkConditions(model));
    checkCommands(model, result);
    append(result, checkModes(model));
    append(result, checkPaths(model));
    const std::string program = programName(model);
    const std::vector<std::string> modes = modeNames(*model.packml());
    const std::vector<bool> used = usedVariables(model);
    for (std::size_t i = 0; i < used.size(); ++i) {
        const Variable& variable = model.variables()[i];
        checkVariable(variable, program, modes, result);
        if (!used[i])
            result.push_back(unusedVariable(variable.name));
    }
    return result;
}

} // namespace core::packml
