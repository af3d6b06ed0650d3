#include "core/verification/propertyevaluation.h"

#include "core/condition/conditionevaluator.h"
#include "core/simulation/simulator.h"

#include <algorithm>

namespace core {

bool propertyViolatedOn(const Model& model, const ParsedProperty& property, const Simulator& simulator)
{
    return propertyViolatedOn(model, property, simulator, 0);
}

bool propertyViolatedOn(const Model& model, const ParsedProperty& property, const Simulator& simulator,
                        std::int64_t faultScan)
{
    const cond::Expression& body = property.expression;
    const std::int64_t scan = simulator.scanCount();
    const cond::Value value = cond::evaluate(body, [&](int node) -> cond::Value {
        const cond::Node& n = body.at(node);
        if (isFaultedAtom(model, n)) {
            if (faultScan <= 0 || faultScan > scan)
                return false;
            if (n.kind == cond::NodeKind::Variable)
                return true;
            return scan - faultScan + 1 >= faultedScansFor(n.durationMs, simulator.cycleTimeMs());
        }
        switch (n.kind) {
        case cond::NodeKind::InStep: return simulator.activeStepId() == propertyStepId(model, n.text);
        case cond::NodeKind::NestedStepActivity: {
            const std::string id = propertyStepId(model, n.text);
            if (simulator.activeStepId() != id || simulator.entry())
                return false;
            const std::vector<int> active = simulator.activeNestedSteps(id);
            return std::find(active.begin(), active.end(), n.number) != active.end();
        }
        default: return simulator.variable(n.text);
        }
    });
    const bool holds = cond::isTrue(value);
    return property.kind == PropertyKind::Never ? holds : !holds;
}

} // namespace core
