#include "packmlcapper.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlprogram.h"
#include "packmlfactory.h"
#include "packmlsamples.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_packmlprogram {

using namespace core;
using namespace core::packml;

namespace {

std::vector<std::string> commandNames(const PackmlProgram& program)
{
    std::vector<std::string> names;
    for (const ProgramCommand& command : program.commands)
        names.push_back(command.name);
    return names;
}

// "Idle:Abort->Aborted(Aborting skipped)" for each transition of a state.
std::vector<std::string> transitionsOf(const ProgramMode& mode, State state)
{
    std::vector<std::string> result;
    const ProgramState* programState = mode.state(state);
    REQUIRE(programState != nullptr);
    for (const ModeTransition& t : programState->transitions) {
        std::string text(stateName(state));
        text += ":";
        text += t.transition.trigger == Trigger::StateComplete ? std::string("SC")
                                                               : std::string(commandName(t.transition.command));
        text += "->" + std::string(stateName(t.destination.state));
        if (t.destination.skipped)
            text += "(" + std::string(stateName(*t.destination.skipped)) + " skipped)";
        result.push_back(text);
    }
    return result;
}

} // namespace

TEST_CASE("The Capper's program: commands, modes, transitions, grants and instances of spec §6.6", "[packml-program]")
{
    const auto model = packmltests::loadCapper();
    const PackmlProgram program = buildPackmlProgram(*model);
    CHECK(program.problems.empty());
    CHECK(program.programName == "Capper");
    // Suspend and Unsuspend are accepted nowhere: not generated (PM013).
    CHECK(commandNames(program) == std::vector<std::string>{"Reset", "Start", "Stop", "Hold", "Unhold", "Abort", "Clear"});
    for (const ProgramCommand& command : program.commands)
        CHECK(command.condition.usable);

    REQUIRE(program.modes.size() == 2);
    const ProgramMode& production = program.modes[0];
    const ProgramMode& manual = program.modes[1];
    CHECK(production.name == "Production");
    CHECK(manual.name == "Manual");
    CHECK(production.enabled
          == StateSet{State::Stopped, State::Resetting, State::Idle, State::Execute, State::Held, State::Aborted});
    CHECK(transitionsOf(production, State::Execute)
          == std::vector<std::string>{"Execute:Abort->Aborted(Aborting skipped)", "Execute:Stop->Stopped(Stopping skipped)",
                                      "Execute:Hold->Held(Holding skipped)"});
    CHECK(transitionsOf(production, State::Resetting)
          == std::vector<std::string>{"Resetting:Abort->Aborted(Aborting skipped)",
                                      "Resetting:Stop->Stopped(Stopping skipped)", "Resetting:SC->Idle"});
    CHECK(transitionsOf(production, State::Held)
          == std::vector<std::string>{"Held:Abort->Aborted(Aborting skipped)", "Held:Stop->Stopped(Stopping skipped)",
                                      "Held:Unhold->Execute(Unholding skipped)"});
    CHECK(transitionsOf(manual, State::Stopped)
          == std::vector<std::string>{"Stopped:Abort->Aborted(Aborting skipped)", "Stopped:Reset->Idle(Resetting skipped)"});
    CHECK(transitionsOf(manual, State::Aborted)
          == std::vector<std::string>{"Aborted:Clear->Stopped(Clearing skipped)"});

    // Mode changes in Stopped, Idle and Aborted both ways; both requests generated.
    REQUIRE(production.grants.size() == 1);
    CHECK(production.grants[0].targetMode == 3);
    CHECK(production.grants[0].states == StateSet{State::Stopped, State::Idle, State::Aborted});
    REQUIRE(manual.grants.size() == 1);
    CHECK(manual.grants[0].targetMode == 1);
    CHECK(production.requestGenerated);
    CHECK(manual.requestGenerated);
    CHECK(production.request.usable);

    // Instances: Production's Resetting and Execute run their GRAFCETs,
    // Manual's Execute the skeleton; no other state holds an FB there.
    std::vector<std::string> instances;
    for (const ProgramInstance& instance : program.instances)
        instances.push_back(instance.name + ":" + instance.typeName);
    CHECK(instances
          == std::vector<std::string>{"Production_Execute:Production_Execute_FB",
                                      "Production_Resetting:Production_Resetting_FB", "Manual_Execute:Execute_FB"});
    CHECK(program.skeletons == std::vector<State>{State::Execute});
    REQUIRE(program.grafcets.size() == 2);
    CHECK(program.grafcets[1].grafcet.writesComplete);
    CHECK_FALSE(program.grafcets[0].grafcet.writesComplete);
    CHECK(program.mode(1)->state(State::Stopped)->instance == -1);

    // The PackTags follow the user variables, in slot order.
    CHECK(program.slotOf("cntrlcmd") == static_cast<int>(model->variables().size()));
    CHECK(program.slotOf("UnitModeCurrent") == static_cast<int>(model->variables().size()) + 5);
}

