// core/checks/incrementalcheck.h: after every edit of random sequences, on
// the nested stress model and on random models with random nested GRAFCETs,
// the incremental result is checkModel's, in its order.

#include "core/checks/checks.h"
#include "core/checks/incrementalcheck.h"
#include "core/model/model.h"
#include "modelfactory.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace test_incrementalcheck {

using namespace core;

namespace {

int drawBetween(std::mt19937& random, int low, int high)
{
    return std::uniform_int_distribution<int>(low, high)(random);
}

template <typename T>
const T& drawOne(std::mt19937& random, const std::vector<T>& items)
{
    return items[static_cast<std::size_t>(drawBetween(random, 0, static_cast<int>(items.size()) - 1))];
}

// What the model reports between two re-checks, as the editor's Document
// collects it.
class ChangeRecorder {
public:
    explicit ChangeRecorder(Model& model)
        : m_model(model)
        , m_handle(model.addObserver([this](const ModelChange& change) { changes.push_back(change); }))
    {
    }
    ~ChangeRecorder() { m_model.removeObserver(m_handle); }
    ChangeRecorder(const ChangeRecorder&) = delete;
    ChangeRecorder& operator=(const ChangeRecorder&) = delete;

    std::vector<ModelChange> changes;

private:
    Model& m_model;
    int m_handle;
};

std::vector<std::string> variableNames(const Model& model)
{
    std::vector<std::string> names;
    for (const Variable& v : model.variables())
        names.push_back(v.name);
    return names;
}

std::string variableOfType(std::mt19937& random, const Model& model, bool numeric)
{
    std::vector<std::string> names;
    for (const Variable& v : model.variables()) {
        if ((v.type != IecType::Bool) == numeric)
            names.push_back(v.name);
    }
    return names.empty() ? std::string(numeric ? "Count" : "In1") : drawOne(random, names);
}

// Mostly a BOOL variable whose edge memory's name is declared (GG420 when
// it is read under an edge).
std::string edgedVariable(std::mt19937& random, const Model& model)
{
    std::vector<std::string> names;
    for (const Variable& v : model.variables()) {
        if (v.type == IecType::Bool && model.variable(v.name + "_PREV") != nullptr)
            names.push_back(v.name);
    }
    return names.empty() || drawBetween(random, 0, 3) == 0 ? variableOfType(random, model, false)
                                                           : drawOne(random, names);
}

// A receptivity: valid ones (edges, durations, step activities, numeric
// comparisons, divisors that read variables, constants), syntax errors,
// undeclared names, type errors, and other variables' names alone.
std::string randomReceptivity(std::mt19937& random, const Model& model)
{
    const std::string b = variableOfType(random, model, false);
    const std::string c = variableOfType(random, model, false);
    const std::string n = variableOfType(random, model, true);
    const std::string x = std::to_string(drawBetween(random, 1, 12));
    switch (drawBetween(random, 0, 19)) {
    case 0: return b;
    case 1: return "NOT " + b + " AND " + c;
    case 2: return "RE " + edgedVariable(random, model);
    case 3: return "FE " + edgedVariable(random, model) + " OR X" + x;
    case 4: return b + " AND 200ms/X" + x;
    case 5: return n + " > " + x;
    case 6: return "100 / " + n + " > 2";
    case 7: return "TRUE";
    case 8: return "FALSE";
    case 9: return b + " OR NOT " + b;
    case 10: return b + " AND";         // syntax errors
    case 11: return "(" + b + " OR " + c;
    case 12: return "";
    case 13: return "Undeclared" + x;    // undeclared
    case 14: return b + " AND Ghost";
    case 15: return n;                    // type errors
    case 16: return b + " + 3";
    case 17: return drawOne(random, variableNames(model)); // another variable's name
    case 18: return "Complete AND " + b;
    default: return "RE " + b + " AND " + n + " = " + x;
    }
}

std::vector<std::string> grafcetKeys(const Model& model)
{
    std::vector<std::string> keys;
    for (const auto& [stepId, grafcet] : model.grafcets())
        keys.push_back(stepId);
    return keys;
}

// Mostly a receptivity edit; otherwise an edit the incremental checker must
// hand to the full check (steps, actions, variables, GEMMA conditions, the
// owner step, settings) or one it also handles (an upstream set).
void applyRandomEdit(std::mt19937& random, Model& model)
{
    const std::vector<std::string> keys = grafcetKeys(model);
    if (keys.empty())
        return;
    const std::string& key = drawOne(random, keys);
    const Grafcet& grafcet = *model.grafcet(key);
    const int kind = drawBetween(random, 0, 99);
    if (kind < 65) {
        if (grafcet.transitions().empty())
            return;
        const int number = drawOne(random, grafcet.transitions()).number;
        (void)model.setReceptivity(key, number, randomReceptivity(random, model));
        return;
    }
    const std::vector<std::string> names{"In0_PREV", "Extra", "In3", "Count", "Unused", "NestedIn0_PREV", "X2"};
    switch (kind % 12) {
    case 0: (void)model.addGrafcetStep(key, {grafcet.nextStepNumber(), false, "", {}}); break;
    case 1:
        if (!grafcet.steps().empty())
            (void)model.removeGrafcetStep(key, drawOne(random, grafcet.steps()).number);
        break;
    case 2: (void)model.addVariable({drawOne(random, names), IecType::Bool, "", ""}); break;
    case 3: (void)model.removeVariable(drawOne(random, variableNames(model))); break;
    case 4: {
        const Transition& t = drawOne(random, model.transitions());
        (void)model.setCondition(t.id, drawBetween(random, 0, 1) ? randomReceptivity(random, model) : "TRUE");
        break;
    }
    case 5:
        if (!grafcet.transitions().empty() && !grafcet.steps().empty())
            (void)model.setGrafcetUpstream(key, drawOne(random, grafcet.transitions()).number,
                                           {drawOne(random, grafcet.steps()).number});
        break;
    case 6:
        if (!grafcet.steps().empty())
            (void)model.addGrafcetAction(key, drawOne(random, grafcet.steps()).number,
                                         {ActionTiming::OnActivation, "S " + variableOfType(random, model, false)});
        break;
    case 7: (void)model.setStepHidden(key, drawBetween(random, 0, 3) == 0); break;
    case 8: (void)model.setStepType(key, drawBetween(random, 0, 1) ? StepType::Macro : StepType::Enclosing); break;
    case 9:
        model.setEvolutionRule(drawBetween(random, 0, 1) ? EvolutionRule::UntilStable
                                                         : EvolutionRule::OneEvolutionPerScan);
        break;
    case 10: (void)model.renameVariable(drawOne(random, variableNames(model)), drawOne(random, names)); break;
    default:
        if (!grafcet.transitions().empty() && !grafcet.steps().empty())
            (void)model.setGrafcetDownstream(key, drawOne(random, grafcet.transitions()).number,
                                             {drawOne(random, grafcet.steps()).number});
        break;
    }
}

// Runs `edits` random edits, sometimes two before one re-check; after each
// re-check the incremental result must be checkModel's. Returns how many
// re-checks were incremental.
int checkRandomEdits(Model& model, std::uint32_t seed, int edits)
{
    std::mt19937 random(seed);
    // Variables named like the edge memories of BOOL variables, so that a
    // receptivity reading one of those under an edge adds or removes GG420.
    for (int i = 0; i < 4; ++i)
        (void)model.addVariable({variableOfType(random, model, false) + "_PREV", IecType::Bool, "", ""});
    ChangeRecorder recorder(model);
    IncrementalCheck incremental;
    REQUIRE(incremental.checkAll(model) == checkModel(model));
    int incrementalCount = 0;
    for (int i = 0; i < edits; ++i) {
        recorder.changes.clear();
        applyRandomEdit(random, model);
        if (drawBetween(random, 0, 4) == 0)
            applyRandomEdit(random, model);
        const std::vector<Diagnostic> expected = checkModel(model);
        INFO("seed " << seed << ", edit " << i);
        REQUIRE(incremental.update(model, recorder.changes) == expected);
        incrementalCount += incremental.lastWasIncremental() ? 1 : 0;
    }
    return incrementalCount;
}

} // namespace

