#pragma once

#include <span>
#include <string>
#include <string_view>

namespace core {

enum class Family { A, F, D };
enum class StepType { Simple, Macro, Enclosing };

std::string_view familyName(Family family);         // "A", "F", "D"
std::string_view stepTypeName(StepType type);       // "simple", "macro", "enclosing"
bool parseStepType(std::string_view name, StepType& type);
bool hasNestedBehaviour(StepType type);             // macro or enclosing

// One of the 16 GEMMA states of the fixed template (spec §2).
struct TemplateState {
    std::string_view id;          // "A1" ... "D3"
    int number;                   // value of State in generated code, 1..16
    Family family;
    StepType defaultType;
    bool defaultInitial;
    std::string_view englishName; // official GEMMA name, used in generated comments
};

// One of the 34 transitions of the template. The family transition has
// source kFamilySource ("F"): it leaves the F family frame.
struct TemplateTransition {
    std::string_view source;
    std::string_view target;
    int defaultPriority;          // 1 = evaluated first among the source's transitions
    bool defaultNegated;
};

inline constexpr std::string_view kFamilySource = "F";

std::span<const TemplateState> templateStates();          // in state-number order
std::span<const TemplateTransition> templateTransitions(); // grouped by source, by priority
const TemplateState* findTemplateState(std::string_view id);

// "A1->F4", "F->D1".
std::string makeTransitionId(std::string_view source, std::string_view target);

} // namespace core
