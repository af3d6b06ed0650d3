#pragma once

// Runs a PackML model scan by scan exactly as its generated PROGRAM does
// (spec packml.md §6.5), from the one reading of its semantics,
// buildPackmlProgram (packmlprogram.h): the generated commands and requests,
// per mode the enabled states with their transitions, the grants S(c,r) and
// the instances <Mode>_<State>. Each instance that runs a GRAFCET has its own
// NestedEngine, even when several share one GRAFCET type; the others run as
// their skeleton (an acting state completes at once, Execute never).
//
// One scan (scan()):
//  1. every generated command condition goes through its R_TRIG; Ev_C is its
//     edge OR (edge of CmdChangeRequest AND CntrlCmd = C);
//  2. the mode manager, on the state at the start of the scan: the first
//     grantable request in mode order sets Mode, Entry := TRUE, Resume := FALSE;
//  3. the branch of State in the new Mode: the instance's entry block and call
//     (no Initialization call when Execute resumes), then the first transition
//     whose event or SC holds fires;
//  4. each continuous output := the output of the instance of (Mode, State)
//     when Entry is FALSE, else FALSE;
//  5. StateCurrent, UnitModeCurrent; 6. the <V>_PREV memories.
// Scans are numbered from 1; simulated time is scanCount() x the cycle time.
// Copies are independent (they share the immutable program).

#include "core/condition/conditionevaluator.h"
#include "core/model/status.h"
#include "core/simulation/nestedengine.h"
#include "core/simulation/simulationfault.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlscanrecord.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core::packml {

class PackmlSimulator {
public:
    // Builds the program of a PackML model; keeps no reference to the model.
    explicit PackmlSimulator(const Model& model);
    // Runs `program` instead of the model's own (the verifier's tests run
    // deliberately wrong programs to show that its checks see them); the
    // model gives the cycle time and the mode-change lists of drop reasons.
    PackmlSimulator(const Model& model, PackmlProgram program);

    // Spec §6.5's start: initial state and mode, Entry TRUE, Resume FALSE,
    // every R_TRIG memory FALSE, variables at their defaults, scan count 0.
    void reset();
    PackmlScanRecord scan();

    // Inputs only: the user's input variables and the four PackTags inputs.
    // A value must be of the variable's type and range; otherwise nothing
    // changes and the Status says why.
    Status setInput(std::string_view name, const cond::Value& value);
    Status setInputText(std::string_view name, std::string_view text); // "TRUE", "9"
    Status setInput(int slot, const cond::Value& value); // by PackmlProgram::variables slot

    // The integer division or MOD by zero that stopped the run, as the PLC's
    // task stops on it (nullopt while running): in a command or request
    // condition the scan stops there; in an instance's GRAFCET, after its
    // call (which went on with 0), before the transitions. After it scan()
    // runs nothing (its record repeats the state); reset() clears it.
    const std::optional<SimulationFault>& fault() const { return m_fault; }

    State state() const { return m_state; }
    int mode() const { return m_mode; }
    bool entry() const { return m_entry; }
    bool resume() const { return m_resume; }
    std::int64_t scanCount() const { return m_scanCount; }
    // The R_TRIG memories (what the last scan's CLK was), for the verifier:
    // by PackmlProgram::commands index, by PackmlProgram::modes index.
    bool commandMemory(std::size_t command) const { return m_commandMemory[command] != 0; }
    bool requestMemory(std::size_t modeIndex) const { return m_requestMemory[modeIndex] != 0; }
    bool cmdChangeMemory() const { return m_cmdChangeMemory; }
    bool modeChangeMemory() const { return m_modeChangeMemory; }
    // <V>_PREV of an edge variable by slot.
    bool previous(int slot) const { return m_previous[static_cast<std::size_t>(slot)] != 0; }
    std::int64_t simulatedTimeMs() const;

    // Variables by slot (PackmlProgram::variables order) or name (ignoring case).
    int slotOf(std::string_view name) const { return program().slotOf(name); }
    cond::Value value(int slot) const { return m_values[static_cast<std::size_t>(slot)]; }
    std::optional<cond::Value> value(std::string_view name) const;

    // The instances (PackmlProgram::instances): the engine of one running a
    // GRAFCET (nullptr for a skeleton) and the Complete its last call gave.
    const NestedEngine* engine(int instance) const;
    bool complete(int instance) const { return m_complete[static_cast<std::size_t>(instance)] != 0; }

    // A simulation aid the generated code does not have (spec §4, as GEMMA's
    // manual Complete): the Complete of an instance without GRAFCET comes
    // from the user, written by its body in every call (so also in the
    // call after Initialization), instead of its skeleton's. nullopt: the
    // skeleton again. Fails for an instance that runs a GRAFCET (its
    // GRAFCET writes Complete) or an index out of range. Kept by reset().
    Status setManualComplete(int instance, std::optional<bool> complete);
    std::optional<bool> manualComplete(int instance) const;

    const PackmlProgram& program() const;

    // The verifier's hook (NestedEngine::setTimerOracle) on every instance's
    // engine: nullptr runs the TONs on the simulated time again.
    void setTimerOracle(TimerOracle* oracle);

private:
    struct Compiled;
    struct Events;

    Events commandEvents();
    void runModeManager(PackmlScanRecord& record);
    bool grantable(int requestedMode) const;
    DroppedEvent refusedRequest(std::size_t modeIndex, const ProgramMode* granted) const;
    std::string modeName(int number) const;
    void runStateMachine(const Events& events, PackmlScanRecord& record);
    bool callInstance(int instance, PackmlScanRecord& record);
    void callFunctionBlock(int instance, bool initialization);
    void fire(const ModeTransition& transition);
    void dropCommands(const Events& events, const ProgramState* programState, bool complete,
                      const ModeTransition* fired, PackmlScanRecord& record) const;
    void writeOutputs();
    // FALSE and a fault at `place` on an integer division by zero.
    bool evaluate(const ProgramCondition& condition, const std::vector<int>& nodeSlots, const std::string& place);
    bool instanceFaulted(int instance);

    std::shared_ptr<const Compiled> m_compiled;
    std::vector<cond::Value> m_values; // by slot
    std::vector<char> m_previous;      // <V>_PREV by slot
    State m_state = State::Stopped;
    int m_mode = 1;
    bool m_entry = true;
    bool m_resume = false;
    std::int64_t m_scanCount = 0;
    std::optional<SimulationFault> m_fault;
    bool m_cmdChangeMemory = false;
    bool m_modeChangeMemory = false;
    std::vector<char> m_commandMemory; // by PackmlProgram::commands index
    std::vector<char> m_requestMemory; // by PackmlProgram::modes index
    std::vector<std::optional<NestedEngine>> m_engines; // by instance
    std::vector<char> m_complete;                       // by instance
    std::vector<std::optional<bool>> m_manualComplete;  // by instance
};

} // namespace core::packml