TEST_CASE("Incremental check: random edits of the nested stress model give checkModel's diagnostics",
          "[checks][incremental][nested]")
{
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        Model model = factory::nestedStressModel();
        const int edits = 60;
        const int incremental = checkRandomEdits(model, seed, edits);
        CHECK(incremental >= edits / 3); // most edits are receptivity edits, handled incrementally
    }
}

TEST_CASE("Incremental check: random edits of random nested models give checkModel's diagnostics",
          "[checks][incremental][nested]")
{
    int incremental = 0;
    for (std::uint32_t seed = 1; seed <= 25; ++seed) {
        Model model = samples::randomModel(seed);
        samples::addRandomNestedGrafcets(model, seed);
        if (seed % 2 == 0)
            model.setEvolutionRule(EvolutionRule::UntilStable);
        incremental += checkRandomEdits(model, seed * 31u, 40);
    }
    CHECK(incremental > 200);
}

TEST_CASE("Incremental check: a receptivity edit is incremental, anything else checks everything again",
          "[checks][incremental]")
{
    Model model = factory::nestedStressModel();
    ChangeRecorder recorder(model);
    IncrementalCheck incremental;
    incremental.checkAll(model);
    CHECK_FALSE(incremental.lastWasIncremental());

    // An undeclared name: GG403 on F2's transition; In4 no longer read there.
    REQUIRE(model.setReceptivity("F2", 3, "Ghost AND 200ms/X4"));
    const std::vector<Diagnostic>& after = incremental.update(model, recorder.changes);
    CHECK(incremental.lastWasIncremental());
    CHECK(after == checkModel(model));
    CHECK(std::any_of(after.begin(), after.end(), [](const Diagnostic& d) {
        return d.code == "GG403" && d.element == "F2" && d.nestedNumber == 3;
    }));

    // An edge on a variable named like an edge memory: GG420 comes and goes.
    recorder.changes.clear();
    REQUIRE(model.addVariable({"In9_PREV", IecType::Bool, "", ""}));
    incremental.update(model, recorder.changes);
    CHECK_FALSE(incremental.lastWasIncremental());
    recorder.changes.clear();
    REQUIRE(model.setReceptivity("A7", 2, "RE In9"));
    const std::vector<Diagnostic>& edged = incremental.update(model, recorder.changes);
    CHECK(incremental.lastWasIncremental());
    CHECK(edged == checkModel(model));
    CHECK(std::any_of(edged.begin(), edged.end(), [](const Diagnostic& d) {
        return d.code == "GG420" && d.element == "In9_PREV";
    }));

    // A GEMMA condition alone: incremental; its negation: the whole check.
    recorder.changes.clear();
    REQUIRE(model.setCondition("A1->F1", "In3 AND Ghost"));
    CHECK(incremental.update(model, recorder.changes) == checkModel(model));
    CHECK(incremental.lastWasIncremental());
    recorder.changes.clear();
    REQUIRE(model.setNegated("F1->A2", true));
    CHECK(incremental.update(model, recorder.changes) == checkModel(model));
    CHECK_FALSE(incremental.lastWasIncremental());

    // No change reported, another model: the whole check.
    CHECK(incremental.update(model, {}) == checkModel(model));
    CHECK_FALSE(incremental.lastWasIncremental());
    Model other = factory::nestedStressModel();
    recorder.changes.clear();
    REQUIRE(model.setReceptivity("F2", 3, "In4"));
    CHECK(incremental.update(other, recorder.changes) == checkModel(other));
    CHECK_FALSE(incremental.lastWasIncremental());
}

} // namespace test_incrementalcheck
