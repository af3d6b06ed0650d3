// Division by zero (issue #32): the checks, the generated code, the
// simulator and the verifier agree on what a division by zero does. A
// constant zero divisor is an error and the condition is FALSE everywhere;
// a divisor that reads a variable is a warning; an integer division by zero
// stops the simulation as it stops the PLC; a REAL one is IEEE 754.

#include <catch2/catch.hpp>

#include "core/checks/checks.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/codegen/stgenerator.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "core/verification/verification.h"
#include "samplemodels.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace test_divisionbyzero {

using namespace core;

namespace {

// A6 (initial) -> A1, every other step hidden; Count = 10, Batch = 0,
// Rate = 1.0, Speed = 0.0.
Model a6ToA1(const std::string& condition)
{
    Model model;
    for (const Step& step : std::vector<Step>(model.steps())) {
        if (step.id != "A6" && step.id != "A1")
            REQUIRE(model.setStepHidden(step.id, true));
    }
    REQUIRE(model.addVariable({"Count", IecType::Int, "10", ""}));
    REQUIRE(model.addVariable({"Batch", IecType::Int, "", ""}));
    REQUIRE(model.addVariable({"Rate", IecType::Real, "1.0", ""}));
    REQUIRE(model.addVariable({"Speed", IecType::Real, "", ""}));
    REQUIRE(model.setCondition("A6->A1", condition));
    return model;
}

std::vector<Diagnostic> withCode(const std::vector<Diagnostic>& diagnostics, const std::string& code)
{
    std::vector<Diagnostic> result;
    std::copy_if(diagnostics.begin(), diagnostics.end(), std::back_inserter(result),
                 [&](const Diagnostic& d) { return d.code == code; });
    return result;
}

std::string gemmaText(const Model& model)
{
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    REQUIRE(!project.pous.empty());
    return formatPou(project.pous.front(), Dialect::Iec);
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// F1 is the initial step, so scan 1 enters it and its GRAFCET evolves at once.
Model lampGrafcetFromF1()
{
    Model model = samples::lampGrafcetModel();
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.addVariable(samples::variable("Batch", IecType::Int, VariableKind::Input)));
    return model;
}

} // namespace

TEST_CASE("Division by zero: a constant zero divisor is an error with its place", "[division][checks]")
{
    const std::vector<std::string> conditions = {
        "Count / 0 > 1", "Count MOD 0 = 0", "Count / (2 - 2) > 1", "Rate / 0.0 > 1.0", "0.0 / 0.0 = 1.0",
    };
    for (const std::string& condition : conditions) {
        INFO(condition);
        const std::vector<Diagnostic> found = withCode(checkModel(a6ToA1(condition)), "GG215");
        REQUIRE(found.size() == 1);
        CHECK(found[0].severity == Severity::Error);
        CHECK(found[0].element == "A6->A1");
        CHECK(found[0].field == "condition");
        REQUIRE(found[0].span.has_value());
        CHECK(found[0].span->begin == 0);
        CHECK(withCode(checkModel(a6ToA1(condition)), "GG216").empty());
    }
    const Diagnostic d = withCode(checkModel(a6ToA1("Count / 0 > 1")), "GG215").front();
    CHECK(d.span->end == 9);
    CHECK(d.arguments == std::vector<std::string>{"A6->A1", "Count / 0", "0"});
    CHECK(d.message
          == "in the condition of A6->A1: 'Count / 0' divides by zero: on the PLC an integer division or MOD by zero "
             "stops the task with a fault and a REAL one gives INF or NaN");
}

TEST_CASE("Division by zero: a divisor that reads a variable is a warning", "[division][checks]")
{
    const std::vector<std::string> conditions = {"Count / Batch > 1", "Count MOD Batch = 1", "Rate / Speed > 1.0",
                                                 "Count > 100 / (Batch + 1)"};
    for (const std::string& condition : conditions) {
        INFO(condition);
        const std::vector<Diagnostic> diagnostics = checkModel(a6ToA1(condition));
        const std::vector<Diagnostic> found = withCode(diagnostics, "GG216");
        REQUIRE(found.size() == 1);
        CHECK(found[0].severity == Severity::Warning);
        CHECK(found[0].element == "A6->A1");
        CHECK(withCode(diagnostics, "GG215").empty());
    }
    const Diagnostic d = withCode(checkModel(a6ToA1("Count > 100 / (Batch + 1)")), "GG216").front();
    CHECK(d.arguments == std::vector<std::string>{"A6->A1", "100 / (Batch + 1)", "Batch + 1"});
    CHECK(d.span == Span{8, 25});
    // A constant divisor that is not zero is nothing to report.
    const std::vector<Diagnostic> fine = checkModel(a6ToA1("Count / 2 > 1 AND Rate / 2.5 < 1.0"));
    CHECK(withCode(fine, "GG215").empty());
    CHECK(withCode(fine, "GG216").empty());
}

