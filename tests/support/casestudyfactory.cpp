// factory::caseStudyModel (modelfactory.h): issue 36's case-study-sized model.

#include "modelfactory.h"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace factory {

namespace {

void require(const core::Status& status)
{
    if (!status)
        throw std::logic_error("case-study model: " + status.message);
}

void declare(core::Model& model, const std::string& name, core::IecType type, core::VariableKind kind)
{
    core::Variable variable{name, type, "", ""};
    variable.kind = kind;
    require(model.addVariable(variable));
}

// The paper's GEMMA conditions; here Alarm is stored by F1's GRAFCET.
constexpr std::array<CaseStudyCondition, 34> kConditions = {{
    {"F->D1", "NOT EmergencyInterrupter"},
    {"A1->F4", "Manual OR StationTest"},
    {"A1->F2", "Start AND NOT Ready"},
    {"A1->F1", "Start AND Ready AND Automatic"},
    {"A1->F5", "Semiautomatic"},
    {"A2->A1", "CycleEnd"},
    {"A3->A4", "CycleEnd"},
    {"A4->F1", "Start"},
    {"A5->A6", "Reset AND NOT Alarm"},
    {"A5->A7", "Reset AND Alarm"},
    {"A6->A1", "Ready"},
    {"A7->A4", "Ready"},
    {"F1->D1", "Alarm"},
    {"F1->D3", "ManualCapping"},
    {"F1->A2", "NOT Stop"},
    {"F1->F4", "Manual OR StationTest"},
    {"F1->F5", "Semiautomatic"},
    {"F1->F3", "EmptyMachine"},
    {"F1->A3", "Stop AND PieceCount >= 100"},
    {"F1->F6", "StationTest AND Manual"},
    {"F1->D2", "Pressure > 6.5"},
    {"F2->F1", "Ready"},
    {"F3->A1", "CycleEnd"},
    {"F4->A6", "NOT Manual AND NOT StationTest"},
    {"F5->F4", "Manual"},
    {"F5->F1", "Automatic"},
    {"F6->D1", "Alarm"},
    {"F6->F1", "Automatic"},
    {"D1->A5", "EmergencyInterrupter"},
    {"D1->D2", "EmergencyInterrupter AND Alarm"},
    {"D2->A5", "Reset"},
    {"D3->A2", "Stop"},
    {"D3->A3", "NOT ManualCapping"},
    {"D3->D2", "Alarm"},
}};

core::GrafcetAction continuous(const std::string& text)
{
    return {core::ActionTiming::Continuous, text};
}

core::GrafcetAction onActivation(const std::string& text)
{
    return {core::ActionTiming::OnActivation, text};
}

// One phase of a station: its step's actions and the receptivity that ends it.
struct Phase {
    std::vector<core::GrafcetAction> actions;
    std::string until;
};

// A station: its phases in turn, then a step that waits for the other stations.
using Station = std::vector<Phase>;

// 1 --start--> three stations side by side --TRUE--> the join step
// (`joinActions`) --leave--> 1: a parallel section, its join waiting for the
// three stations' last steps. Steps are numbered from 2 in station order.
void addThreeStations(core::Model& model, const std::string& stepId, const std::string& start,
                      const std::array<Station, 3>& stations, std::vector<core::GrafcetAction> joinActions,
                      const std::string& leave)
{
    require(model.addGrafcetStep(stepId, {1, true, "", {}}));
    std::vector<int> firsts, lasts;
    int number = 2;
    int transition = 10;
    std::vector<core::GrafcetTransition> phaseEnds;
    for (const Station& station : stations) {
        firsts.push_back(number);
        for (const Phase& phase : station) {
            require(model.addGrafcetStep(stepId, {number, false, "", phase.actions}));
            phaseEnds.push_back({transition++, {number}, {number + 1}, phase.until});
            ++number;
        }
        require(model.addGrafcetStep(stepId, {number, false, "", {}}));
        lasts.push_back(number++);
    }
    for (core::GrafcetTransition& end : phaseEnds)
        require(model.addGrafcetTransition(stepId, std::move(end)));
    require(model.addGrafcetStep(stepId, {number, false, "", std::move(joinActions)}));
    require(model.addGrafcetTransition(stepId, {1, {1}, firsts, start}));
    require(model.addGrafcetTransition(stepId, {2, lasts, {number}, "TRUE"}));
    require(model.addGrafcetTransition(stepId, {3, {number}, {1}, leave}));
}

void addVariables(core::Model& model)
{
    using core::IecType;
    using core::VariableKind;
    // 12 operator and mode inputs of the paper, 10 station sensors.
    for (const char* name : {"EmergencyInterrupter", "ManualCapping", "Stop", "Manual", "StationTest",
                             "Semiautomatic", "EmptyMachine", "Start", "Ready", "Automatic", "CycleEnd", "Reset",
                             "BottleIn", "Full", "CapIn", "Capped", "Ejected", "CP1", "CP2", "CP3", "CapDone", "Jog"})
        declare(model, name, IecType::Bool, VariableKind::Input);
    require(model.setVariableDefault("EmergencyInterrupter", "TRUE"));
    declare(model, "PieceCount", IecType::Int, VariableKind::Input);
    declare(model, "Pressure", IecType::Real, VariableKind::Input);
    for (const char* name : {"Conveyor", "FillValve", "CapFeeder", "CapScrew", "Ejector", "RinseValve", "DrainValve",
                             "TestLamp", "StationFill", "StationCap", "HandCapLamp", "SemiLamp", "AlarmLamp",
                             "ReadyLamp"})
        declare(model, name, IecType::Bool, VariableKind::Output);
    for (const char* name : {"Alarm", "Filled", "CapTight", "BottleOut", "BatchRunning"})
        declare(model, name, IecType::Bool, VariableKind::Internal);
}

// F1, normal production: fill, cap and eject one bottle at each station
// (a bottle's arrival read as an edge, the filled level and the screwing
// given time to settle),
// each station's progress stored (Filled, CapTight, BottleOut: left as they
// are when the GEMMA layer leaves F1 in mid-cycle); the three checkpoints
// decide the stored Alarm as the bottles leave.
void addProduction(core::Model& model)
{
    // Steps: 1; filling 2-3 (4 waits); capping 5-7 (8 waits); ejecting 9-10 (11 waits); join 12.
    addThreeStations(model, "F1", "RE BottleIn",
                     {{{{{continuous("FillValve")}, "Full"}, {{onActivation("S Filled")}, "CP1 AND 1s/X3"}},
                       {{{continuous("CapFeeder")}, "CapIn"},
                        {{continuous("CapScrew IF CapIn")}, "Capped AND 500ms/X6"},
                        {{onActivation("S CapTight")}, "CP2"}},
                       {{{continuous("Ejector")}, "Ejected"}, {{onActivation("S BottleOut")}, "NOT Ejected AND CP3"}}}},
                     {onActivation("Alarm := NOT (CP1 AND CP2 AND CP3)"), onActivation("S Complete"),
                      onActivation("R Filled"), onActivation("R CapTight"), onActivation("R BottleOut"),
                      continuous("Conveyor"), continuous("AlarmLamp IF Alarm")},
                     "NOT BottleIn");
    require(model.addGrafcetAction("F1", 1, onActivation("R Complete")));
    require(model.addGrafcetAction("F1", 1, onActivation("S BatchRunning")));
}

// F2, preparation run: rinse, drain, ready.
void addPreparation(core::Model& model)
{
    const std::string id = "F2";
    require(model.addGrafcetStep(id, {1, true, "", {onActivation("R Complete")}}));
    require(model.addGrafcetStep(id, {2, false, "", {onActivation("R Alarm"), continuous("RinseValve")}}));
    require(model.addGrafcetStep(id, {3, false, "", {continuous("DrainValve")}}));
    require(model.addGrafcetStep(id, {4, false, "", {onActivation("S Complete"), continuous("ReadyLamp")}}));
    require(model.addGrafcetTransition(id, {1, {1}, {2}, "Start"}));
    require(model.addGrafcetTransition(id, {2, {2}, {3}, "Full"}));
    require(model.addGrafcetTransition(id, {3, {3}, {4}, "NOT Full"}));
    require(model.addGrafcetTransition(id, {4, {4}, {1}, "NOT Start"}));
}

// F4, manual and station test: Manual and StationTest may both hold, so both
// branches of the selection start, and step 4 may be entered again from the
// other one while active.
void addManualTest(core::Model& model)
{
    const std::string id = "F4";
    require(model.addGrafcetStep(id, {1, true, "", {}}));
    require(model.addGrafcetStep(id, {2, false, "", {continuous("StationFill IF Jog")}}));
    require(model.addGrafcetStep(id, {3, false, "", {continuous("TestLamp")}}));
    require(model.addGrafcetStep(id, {4, false, "", {continuous("StationCap")}}));
    require(model.addGrafcetTransition(id, {1, {1}, {2}, "Manual"}));
    require(model.addGrafcetTransition(id, {2, {1}, {3}, "StationTest"}));
    require(model.addGrafcetTransition(id, {3, {2}, {4}, "Jog"}));
    require(model.addGrafcetTransition(id, {4, {3}, {4}, "CP1"}));
    require(model.addGrafcetTransition(id, {5, {4}, {1}, "NOT Jog AND NOT CP1"}));
}

} // namespace

