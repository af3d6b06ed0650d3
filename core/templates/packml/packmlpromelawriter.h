#pragma once

// Writes the Promela model of packmlpromela.h: the PackML layer
// (packmlpromela.cpp) and the calls of the instances' GRAFCETs
// (packmlpromelainstance.cpp).

#include "core/templates/packml/packmlinputchoices.h"
#include "core/templates/packml/packmlpromela.h"
#include "core/templates/packml/packmlpromelatext.h"
#include "core/templates/packml/packmlscanchecks.h"

#include <array>

namespace core::packml::promela {

class Writer {
public:
    Writer(const Model& model, const PackmlProgram& program);
    PackmlPromela run();

private:
    // The PackML layer (packmlpromela.cpp; the inputs: packmlpromelainputs.cpp).
    void writeHeader();
    void writeDeclarations();
    void writeProcess();
    void writeInputs();
    void writeCommandEvent();
    void writeModeEvent();
    void writeCommands();
    void writeModeManager();
    void writeStateMachine();
    void writeBranch(const ProgramState& state);
    void writeFire(const ModeTransition& transition);
    void writeEndOfScan();
    void writeReachMarkers();
    void writeCheckMarkers();
    void writeForget();
    std::string condition(const ProgramCondition& condition) const;
    std::string stateIn(const std::vector<State>& states) const;
    void marker(PackmlMarker m, const std::string& what);
    void markIf(const std::string& test, PackmlMarker m, const std::string& what);
    // Collapsed conditions: may their private inputs make them TRUE, FALSE?
    std::pair<bool, bool> collapsedValues(const ProgramCondition& condition) const;
    std::vector<State> acceptingStates(Command command) const; // some mode accepts it there

    // The instances' GRAFCETs.
    void declareInstance(int instance);
    void writeInitializationCall(int instance);
    void writeOrdinaryCall(int instance);
    void writeEvolution(int instance, bool first);
    void writeStored(int instance, const std::vector<NestedAction>& actions);
    void writeOutputs(int instance);
    void writeStepMarkers(int instance);
    void writeTimersAging();
    const NestedGrafcet* grafcetOf(int instance) const;

    const Model& m_model;
    const PackmlProgram& m_program;
    InputChoices m_choices;
    ScanReference m_reference;
    Names m_names;
    Lines m_declarations;
    Lines m_process;
    std::vector<PackmlMarker> m_markers;
    std::size_t m_maxTransitions = 0, m_maxSteps = 0, m_maxOutputs = 0;
    std::array<std::vector<Command>, kStateCount + 1> m_accepted{}; // by state: some mode accepts the command there
    std::array<std::vector<int>, kStateCount + 1> m_grantable{};    // by state: mode indexes some grant reaches
    int m_cntrlCmd = -1, m_cmdChangeRequest = -1, m_unitMode = -1, m_unitModeChangeRequest = -1;
};

} // namespace core::packml::promela
