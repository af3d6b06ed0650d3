// The figures of issue #16 for the nested GRAFCET layer (README, Performance).

#include "core/checks/checks.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"
#include "core/layout/grafcetlayout.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

namespace {

using namespace core;

// Six nested GRAFCETs of 40 steps: a sequence of blocks, each a three-way
// parallel section of three steps per branch, with a timer on every branch,
// and a loop back to the initial step.
Model stressModel()
{
    Model model;
    for (int i = 0; i < 20; ++i) {
        Variable input{"In" + std::to_string(i), IecType::Bool, "", "input " + std::to_string(i)};
        model.addVariable(input);
        Variable output{"Out" + std::to_string(i), IecType::Bool, "", "output " + std::to_string(i)};
        output.kind = VariableKind::Output;
        model.addVariable(output);
    }
    Variable count{"Count", IecType::Int, "", "cycles"};
    count.kind = VariableKind::Internal;
    model.addVariable(count);
    int outputIndex = 0;
    for (const char* stepId : {"F1", "F2", "F3", "F5", "A7", "F4"}) {
        model.setStepHidden(stepId, false);
        int transition = 1;
        model.addGrafcetStep(stepId, {1, true, "", {{ActionTiming::OnActivation, "Count := Count + 1"}}});
        int previous = 1;
        int next = 2;
        while (next + 9 <= 40) {
            std::vector<int> heads{next, next + 3, next + 6};
            for (int branch = 0; branch < 3; ++branch) {
                for (int k = 0; k < 3; ++k) {
                    const std::string out = "Out" + std::to_string(outputIndex++ % 20);
                    model.addGrafcetStep(stepId, {next + branch * 3 + k, false, "", {{ActionTiming::Continuous, "N " + out}}});
                }
                for (int k = 0; k < 2; ++k) {
                    const int from = next + branch * 3 + k;
                    model.addGrafcetTransition(stepId, {transition++, {from}, {from + 1},
                                                        "In" + std::to_string((from + k) % 20) + " AND 200ms/X"
                                                            + std::to_string(from)});
                }
            }
            model.addGrafcetTransition(stepId, {transition++, {previous}, heads, "RE In0 OR In1"});
            previous = next + 9;
            model.addGrafcetStep(stepId, {previous, false, "", {}});
            model.addGrafcetTransition(stepId, {transition++, {next + 2, next + 5, next + 8}, {previous}, "In2"});
            next = previous + 1;
        }
        for (int step = next; step < 40; ++step) { // a sequence to the 40th step
            model.addGrafcetStep(stepId, {step, false, "", {{ActionTiming::Continuous, "Out" + std::to_string(step % 20)}}});
            model.addGrafcetTransition(stepId, {transition++, {previous}, {step}, "In" + std::to_string(step % 20)});
            previous = step;
        }
        model.addGrafcetStep(stepId, {40, false, "", {{ActionTiming::Continuous, "Complete"}}});
        model.addGrafcetTransition(stepId, {transition++, {previous}, {40}, "In3"});
        model.addGrafcetTransition(stepId, {transition++, {40}, {1}, "NOT In3"});
    }
    return model;
}

// A GRAFCET of 200 steps: from the initial step, blocks of a three-way
// selection (a sequence of two steps, a parallel section of two sequences
// of two steps, one step) converging on a step, then a loop (a step that
// goes back or on), and a sequence to the 200th step, which loops back to 1.
Grafcet layoutStressGrafcet()
{
    Grafcet g;
    int transition = 1;
    const auto step = [&](int number, bool conditional = false) {
        GrafcetStep s{number, number == 1, "", {}};
        s.actions.push_back({ActionTiming::Continuous, "N Out" + std::to_string(number % 20)
                                                           + (conditional ? " IF In" + std::to_string(number % 7) : "")});
        if (number % 3 == 0)
            s.actions.push_back({ActionTiming::OnActivation, "Count := Count + " + std::to_string(number)});
        g.addStep(std::move(s));
        return number;
    };
    const auto link = [&](std::vector<int> up, std::vector<int> down) {
        g.addTransition({transition, std::move(up), std::move(down),
                         "In" + std::to_string(transition % 20) + " AND NOT In" + std::to_string((transition + 3) % 20)});
        ++transition;
    };
    int at = step(1);
    int next = 2;
    while (next + 9 <= 200) {
        const int a1 = step(next++), a2 = step(next++);
        const int b1 = step(next++), b2 = step(next++), c1 = step(next++, true), c2 = step(next++);
        const int d1 = step(next++);
        const int join = step(next++, true);
        const int body = step(next++);
        const int after = step(next++);
        link({at}, {a1});
        link({a1}, {a2});
        link({a2}, {join});
        link({at}, {b1, c1});
        link({b1}, {b2});
        link({c1}, {c2});
        link({b2, c2}, {join});
        link({at}, {d1});
        link({d1}, {join});
        link({join}, {body});
        link({body}, {join});
        link({body}, {after});
        at = after;
    }
    while (next <= 200) {
        const int s = step(next++);
        link({at}, {s});
        at = s;
    }
    link({at}, {1});
    return g;
}

} // namespace

TEST_CASE("Nested GRAFCETs: the layout of a 200-step GRAFCET", "[benchmark][nested][layout]")
{
    const Grafcet grafcet = layoutStressGrafcet();
    REQUIRE(grafcet.steps().size() == 200);
    const TextMeasure measure = [](std::string_view text) { return 7.0 * static_cast<double>(text.size()); };
    const GrafcetLayout layout = layoutGrafcet(grafcet, measure);
    REQUIRE(layout.links.size() > 200);
    for (const GrafcetTransitionLayout& t : layout.transitions)
        REQUIRE_FALSE(t.detached); // the structure is found: every block drawn as a block
    BENCHMARK("layout of a 200-step GRAFCET")
    {
        return layoutGrafcet(grafcet, measure).links.size();
    };
}

TEST_CASE("Nested GRAFCETs: the stress model and the shipped example", "[benchmark][nested]")
{
    Model stress = stressModel();
    REQUIRE(stress.grafcets().size() == 6);
    REQUIRE(stress.grafcet("F1")->steps().size() == 40);
    int flip = 0;
    BENCHMARK("re-parse and re-check everything after one receptivity edit (stress model)")
    {
        stress.setReceptivity("F2", 3, (++flip % 2) ? "In4 AND 200ms/X4" : "In5 AND 200ms/X4");
        return checkModel(stress).size();
    };
    BENCHMARK("Structured Text of the whole program (stress model)")
    {
        const PlcProject project = buildPlcProject(stress, Dialect::Iec);
        return formatSingleFileIec(project).size();
    };
    const std::string text = saveNativeJson(stress);
    BENCHMARK("load + save (stress model)")
    {
        const auto loaded = loadNativeJson(text, "stress.json");
        return saveNativeJson(*std::get<std::unique_ptr<Model>>(loaded)).size();
    };

    const auto example = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(example.model);
    Simulator simulator(*example.model);
    std::mt19937 random(16);
    std::vector<std::size_t> inputs;
    for (std::size_t i = 0; i < simulator.variableNames().size(); ++i) {
        if (simulator.variableKind(i) == VariableKind::Input && simulator.variableType(i) == IecType::Bool)
            inputs.push_back(i);
    }
    BENCHMARK("simulation: 100000 scans of the drilling-cell example, one input change per scan")
    {
        for (int scan = 0; scan < 100'000; ++scan) {
            simulator.setVariableAt(inputs[random() % inputs.size()], random() % 2 == 0);
            simulator.run(1);
        }
        return simulator.activeStepNumber();
    };
}