TEST_CASE("Division by zero: a constant zero divisor generates FALSE with its error", "[division][codegen]")
{
    const std::string text = gemmaText(a6ToA1("Count MOD 0 = 0"));
    CHECK(contains(text, "(* ERROR GG215: in the condition of A6->A1: 'Count MOD 0' divides by zero"));
    CHECK(contains(text, "    IF FALSE THEN\n"));
    CHECK_FALSE(contains(text, "IF Count MOD 0"));
    // A variable divisor is the engineer's to guard: the code divides.
    CHECK(contains(gemmaText(a6ToA1("Count / Batch > 1")), "    IF Count / Batch > 1 THEN\n"));
}

TEST_CASE("Division by zero: the simulator agrees with the code on a constant zero divisor", "[division][simulation]")
{
    // The old simulator read Count MOD 0 as 0 and fired; the code never does.
    Simulator sim(a6ToA1("Count MOD 0 = 0"));
    sim.run(3);
    CHECK(sim.activeStepId() == "A6");
    CHECK_FALSE(sim.fault());
    CHECK(sim.scanCount() == 3);
}

TEST_CASE("Division by zero: an integer division by zero stops the simulation", "[division][simulation]")
{
    Simulator sim(a6ToA1("Count / Batch > 1"));
    REQUIRE(sim.setVariable("Batch", cond::Value{std::int64_t{2}}));
    sim.step(); // 10 / 2 > 1
    CHECK(sim.activeStepId() == "A1");
    CHECK_FALSE(sim.fault());

    sim.reset(); // Batch back to its default, 0
    // The condition divides by zero in scan 1.
    const ScanRecord record = sim.step();
    REQUIRE(sim.fault());
    const SimulationFault& fault = *sim.fault();
    CHECK(fault.scan == 1);
    CHECK(fault.stepId == "A6");
    CHECK(fault.transitionId == "A6->A1");
    CHECK(fault.division == "Count / Batch");
    CHECK(fault.text == "Count / Batch > 1");
    CHECK(toText(fault)
          == "scan 1: integer division by zero in the condition of A6->A1 (Count / Batch in 'Count / Batch > 1'): the "
             "PLC stops with a fault, and so does the simulation");
    CHECK(record.scan == 1);
    CHECK(record.fired.empty());
    // The task has stopped: no further scan runs.
    sim.step();
    sim.run(10);
    CHECK(sim.scanCount() == 1);
    CHECK(sim.activeStepId() == "A6");
    sim.reset();
    CHECK_FALSE(sim.fault());
}

TEST_CASE("Division by zero: MOD by zero stops the simulation too", "[division][simulation]")
{
    Simulator sim(a6ToA1("Count MOD Batch = 0"));
    sim.step();
    REQUIRE(sim.fault());
    CHECK(sim.fault()->division == "Count MOD Batch");
}

TEST_CASE("Division by zero: REAL division follows IEEE 754 and the run goes on", "[division][simulation]")
{
    CHECK(std::isinf(cond::realDivision(1.0, 0.0)));
    CHECK(cond::realDivision(1.0, 0.0) > 0);
    CHECK(cond::realDivision(-1.0, 0.0) < 0);
    CHECK(cond::realDivision(1.0, -0.0) < 0);
    CHECK(std::isnan(cond::realDivision(0.0, 0.0)));
    CHECK(cond::realDivision(3.0, 2.0) == 1.5);

    // 1.0 / 0.0 is +INF: the transition fires (the old simulator read 0.0).
    Simulator inf(a6ToA1("Rate / Speed > 1.0"));
    inf.step();
    CHECK_FALSE(inf.fault());
    CHECK(inf.activeStepId() == "A1");
    // 0.0 / 0.0 is NaN: = and < are FALSE, <> is TRUE.
    Simulator nanEqual(a6ToA1("Speed / Speed = Speed / Speed OR Speed / Speed < 1.0"));
    nanEqual.step();
    CHECK(nanEqual.activeStepId() == "A6");
    Simulator nanDiffers(a6ToA1("Speed / Speed <> 1.0"));
    nanDiffers.step();
    CHECK(nanDiffers.activeStepId() == "A1");
    CHECK_FALSE(nanDiffers.fault());
}

