// The figures of issue #16 for the nested GRAFCET layer (README, Performance).

#include "core/checks/checks.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"
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

} // namespace

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
