// Soundness of the verifier's numeric comparisons (docs/verification.md,
// "Both layers" and "Conditions"): a transition it calls dead, or a property
// it says holds, must be so for every value of the inputs' types. Each case
// is a condition that some input values make TRUE (checked by brute force
// with the condition evaluator and by the simulator); the verifier may then
// claim neither a dead GEMMA transition (GV102), a dead nested transition
// (GV111), a step never active (GV110) nor that `never in A1` holds.

#include "samplemodels.h"

#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace test_numericsoundness {

using namespace core;

namespace {

namespace code = core::verification;

// The inputs every case reads: P and Q are INT, R is REAL (nestedMachine has
// BOOL inputs A, B and C).
void addInputs(Model& model)
{
    REQUIRE(model.addVariable(samples::variable("P", IecType::Int, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Q", IecType::Int, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("R", IecType::Real, VariableKind::Input)));
}

// A6 (initial) --condition--> A1, every other step hidden.
Model gemmaTransitionModel(const std::string& condition)
{
    Model model;
    for (const Step& step : std::vector<Step>(model.steps())) {
        if (step.id != "A6" && step.id != "A1")
            REQUIRE(model.setStepHidden(step.id, true));
    }
    addInputs(model);
    REQUIRE(model.setCondition("A6->A1", condition));
    return model;
}

// F1 (initial macro-step) runs 1 --condition--> 2.
Model nestedReceptivityModel(const std::string& condition)
{
    Model model = samples::nestedMachine();
    addInputs(model);
    REQUIRE(model.setInitialStep("F1"));
    samples::addMachineStep(model, 1, true);
    samples::addMachineStep(model, 2, false);
    samples::addMachineTransition(model, 1, {1}, {2}, condition);
    return model;
}

struct Inputs {
    std::int64_t a = 0;
    std::int64_t b = 0;
    double r = 0.0;
};

// The condition's value for these inputs; nullopt when it divides an
// integer by zero (the PLC faults there, the transition never fires).
std::optional<bool> evaluateWith(const cond::Expression& expression, const Inputs& inputs)
{
    int divisionByZero = -1;
    const cond::Value value = cond::evaluate(
        expression,
        [&](int node) -> cond::Value {
            const std::string& name = expression.at(node).text;
            if (name == "P")
                return inputs.a;
            if (name == "Q")
                return inputs.b;
            return inputs.r;
        },
        divisionByZero);
    if (divisionByZero >= 0)
        return std::nullopt;
    return cond::isTrue(value);
}

// Input values that make the condition TRUE, by brute force over small
// values and the ends of INT's range; nullopt when none does (which proves
// nothing: the search is not over every value).
std::optional<Inputs> satisfyingInputs(const std::string& condition)
{
    const cond::ParseResult parsed = cond::parse(condition);
    REQUIRE(parsed.ok());
    std::vector<std::int64_t> integers;
    for (std::int64_t i = -60; i <= 60; ++i)
        integers.push_back(i);
    for (std::int64_t i : {-32768, -32767, -1000, 1000, 32766, 32767})
        integers.push_back(i);
    const std::vector<double> reals{0.0, -1.5, 1.5, -1000.0, 1000.0};
    for (std::int64_t a : integers) {
        for (std::int64_t b : integers) {
            for (double r : reals) {
                const Inputs inputs{a, b, r};
                if (evaluateWith(parsed.expression, inputs).value_or(false))
                    return inputs;
            }
        }
    }
    return std::nullopt;
}

void setInputs(Simulator& simulator, const Inputs& inputs)
{
    REQUIRE(simulator.setVariable("P", inputs.a).ok);
    REQUIRE(simulator.setVariable("Q", inputs.b).ok);
    REQUIRE(simulator.setVariable("R", inputs.r).ok);
}

bool hasFinding(const VerificationResult& result, const std::string& findingCode, const std::string& element)
{
    return std::any_of(result.findings.begin(), result.findings.end(), [&](const VerificationFinding& finding) {
        return finding.code == findingCode && !finding.elements.empty() && finding.elements.front() == element;
    });
}

VerificationResult verifyWithProperty(const Model& model, const std::string& property)
{
    VerificationOptions options;
    options.properties = {property};
    return verifyModel(model, options);
}

// The verifier's claims about a condition that `inputs` make TRUE: none may
// say it never fires.
void checkNoNeverClaim(const std::string& condition, const Inputs& inputs)
{
    INFO("condition: " << condition << " (TRUE for P = " << inputs.a << ", Q = " << inputs.b << ", R = " << inputs.r
                       << ")");
    const Model gemma = gemmaTransitionModel(condition);
    const VerificationResult gemmaResult = verifyWithProperty(gemma, "never in A1");
    CHECK_FALSE(hasFinding(gemmaResult, code::kDeadTransition, "A6->A1"));
    REQUIRE(gemmaResult.propertyVerdicts.size() == 1);
    CHECK(gemmaResult.propertyVerdicts[0].outcome != PropertyOutcome::Holds);

    const Model nested = nestedReceptivityModel(condition);
    const VerificationResult nestedResult = verifyModel(nested);
    CHECK_FALSE(hasFinding(nestedResult, code::kNestedTransitionDead, "F1/T1"));
    CHECK_FALSE(hasFinding(nestedResult, code::kNestedStepNeverActive, "F1/2"));
}

} // namespace

TEST_CASE("Numeric soundness: the simulator fires what the cases claim", "[numericsoundness]")
{
    // The ground truth of the cases below, on the simulator itself.
    const std::vector<std::pair<std::string, Inputs>> cases = {
        {"P > P * 2", {-1, 0, 0.0}},     {"P > 100 - P", {51, 0, 0.0}}, {"P < P / 2", {-2, 0, 0.0}},
        {"P = P * P", {1, 0, 0.0}},      {"R > R * 2.0", {0, 0, -1.5}}, {"P MOD 7 = 3", {10, 0, 0.0}},
        {"P / 2 = 3", {7, 0, 0.0}},      {"P > 10 AND P < P * P - 200", {20, 0, 0.0}},
    };
    for (const auto& [condition, inputs] : cases) {
        INFO(condition);
        Simulator gemma(gemmaTransitionModel(condition));
        setInputs(gemma, inputs);
        gemma.step();
        CHECK(gemma.activeStepId() == "A1");

        Simulator nested(nestedReceptivityModel(condition));
        setInputs(nested, inputs);
        nested.run(2);
        CHECK(nested.activeNestedSteps("F1") == std::vector<int>{2});
    }
}

TEST_CASE("Numeric soundness: a comparison with its variable on both sides is not decided on sample values",
          "[numericsoundness]")
{
    // The explorer decided `P > P * 2` on P's sample values (its default 0
    // only, since no comparison with a constant names P): never TRUE, so it
    // claimed the transition dead and `never in A1` proved; P = -1 fires it.
    for (const std::string condition :
         {"P > P * 2", "P > 100 - P", "P < P / 2", "P = P * P", "R > R * 2.0", "P > 10 AND P < P * P - 200"}) {
        const std::optional<Inputs> inputs = satisfyingInputs(condition);
        REQUIRE(inputs);
        checkNoNeverClaim(condition, *inputs);
    }
}

TEST_CASE("Numeric soundness: arithmetic on a variable against a constant is never claimed dead",
          "[numericsoundness]")
{
    for (const std::string condition : {"P MOD 7 = 3", "P / 2 = 3", "P - Q > 0 AND P * 2 > 7", "P * P > 1000",
                                        "R * 2.0 > 5.0 AND P > 3", "P * 3 > 100 AND P < 40"}) {
        const std::optional<Inputs> inputs = satisfyingInputs(condition);
        REQUIRE(inputs);
        checkNoNeverClaim(condition, *inputs);
    }
}

namespace {

// A random comparison over P and Q with small constants, +, -, *, / and MOD.
std::string randomOperand(std::mt19937& random, int depth)
{
    std::uniform_int_distribution<int> pick(0, depth > 0 ? 6 : 2);
    std::uniform_int_distribution<int> constant(-20, 20);
    switch (pick(random)) {
    case 0: return "P";
    case 1: return "Q";
    case 2: {
        const int c = constant(random);
        return c < 0 ? "(" + std::to_string(c) + ")" : std::to_string(c);
    }
    default: {
        static const char* const operators[] = {" + ", " - ", " * ", " / ", " MOD "};
        std::uniform_int_distribution<int> op(0, 4);
        return "(" + randomOperand(random, depth - 1) + operators[op(random)] + randomOperand(random, depth - 1) + ")";
    }
    }
}

std::string randomComparison(std::mt19937& random)
{
    static const char* const relations[] = {" < ", " > ", " <= ", " >= ", " = ", " <> "};
    std::uniform_int_distribution<int> relation(0, 5);
    return randomOperand(random, 2) + relations[relation(random)] + randomOperand(random, 2);
}

} // namespace

TEST_CASE("Numeric soundness: random conditions TRUE for some inputs are never claimed dead", "[numericsoundness]")
{
    std::mt19937 random(20261206);
    int satisfiable = 0;
    for (int i = 0; i < 120; ++i) {
        std::string condition = randomComparison(random);
        if (random() % 3 == 0)
            condition += (random() % 2 ? " AND " : " OR ") + randomComparison(random);
        const std::optional<Inputs> inputs = satisfyingInputs(condition);
        if (!inputs)
            continue; // nothing to contradict: the verifier may say either
        ++satisfiable;
        checkNoNeverClaim(condition, *inputs);
    }
    CHECK(satisfiable > 40);
}

TEST_CASE("Numeric soundness: a REAL the actions write may be infinite or NaN", "[numericsoundness]")
{
    // Step 2 stores R * 1.0E30 in the REAL X: beyond REAL's range the PLC
    // (and the simulator, which stores a REAL as a float) keeps an infinity;
    // R / R with R = 0.0 is NaN, which is neither below nor above 1.0.
    Model model = samples::nestedMachine();
    addInputs(model);
    REQUIRE(model.addVariable(samples::variable("X", IecType::Real, VariableKind::Internal)));
    REQUIRE(model.addVariable(samples::variable("Y", IecType::Real, VariableKind::Internal)));
    REQUIRE(model.setInitialStep("F1"));
    samples::addMachineStep(model, 1, true);
    samples::addMachineStep(model, 2, false,
                            {{ActionTiming::OnActivation, "X := R * 1.0E30"}, {ActionTiming::OnActivation, "Y := R / R"}});
    samples::addMachineTransition(model, 1, {1}, {2}, "A");

    Simulator simulator(model);
    REQUIRE(simulator.setVariable("A", true).ok);
    REQUIRE(simulator.setVariable("R", -1.0E10).ok);
    simulator.run(2);
    REQUIRE(simulator.activeNestedSteps("F1") == std::vector<int>{2});
    CHECK(simulator.variable("X") == cond::Value{-std::numeric_limits<double>::infinity()});
    simulator.reset();
    REQUIRE(simulator.setVariable("A", true).ok);
    REQUIRE(simulator.setVariable("R", 0.0).ok);
    simulator.run(2);
    REQUIRE(std::holds_alternative<double>(simulator.variable("Y")));
    CHECK(std::isnan(std::get<double>(simulator.variable("Y"))));

    VerificationOptions options;
    options.properties = {"never X < -3.5E38", "never X > 3.5E38", "never NOT (Y < 1.0) AND NOT (Y >= 1.0)"};
    const VerificationResult result = verifyModel(model, options);
    REQUIRE(result.propertyVerdicts.size() == 3);
    for (const PropertyVerdict& verdict : result.propertyVerdicts)
        CHECK(verdict.outcome != PropertyOutcome::Holds);
}

TEST_CASE("Numeric soundness: a GEMMA transition on an infinite REAL is not dead", "[numericsoundness]")
{
    // F1's step 2 stores -INF in X (R = -1.0E10) and sets Complete; F1 -> A2
    // (waiting for Complete) reads X < -3.5E38, beyond REAL's finite values.
    Model model = samples::nestedMachine();
    addInputs(model);
    REQUIRE(model.addVariable(samples::variable("X", IecType::Real, VariableKind::Internal)));
    samples::addMachineStep(model, 1, true);
    samples::addMachineStep(model, 2, false,
                            {{ActionTiming::OnActivation, "X := R * 1.0E30"}, {ActionTiming::OnActivation, "S Complete"}});
    samples::addMachineTransition(model, 1, {1}, {2}, "A");
    REQUIRE(model.setCondition("F1->A2", "X < -3.5E38"));

    Simulator simulator(model);
    REQUIRE(simulator.setVariable("Start", true).ok);
    REQUIRE(simulator.setVariable("A", true).ok);
    REQUIRE(simulator.setVariable("R", -1.0E10).ok);
    simulator.run(2); // A1 -> F1, then F1 enters step 2 and F1 -> A2 fires
    CHECK(simulator.activeStepId() == "A2");

    const VerificationResult result = verifyModel(model);
    CHECK_FALSE(hasFinding(result, code::kDeadTransition, "F1->A2"));
    CHECK_FALSE(hasFinding(result, code::kUnreachableStep, "A2"));
}

} // namespace test_numericsoundness
