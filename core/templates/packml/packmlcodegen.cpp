#include "core/templates/packml/packmlcodegen.h"

#include "core/codegen/nestedcode.h"
#include "core/codegen/stgenerator.h"
#include "core/model/iectypes.h"
#include "core/templates/packml/packmlcodenaming.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlprogrampou.h"

#include <algorithm>
#include <functional>
#include <iterator>

namespace core::packml {

namespace {

std::string comment(std::string_view text)
{
    return "(* " + escapeComment(std::string(text)) + " *)";
}

PlcPou functionBlockHead(std::string name)
{
    PlcPou pou;
    pou.name = std::move(name);
    pou.kind = PouKind::FunctionBlock;
    pou.inputs.push_back({"Initialization", "BOOL", {}, "TRUE in the first scan of the state"});
    pou.outputs.push_back({"Complete", "BOOL", {}, "State Complete (SC)"});
    return pou;
}

// Spec §6.4, §6.6: GEMMA's skeleton; Execute's never completes (it waits
// for a command, §4), an acting state's completes at once.
PlcPou skeletonFunctionBlock(State state)
{
    PlcPou pou = functionBlockHead(skeletonTypeName(state));
    const std::string name(stateName(state));
    std::string& body = pou.body;
    body += "IF Initialization THEN\n";
    body += "    Complete := FALSE;\n";
    body += "    " + comment("initialization actions") + "\n";
    body += "END_IF;\n";
    if (state == State::Execute) {
        body += comment("The behaviour of Execute goes here. Without it Execute never completes: the unit waits "
                        "for a command.") + "\n";
        return pou;
    }
    body += comment("The behaviour of " + name + " goes here; it sets Complete := TRUE when the state is complete (SC).")
            + "\n";
    body += comment("Until it is written, the state completes at once:") + "\n";
    body += "Complete := TRUE;\n";
    return pou;
}

PlcPou grafcetFunctionBlock(const PackmlProgram& program, const ProgramGrafcet& grafcet,
                            const std::vector<std::string>& declared, Dialect dialect)
{
    PlcPou pou = functionBlockHead(grafcet.typeName);
    PackmlNaming naming(program, declared, dialect);
    const std::function<std::string(std::string_view)> global = [&naming](std::string_view name) {
        return naming.global(name);
    };
    const std::function<std::string(std::string_view)> edgeMemory = [&naming](std::string_view name) {
        return naming.edgeMemory(name);
    };
    const std::string label = program.mode(grafcet.ownerMode)->name + " " + std::string(stateName(grafcet.state));
    const NestedCodeSource source{grafcet.grafcet, grafcet.key, label, program.evolution, program.edgeVariables,
                                  program.problems};
    NestedCode code = generateNestedCode(source, global, edgeMemory);
    pou.outputs.insert(pou.outputs.end(), std::make_move_iterator(code.outputs.begin()),
                       std::make_move_iterator(code.outputs.end()));
    pou.locals = std::move(code.locals);
    pou.body = std::move(code.body);
    if (dialect == Dialect::Iec) {
        pou.externals = naming.readVariables();
        pou.externals.insert(pou.externals.end(), std::make_move_iterator(code.edgeMemories.begin()),
                             std::make_move_iterator(code.edgeMemories.end()));
    }
    return pou;
}

// Spec §6.1: owner mode, then state order, whichever mode first used it.
std::vector<const ProgramGrafcet*> grafcetsInOrder(const PackmlProgram& program)
{
    std::vector<const ProgramGrafcet*> ordered;
    for (const ProgramGrafcet& grafcet : program.grafcets)
        ordered.push_back(&grafcet);
    std::stable_sort(ordered.begin(), ordered.end(), [](const ProgramGrafcet* a, const ProgramGrafcet* b) {
        return std::pair(a->ownerMode, static_cast<int>(a->state)) < std::pair(b->ownerMode, static_cast<int>(b->state));
    });
    return ordered;
}

// Spec §6.1: the user variables with their defaults, the six PackTags, the
// <V>_PREV (initial value: V's). As the spec's example, a declaration has
// a comment only when its default could not be used.
std::vector<PlcVariable> globalsOf(const PackmlProgram& program, const std::vector<std::string>& declared)
{
    std::vector<PlcVariable> globals;
    for (std::size_t slot = 0; slot < program.variables.size(); ++slot) {
        const Variable& variable = program.variables[slot];
        std::string problem;
        std::string value = plcInitialValue(variable, problem);
        std::string note;
        if (declared[slot] != variable.name)
            note = "ERROR: '" + variable.name + "' cannot be declared as it is named; every condition that reads it is FALSE";
        if (!problem.empty())
            note += (note.empty() ? "" : ". ") + std::string("ERROR: default ") + problem + "; " + value
                    + " is used instead";
        globals.push_back({declared[slot], std::string(iecTypeName(variable.type)), value, note});
    }
    for (const std::string& name : program.edgeVariables) {
        const int slot = program.slotOf(name);
        std::string unused;
        globals.push_back({edgeMemoryName(name), "BOOL",
                           slot < 0 ? "FALSE" : plcInitialValue(program.variables[static_cast<std::size_t>(slot)], unused),
                           {}});
    }
    return globals;
}

} // namespace

PlcProject buildPackmlPlcProject(const Model& model, Dialect dialect)
{
    const PackmlProgram program = buildPackmlProgram(model);
    const std::vector<std::string> declared = declaredGlobalNames(program);
    PlcProject project = startPlcProject(model, dialect);
    project.globals = globalsOf(program, declared);
    for (State state : program.skeletons)
        project.pous.push_back(skeletonFunctionBlock(state));
    for (const ProgramGrafcet* grafcet : grafcetsInOrder(program))
        project.pous.push_back(grafcetFunctionBlock(program, *grafcet, declared, dialect));
    project.pous.push_back(buildPackmlProgramPou(program, declared, dialect));
    project.configurationName = "PackMLConfiguration";
    project.resourceName = "PackMLResource";
    project.taskName = "MainTask";
    project.programInstanceName = "PackMLInstance";
    return project;
}

} // namespace core::packml
