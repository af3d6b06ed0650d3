#include "modelfactory.h"

#include "core/checks/checks.h"

#include <catch2/catch.hpp>

namespace {

// One keystroke in the condition editor: change the condition, then
// re-parse and re-check the whole model, as the editor does.
void benchmarkConditionEdit(core::Model& model, const std::string& transitionId)
{
    const std::string original = model.transition(transitionId)->condition;
    bool toggle = false;
    BENCHMARK("set condition + re-check")
    {
        toggle = !toggle;
        (void)model.setCondition(transitionId, toggle ? original + " AND TRUE" : original);
        return core::checkModel(model).size();
    };
}

} // namespace

TEST_CASE("Re-check after a condition edit: realistic model (target <= 1 ms)", "[benchmark][checks]")
{
    core::Model model = factory::realisticModel();
    benchmarkConditionEdit(model, "F1->A2");
}

TEST_CASE("Re-check after a condition edit: stress model (target <= 10 ms)", "[benchmark][checks]")
{
    core::Model model = factory::stressModel();
    benchmarkConditionEdit(model, "F1->A2");
}
