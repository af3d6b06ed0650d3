#pragma once

// The ways the inputs of a PackML program may go in one scan, as the
// verifier explores them (docs/packml.md, "Verification"). Inputs are free at
// every scan; to keep the exploration small without losing any behaviour
// the ways are grouped:
// - an input read by nothing but one command or request condition (and by no
//   GRAFCET, property or edge) is *private* to it: only the condition's value
//   matters. Such a condition gets a rising edge only where its event can act
//   (the command is accepted in the state by some mode, the mode may be
//   granted there), at most one command event and one mode event per scan;
//   otherwise it is kept FALSE (TRUE only when its private inputs cannot make
//   it FALSE). An edge left out is simulated by one kept: the higher-priority
//   event alone leads to the same state, and a memory left FALSE allows every
//   edge a memory TRUE would (docs/packml.md gives the argument);
// - every other input the scan reads is enumerated: BOOL both values, a
//   number the values around the constants the model compares it with (not
//   exhaustive: an abstraction the result names);
// - CntrlCmd takes the number of each command the state accepts with a
//   rising edge of CmdChangeRequest, UnitMode each mode that may be granted
//   there with one of UnitModeChangeRequest (the other values of spec §8's
//   0..10 and "one other mode" do what no request does).

#include "core/condition/conditionevaluator.h"
#include "core/templates/packml/packmlprogram.h"

#include <array>
#include <map>
#include <cstddef>
#include <string>
#include <vector>

namespace core::packml {

class PackmlSimulator;

struct InputValue {
    int slot = -1;
    cond::Value value;
};
using InputChoice = std::vector<InputValue>; // the values set before the scan, by slot

class InputChoices {
public:
    // `alwaysRead`: more variables read at the end of every scan (the
    // engineer's properties), by name.
    InputChoices(const PackmlProgram& program, const std::vector<std::string>& alwaysRead);

    // At most kMaxChoices; `truncated` (when given) is set when there were more.
    std::vector<InputChoice> choices(const PackmlSimulator& simulator, bool* truncated = nullptr) const;
    static constexpr std::size_t kMaxChoices = 4096;

    // What makes the enumeration less than every value (English), empty when exact.
    const std::vector<std::string>& abstractions() const { return m_abstractions; }

    // What the Promela export (packmlpromela.h) needs to choose the inputs
    // as these choices do: whether a command's condition (by
    // PackmlProgram::commands index) or a mode's request (by
    // PackmlProgram::modes index) is collapsed to its value, and the values
    // enumerated for an input (empty for CntrlCmd and UnitMode).
    bool commandCollapsed(std::size_t command) const { return m_commands[command].collapsible; }
    bool requestCollapsed(std::size_t modeIndex) const;
    const std::vector<cond::Value>& values(int slot) const { return m_values[static_cast<std::size_t>(slot)]; }

private:
    struct Condition {
        const ProgramCondition* condition = nullptr;
        std::vector<int> nodeSlots;    // by expression node, -1 for others
        std::vector<int> inputs;       // input slots it reads, each once
        bool collapsible = false;      // every input private to it, all BOOL
        Command command = Command::Reset; // commands: which
        int modeIndex = -1;            // requests: index into program.modes
    };
    struct Assignments {
        bool canBeTrue = false, canBeFalse = false;
        InputChoice whenTrue, whenFalse;
    };

    // What one GRAFCET's parts read: the inputs a call can read depend on
    // its situation (the transitions enabled and the steps they lead to).
    struct GrafcetReads {
        bool untilStable = false;
        std::vector<int> all;
        std::vector<int> initialSteps;
        std::map<int, std::vector<int>> step;         // by step number: its actions
        std::vector<std::vector<int>> transitions;    // by NestedGrafcet::transitions index
    };

    void classify(const std::vector<std::string>& alwaysRead);
    GrafcetReads grafcetReads(const NestedGrafcet& grafcet) const;
    void addInstanceReads(const PackmlSimulator& simulator, int mode, std::vector<int>& into) const;
    void noteReads(const cond::Expression& expression, std::vector<int>& into) const;
    Assignments assignments(const Condition& condition, const PackmlSimulator& simulator) const;

    const PackmlProgram& m_program;
    std::vector<Condition> m_commands; // PackmlProgram::commands order
    std::vector<Condition> m_requests; // generated requests only
    std::vector<int> m_alwaysEnumerated; // shared inputs read at every scan
    std::array<std::vector<int>, kStateCount + 1> m_grafcetReads{}; // by state: inputs its instances read
    std::vector<GrafcetReads> m_reads; // by PackmlProgram::grafcets index
    std::array<std::vector<Command>, kStateCount + 1> m_accepted{};  // by state, some mode
    std::array<std::vector<int>, kStateCount + 1> m_grantable{};     // by state: mode indexes some grant reaches
    std::vector<std::vector<cond::Value>> m_values; // by slot: the values enumerated for a number
    int m_cntrlCmd = -1, m_cmdChangeRequest = -1, m_unitMode = -1, m_unitModeChangeRequest = -1;
    std::vector<std::string> m_abstractions;
};

} // namespace core::packml