std::span<const CaseStudyCondition> caseStudyConditions()
{
    return kConditions;
}

core::Model caseStudyModel()
{
    core::Model model;
    require(model.setName("Filling and capping machine"));
    addVariables(model);
    require(model.setStepType("A7", core::StepType::Simple));
    require(model.setStepType("D2", core::StepType::Simple));
    require(model.setStepHidden("F6", true));
    for (const CaseStudyCondition& row : kConditions)
        require(model.setCondition(row.transition, row.condition));
    require(model.setTokens("F1->A2", {"Stop"}));
    require(model.setTokens("F1->F3", {"EmptyMachine"}));
    addProduction(model);
    addPreparation(model);
    // F3, closing run: empty the three stations, clearing what they stored.
    addThreeStations(model, "F3", "TRUE",
                     {{{{{continuous("DrainValve"), onActivation("R Filled")}, "NOT Full"}},
                       {{{continuous("Conveyor"), onActivation("R CapTight")}, "NOT BottleIn"}},
                       {{{continuous("Ejector"), onActivation("R BottleOut")}, "Ejected"}}}},
                     {onActivation("S Complete"), onActivation("R BatchRunning")}, "NOT EmptyMachine");
    require(model.addGrafcetAction("F3", 1, onActivation("R Complete")));
    addManualTest(model);
    // F5, one semi-automatic cycle on request.
    addThreeStations(model, "F5", "Start",
                     {{{{{continuous("FillValve")}, "Full"}},
                       {{{continuous("CapFeeder")}, "CapIn"}, {{continuous("CapScrew")}, "Capped"}},
                       {{{continuous("Ejector")}, "Ejected"}}}},
                     {onActivation("S Complete"), continuous("SemiLamp")}, "NOT Start");
    require(model.addGrafcetAction("F5", 1, onActivation("R Complete")));
    // D3, capping by hand while the filler goes on.
    addThreeStations(model, "D3", "TRUE",
                     {{{{{continuous("FillValve"), onActivation("S Filled")}, "Full"}},
                       {{{continuous("HandCapLamp")}, "CapDone"}, {{onActivation("S CapTight")}, "NOT CapDone"}},
                       {{{continuous("Ejector")}, "Ejected"}}}},
                     {continuous("Conveyor"), onActivation("R Filled"), onActivation("R CapTight")}, "NOT BottleIn");
    return model;
}

} // namespace factory
