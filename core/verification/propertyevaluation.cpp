#include "core/verification/propertyevaluation.h"

#include "core/condition/conditionevaluator.h"
#include "core/simulation/simulator.h"

#include <algorithm>

namespace core {

bool propertyViolatedOn(const Model& model, const ParsedProperty& property, const Simulator& simulator)
{
    const cond::Expression& body = property.expression;
    const cond::Value value = cond::evaluate(body, [&](int node) -> cond::Value {
        const cond::Node& n = body.at(node);
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
