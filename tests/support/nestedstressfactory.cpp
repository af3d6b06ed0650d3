// The nested stress model of the benchmarks (issue #16) and of the tests of
// the incremental checks (issue #36).

#include "modelfactory.h"

#include "core/model/model.h"

#include <string>
#include <vector>

namespace factory {

using namespace core;

core::Model nestedStressModel()
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

} // namespace factory
