// factory::verificationSeriesModel (modelfactory.h): issue 36's growing
// series for the verifier against SPIN.

#include "modelfactory.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace factory {

namespace {

void requireSeries(const core::Status& status)
{
    if (!status)
        throw std::logic_error("verification series model: " + status.message);
}

void declareBool(core::Model& model, const std::string& name, core::VariableKind kind)
{
    core::Variable variable{name, core::IecType::Bool, "", ""};
    variable.kind = kind;
    requireSeries(model.addVariable(variable));
}

// The steps that hold the nested GRAFCETs, in the order the series fills
// them: first the eight of the template that are not simple (F4, F6 and D3
// enclosing steps, the others macro-steps), then eight simple ones made
// macro-steps.
constexpr std::array<const char*, 16> kHosts{"F1", "F2", "F5", "F4", "F3", "F6", "D3", "A7",
                                             "A2", "A6", "A5", "A4", "A3", "D2", "D1", "A1"};
constexpr int kTemplateHosts = 8;

// The nested GRAFCET of `host`: a fork from its initial step (on Go) into three
// branches of `length` steps (each step after the first on its branch's
// input, In<b> and NOT In<b> in turn), a join that sets Complete and resets
// the GRAFCET's stored BOOLs, then a step that resets Complete and returns
// to the initial step when Ack falls. `stored[i]` is set on activation of
// the branch step i (branch-major), several per step when there are more.
void addSection(core::Model& model, const std::string& host, int length, const std::vector<std::string>& stored)
{
    const std::string prefix = host + "_";
    const int base = 1; // the initial step, and the first transition numbers
    for (const char* name : {"Go", "In0", "In1", "In2"})
        declareBool(model, prefix + name, core::VariableKind::Input);
    const std::string output = prefix + "Move";
    declareBool(model, output, core::VariableKind::Output);

    requireSeries(model.addGrafcetStep(host, {base, true, "", {}}));
    std::vector<int> firsts, lasts;
    const int branchSteps = 3 * length;
    for (int branch = 0; branch < 3; ++branch) {
        const std::string input = prefix + "In" + std::to_string(branch);
        for (int k = 0; k < length; ++k) {
            const int position = branch * length + k;
            const int number = base + 1 + position;
            std::vector<core::GrafcetAction> actions;
            for (std::size_t m = static_cast<std::size_t>(position); m < stored.size();
                 m += static_cast<std::size_t>(branchSteps))
                actions.push_back({core::ActionTiming::OnActivation, "S " + stored[m]});
            if (k == length - 1)
                actions.push_back({core::ActionTiming::Continuous, "N " + output + " IF " + prefix + "Go"});
            requireSeries(model.addGrafcetStep(host, {number, false, "", actions}));
            if (k == 0)
                firsts.push_back(number);
            else
                requireSeries(model.addGrafcetTransition(
                    host, {base + 50 + position, {number - 1}, {number}, (k % 2 ? "" : "NOT ") + input}));
            if (k == length - 1)
                lasts.push_back(number);
        }
    }
    const int join = base + 1 + branchSteps;
    std::vector<core::GrafcetAction> joinActions{{core::ActionTiming::OnActivation, "S Complete"}};
    for (const std::string& name : stored)
        joinActions.push_back({core::ActionTiming::OnActivation, "R " + name});
    requireSeries(model.addGrafcetStep(host, {join, false, "", joinActions}));
    requireSeries(model.addGrafcetStep(host, {join + 1, false, "", {{core::ActionTiming::OnActivation, "R Complete"}}}));
    requireSeries(model.addGrafcetTransition(host, {base, {base}, firsts, prefix + "Go"}));
    requireSeries(model.addGrafcetTransition(host, {base + 1, lasts, {join}, "TRUE"}));
    requireSeries(model.addGrafcetTransition(host, {base + 2, {join}, {join + 1}, host + "_Ack"}));
    requireSeries(model.addGrafcetTransition(host, {base + 3, {join + 1}, {base}, "NOT " + host + "_Ack"}));
}

} // namespace