TEST_CASE("PackML program: 'same as' shares one built GRAFCET, a broken one falls back to the skeleton",
          "[packml-program]")
{
    Model model = newModel();
    REQUIRE(model.setGrafcetChoice(1, State::Starting, GrafcetChoice::own()));
    REQUIRE(model.setGrafcetChoice(3, State::Starting, GrafcetChoice::sameAs(1)));
    REQUIRE(model.setGrafcetChoice(2, State::Starting, GrafcetChoice::sameAs(3))); // no chains (PM015)
    const PackmlProgram program = buildPackmlProgram(model);
    REQUIRE(program.grafcets.size() == 1);
    CHECK(program.instance(1, State::Starting)->typeName == "Production_Starting_FB");
    CHECK(program.instance(3, State::Starting)->typeName == "Production_Starting_FB");
    CHECK(program.instance(3, State::Starting)->ownerMode == 1);
    CHECK(program.instance(2, State::Starting)->isSkeleton());
    CHECK(program.instance(2, State::Starting)->typeName == "Starting_FB");
    // Every acting state and Execute of every mode has an instance: 3 modes × 11.
    CHECK(program.instances.size() == 33);
    CHECK(program.instance(1, State::Idle) == nullptr);
}

TEST_CASE("PackML program: conditions that cannot be used are FALSE, with the reason", "[packml-program]")
{
    Model model = newModel();
    REQUIRE(model.setCommandCondition(Command::Start, "Cmd_Start AND"));
    REQUIRE(model.setCommandCondition(Command::Stop, "Speed"));
    REQUIRE(model.setCommandCondition(Command::Hold, ""));
    REQUIRE(model.setModeRequest(3, "UnitModeChangeRequest AND UnitMode = 3"));
    REQUIRE(model.setName("State")); // a generated name: the program keeps "PackML"
    const PackmlProgram program = buildPackmlProgram(model);
    CHECK(program.programName == "PackML");
    CHECK_FALSE(program.command(Command::Start)->condition.usable);
    CHECK_FALSE(program.command(Command::Stop)->condition.usable);
    CHECK_FALSE(program.command(Command::Hold)->condition.usable); // empty: FALSE, and GG202 says to write it
    CHECK(program.command(Command::Reset)->condition.usable);
    // The PackTags are the program's own globals: a request may read them.
    CHECK(program.mode(3)->request.usable);
    std::vector<std::string> problems;
    for (const ProgramProblem& problem : program.problems)
        problems.push_back(problem.code + "@" + problem.element);
    CHECK(problems == std::vector<std::string>{"GG201@Start", "GG203@Stop", "GG202@Hold"});
}

TEST_CASE("PackML program: a user variable with a reserved name makes what reads it unusable", "[packml-program]")
{
    Model model = newModel();
    Variable clash;
    clash.name = "CntrlCmd";
    REQUIRE(model.addVariable(clash));
    REQUIRE(model.setCommandCondition(Command::Start, "CntrlCmd"));
    const PackmlProgram program = buildPackmlProgram(model);
    CHECK_FALSE(program.command(Command::Start)->condition.usable);
    REQUIRE_FALSE(program.problems.empty());
    CHECK(program.problems.front().code == "PM018");
}

