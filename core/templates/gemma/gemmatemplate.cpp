#include "core/templates/gemma/gemmatemplate.h"

#include <array>

namespace core {

namespace {

constexpr std::array<TemplateState, 16> kStates{{
    {"A1", 1, Family::A, StepType::Simple, false, "Stop in initial state"},
    {"A2", 2, Family::A, StepType::Simple, false, "Stop requested at end of cycle"},
    {"A3", 3, Family::A, StepType::Simple, false, "Stop requested in a given state"},
    {"A4", 4, Family::A, StepType::Simple, false, "Stop obtained"},
    {"A5", 5, Family::A, StepType::Simple, false, "Preparation for restart after failure"},
    {"A6", 6, Family::A, StepType::Simple, true, "Operative part reset to initial state"},
    {"A7", 7, Family::A, StepType::Macro, false, "Operative part set to a given state"},
    {"F1", 8, Family::F, StepType::Macro, false, "Normal production"},
    {"F2", 9, Family::F, StepType::Macro, false, "Preparation run"},
    {"F3", 10, Family::F, StepType::Macro, false, "Closing run"},
    {"F4", 11, Family::F, StepType::Enclosing, false, "Verification run out of order"},
    {"F5", 12, Family::F, StepType::Macro, false, "Verification run in order"},
    {"F6", 13, Family::F, StepType::Enclosing, false, "Test run"},
    {"D1", 14, Family::D, StepType::Simple, false, "Emergency stop"},
    {"D2", 15, Family::D, StepType::Simple, false, "Diagnosis and/or failure handling"},
    {"D3", 16, Family::D, StepType::Enclosing, false, "Production despite failure"},
}};

constexpr std::array<TemplateTransition, 34> kTransitions{{
    {"F", "D1", 1, false},
    {"A1", "F4", 1, false}, {"A1", "F2", 2, false}, {"A1", "F1", 3, false}, {"A1", "F5", 4, false},
    {"A2", "A1", 1, false},
    {"A3", "A4", 1, false},
    {"A4", "F1", 1, false},
    {"A5", "A6", 1, false}, {"A5", "A7", 2, false},
    {"A6", "A1", 1, false},
    {"A7", "A4", 1, false},
    {"F1", "D1", 1, true}, {"F1", "D3", 2, false}, {"F1", "A2", 3, false}, {"F1", "F4", 4, false},
    {"F1", "F5", 5, false}, {"F1", "F3", 6, false}, {"F1", "A3", 7, false}, {"F1", "F6", 8, false},
    {"F1", "D2", 9, false},
    {"F2", "F1", 1, false},
    {"F3", "A1", 1, false},
    {"F4", "A6", 1, false},
    {"F5", "F4", 1, false}, {"F5", "F1", 2, false},
    {"F6", "D1", 1, false}, {"F6", "F1", 2, false},
    {"D1", "A5", 1, false}, {"D1", "D2", 2, false},
    {"D2", "A5", 1, false},
    {"D3", "A2", 1, false}, {"D3", "A3", 2, false}, {"D3", "D2", 3, false},
}};

} // namespace

std::string_view familyName(Family family)
{
    switch (family) {
    case Family::A: return "A";
    case Family::F: return "F";
    case Family::D: return "D";
    }
    return "?";
}

std::string_view stepTypeName(StepType type)
{
    switch (type) {
    case StepType::Simple: return "simple";
    case StepType::Macro: return "macro";
    case StepType::Enclosing: return "enclosing";
    }
    return "?";
}

bool parseStepType(std::string_view name, StepType& type)
{
    for (StepType candidate : {StepType::Simple, StepType::Macro, StepType::Enclosing}) {
        if (stepTypeName(candidate) == name) {
            type = candidate;
            return true;
        }
    }
    return false;
}

bool hasNestedBehaviour(StepType type)
{
    return type != StepType::Simple;
}

std::span<const TemplateState> templateStates()
{
    return kStates;
}

std::span<const TemplateTransition> templateTransitions()
{
    return kTransitions;
}

const TemplateState* findTemplateState(std::string_view id)
{
    for (const TemplateState& state : kStates) {
        if (state.id == id)
            return &state;
    }
    return nullptr;
}

std::string makeTransitionId(std::string_view source, std::string_view target)
{
    std::string id;
    id.reserve(source.size() + target.size() + 2);
    id.append(source).append("->").append(target);
    return id;
}

} // namespace core