core::Model verificationSeriesModel(int nestedGrafcets, int storedBools)
{
    if (nestedGrafcets < 1 || nestedGrafcets > static_cast<int>(kHosts.size()) || storedBools < 0)
        throw std::invalid_argument("verification series model: 1 to 16 nested GRAFCETs, stored BOOLs >= 0");
    core::Model model;
    requireSeries(model.setName("Verification series " + std::to_string(nestedGrafcets) + " x "
                                + std::to_string(storedBools)));
    for (const char* name : {"Start", "Stop", "EStop", "Fault", "Test", "Reset"})
        declareBool(model, name, core::VariableKind::Input);
    requireSeries(model.setInitialStep("A1"));
    // Every step reachable whatever the size (the GEMMA layer stays the same,
    // only the nested GRAFCETs grow): A1 -> F2 -> F1, from F1 to F5 -> F4 ->
    // A6, F3, F6, D3 -> A2, A3 -> A4, and the emergency stop F -> D1 -> A5 ->
    // A7 -> A4 -> F1, D1 -> D2 -> A5.
    const std::vector<std::pair<std::string, std::string>> conditions{
        {"A1->F2", "Start"},         {"F2->F1", "NOT Start"},         {"F1->A2", "Stop"},
        {"A2->A1", "TRUE"},          {"F1->F5", "Test AND NOT Fault"}, {"F5->F4", "NOT Test"},
        {"F4->A6", "Reset"},         {"A6->A1", "NOT Reset"},         {"F1->F3", "Fault AND NOT Test"},
        {"F3->A1", "Reset"},         {"F1->F6", "Fault AND Test"},    {"F6->F1", "NOT Fault"},
        {"F1->D3", "Reset AND Stop"}, {"D3->A2", "NOT Reset"},         {"F->D1", "EStop"},
        {"D1->A5", "NOT EStop"},     {"A5->A7", "Reset"},             {"A7->A4", "NOT Reset"},
        {"A4->F1", "Start"},         {"F1->A3", "Stop AND Test"},     {"A3->A4", "NOT Stop"},
        {"D1->D2", "Fault"},         {"D2->A5", "Reset"}};
    for (const auto& [id, condition] : conditions)
        requireSeries(model.setCondition(id, condition));
    for (const core::Transition& t : model.transitions()) {
        if (t.condition.empty())
            requireSeries(model.setTransitionHidden(t.id, true));
    }

    // GRAFCET g lives in host g; stored BOOL j belongs to GRAFCET j mod
    // nestedGrafcets.
    std::vector<std::vector<std::string>> stored(static_cast<std::size_t>(nestedGrafcets));
    for (int j = 0; j < storedBools; ++j) {
        const std::string name = "Mem" + std::to_string(j);
        declareBool(model, name, core::VariableKind::Internal);
        stored[static_cast<std::size_t>(j % nestedGrafcets)].push_back(name);
    }
    for (int h = 0; h < nestedGrafcets; ++h) {
        const std::string host = kHosts[static_cast<std::size_t>(h)];
        declareBool(model, host + "_Ack", core::VariableKind::Input);
        if (h >= kTemplateHosts)
            requireSeries(model.setStepType(host, core::StepType::Macro));
    }
    const int perSection = (storedBools + nestedGrafcets - 1) / nestedGrafcets;
    const int length = std::max(2, (perSection + 2) / 3);
    if (3 * length > 45)
        throw std::invalid_argument("verification series model: at most 45 stored BOOLs per nested GRAFCET");
    for (int g = 0; g < nestedGrafcets; ++g)
        addSection(model, kHosts[static_cast<std::size_t>(g)], length, stored[static_cast<std::size_t>(g)]);
    return model;
}

} // namespace factory