TEST_CASE("The shipped PackML example builds without a problem, with the instances it documents", "[packml-program]")
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");
    REQUIRE(loaded.ok());
    const PackmlProgram program = buildPackmlProgram(*loaded.model);
    for (const ProgramProblem& problem : program.problems)
        FAIL_CHECK(problem.code << ": " << problem.message);
    CHECK(program.programName == "BottleFiller");
    std::vector<std::string> withGrafcet;
    for (const ProgramInstance& instance : program.instances)
        if (!instance.isSkeleton())
            withGrafcet.push_back(instance.name + ":" + instance.typeName);
    CHECK(withGrafcet
          == std::vector<std::string>{"Production_Starting:Production_Starting_FB",
                                      "Production_Execute:Production_Execute_FB",
                                      "Production_Stopping:Production_Stopping_FB",
                                      "Production_Aborting:Production_Aborting_FB",
                                      "Production_Resetting:Production_Resetting_FB", "Manual_Execute:Manual_Execute_FB",
                                      "Manual_Stopping:Production_Stopping_FB", "Manual_Aborting:Production_Aborting_FB"});
    // Every command of the edition is accepted somewhere; Suspend and
    // Unsuspend come from the infeed's photo-eye.
    CHECK(commandNames(program).size() == 9);
    CHECK(program.edgeVariables == std::vector<std::string>{"BottleIn"});
}

TEST_CASE("The PackML stress model: 31 modes sharing Production's eleven 40-step GRAFCETs", "[packml-program]")
{
    const Model model = factory::packmlStressModel();
    CHECK(model.invariantViolations().empty());
    const PackmlProgram program = buildPackmlProgram(model);
    for (const ProgramProblem& problem : program.problems)
        FAIL_CHECK(problem.code << ": " << problem.message);
    CHECK(program.modes.size() == 31);
    CHECK(program.instances.size() == 31 * 11);
    REQUIRE(program.grafcets.size() == 11);
    for (const ProgramGrafcet& grafcet : program.grafcets)
        CHECK(grafcet.grafcet.steps.size() == 40);
    CHECK(program.instance(31, State::Execute)->typeName == "Production_Execute_FB");
    CHECK(program.mode(31)->requestGenerated);
    CHECK(program.mode(1)->grants.size() == 30);
}

TEST_CASE("Random PackML models: programs without problems, covering what the agreement test needs",
          "[packml-program]")
{
    int editions2022 = 0, userModes = 0, shared = 0, grafcets = 0, skipped = 0, emptyCommands = 0;
    for (std::uint32_t seed = 0; seed < 40; ++seed) {
        const Model model = samples::randomPackmlModel(seed);
        CHECK(model.invariantViolations().empty());
        const PackmlProgram program = buildPackmlProgram(model);
        REQUIRE(program.problems.empty());
        editions2022 += program.options.edition == Edition::Y2022 ? 1 : 0;
        userModes += program.modes.back().number >= kFirstUserMode ? 1 : 0;
        grafcets += static_cast<int>(program.grafcets.size());
        for (const ProgramInstance& instance : program.instances)
            shared += !instance.isSkeleton() && instance.ownerMode != instance.mode ? 1 : 0;
        for (const ProgramMode& mode : program.modes)
            for (const ProgramState& state : mode.states)
                for (const ModeTransition& t : state.transitions)
                    skipped += t.destination.skipped ? 1 : 0;
        for (const ProgramCommand& command : program.commands)
            emptyCommands += command.condition.text == "FALSE" ? 1 : 0;
        CHECK(samples::randomPackmlModel(seed).sameContent(model)); // reproducible
    }
    CHECK(editions2022 > 5);
    CHECK(userModes > 5);
    CHECK(shared > 5);
    CHECK(grafcets > 40);
    CHECK(skipped > 40);
    CHECK(emptyCommands > 5);
}

} // namespace test_packmlprogram
