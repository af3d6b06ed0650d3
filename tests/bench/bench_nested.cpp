// The figures of issue #16 for the nested GRAFCET layer (README, Performance).

#include "core/checks/checks.h"
#include "core/checks/incrementalcheck.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"
#include "core/layout/grafcetlayout.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "modelfactory.h"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

namespace {

using namespace core;

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
    Model stress = factory::nestedStressModel();
    REQUIRE(stress.grafcets().size() == 6);
    REQUIRE(stress.grafcet("F1")->steps().size() == 40);
    int flip = 0;
    BENCHMARK("re-parse and re-check everything after one receptivity edit (stress model)")
    {
        stress.setReceptivity("F2", 3, (++flip % 2) ? "In4 AND 200ms/X4" : "In5 AND 200ms/X4");
        return checkModel(stress).size();
    };
    // The same edit as the editor re-checks it (editor/document.cpp): told
    // what the model reported, core/checks/incrementalcheck.h recomputes F2's
    // part and the model-wide checks that read every GRAFCET.
    IncrementalCheck incremental;
    incremental.checkAll(stress);
    std::vector<ModelChange> changes;
    const int observer = stress.addObserver([&](const ModelChange& change) { changes.push_back(change); });
    stress.setReceptivity("F2", 3, "In6 AND 200ms/X4");
    REQUIRE(incremental.update(stress, changes) == checkModel(stress));
    REQUIRE(incremental.lastWasIncremental());
    BENCHMARK("re-check after one receptivity edit, incremental (stress model)")
    {
        changes.clear();
        stress.setReceptivity("F2", 3, (++flip % 2) ? "In4 AND 200ms/X4" : "In5 AND 200ms/X4");
        return incremental.update(stress, changes).size();
    };
    stress.removeObserver(observer);
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