TEST_CASE("Division by zero: in a nested GRAFCET, a warning and a stopped run", "[division][nested]")
{
    Model model = lampGrafcetFromF1();
    REQUIRE(model.setReceptivity("F1", 1, "Count / Batch > 1"));
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    const std::vector<Diagnostic> found = withCode(diagnostics, "GG409");
    REQUIRE(found.size() == 1);
    CHECK(found[0].severity == Severity::Warning);
    CHECK(found[0].target == Diagnostic::Target::GrafcetTransition);
    CHECK(found[0].nestedNumber == 1);
    CHECK(found[0].span == Span{0, 13});
    CHECK(found[0].arguments == std::vector<std::string>{"F1", "the receptivity of T1 of F1", "Count / Batch", "Batch"});

    Simulator sim(model);
    sim.step(); // F1's entry scan: the evolving call reads T1
    REQUIRE(sim.fault());
    CHECK(sim.fault()->stepId == "F1");
    CHECK(sim.fault()->nestedTransition == 1);
    CHECK(toText(*sim.fault())
          == "scan 1: integer division by zero in the receptivity of T1 of F1 (Count / Batch in 'Count / Batch > 1'): "
             "the PLC stops with a fault, and so does the simulation");
    // A scenario run ends there and does not pass.
    const ScenarioRunResult run = runScenario(parseScenario("at 5: expect step F1\n", "s.txt").scenario, sim);
    CHECK(run.records.size() == 1);
    REQUIRE(run.fault);
    CHECK(run.fault->scan == 1);
    CHECK_FALSE(run.passed());
}

TEST_CASE("Division by zero: a nested action that divides by zero names the action", "[division][nested]")
{
    Model model = lampGrafcetFromF1();
    REQUIRE(model.setReceptivity("F1", 1, "TRUE"));
    REQUIRE(model.addGrafcetAction("F1", 2, {ActionTiming::OnActivation, "Count := Count MOD Batch"}));
    CHECK(withCode(checkModel(model), "GG409").size() == 1);
    Simulator sim(model);
    sim.step(); // 1 -> 2: step 2's on-activation actions run
    REQUIRE(sim.fault());
    CHECK(sim.fault()->nestedStep == 2);
    CHECK(sim.fault()->actionIndex == 2);
    CHECK(sim.fault()->place == "action 3 of step 2 of F1");
    CHECK(sim.fault()->division == "Count MOD Batch");

    // A constant zero divisor: the action is not generated and does nothing.
    Model constant = lampGrafcetFromF1();
    REQUIRE(constant.addGrafcetAction("F1", 2, {ActionTiming::OnActivation, "Count := Count / (1 - 1)"}));
    const GemmaProgram program = buildGemmaProgram(constant);
    const auto problem = std::find_if(program.problems.begin(), program.problems.end(),
                                      [](const ProgramProblem& p) { return p.code == "GG408"; });
    REQUIRE(problem != program.problems.end());
    CHECK(problem->nestedStep == 2);
    CHECK(problem->actionIndex == 2);
    CHECK_FALSE(program.step("F1")->nested->steps[1].onActivation.back().usable);
}

TEST_CASE("Division by zero: the verifier reads a division by a variable as a free BOOL", "[division][verification]")
{
    // Batch is a free input: 100 / Batch may be zero (a fault on the PLC),
    // and the values of Batch the verifier tried (its initial 0 only: no
    // comparison with a constant names it) made T1 look dead. With Batch = 11
    // the PLC fires T1.
    Model model = lampGrafcetFromF1();
    REQUIRE(model.setReceptivity("F1", 1, "Batch > 100 / Batch"));
    const VerificationResult result = verifyModel(model);
    for (const VerificationFinding& finding : result.findings) {
        INFO(finding.code << " " << verificationElementLabel(finding) << ": " << finding.message);
        CHECK(finding.code != verification::kNestedTransitionDead);
        CHECK(finding.code != verification::kNestedStepNeverActive);
    }
    CHECK(std::any_of(result.abstractions.begin(), result.abstractions.end(),
                      [](const std::string& a) { return a.find("Batch > 100 / Batch") != std::string::npos; }));
}

} // namespace test_divisionbyzero
