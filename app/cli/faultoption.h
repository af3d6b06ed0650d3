#pragma once

// `simulate --fault "120:Clamped stuck FALSE"` (docs/cli.md): a scenario's
// fault line given on the command line, `SCAN:TARGET KIND` for
// `at SCAN: fault TARGET KIND`, parsed by the scenario parser itself so
// that both spell faults alike.

#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace cli {

// The fault action of one option; false and `error` set ("expected TRUE or
// FALSE, found 'maybe'") when it is malformed.
bool parseFaultOption(const std::string& option, core::ScenarioAction& action, std::string& error);

// Every option, in order; false and `error` ("--fault '5:x': ...") at the
// first malformed one.
bool parseFaultOptions(const std::vector<std::string>& options, std::vector<core::ScenarioAction>& faults,
                       std::string& error);

// The faults against the machine (`loop` nullptr: none, or `openLoop`
// ignores it); false and `error` when one does not apply.
bool checkFaultOptions(const std::vector<std::string>& options, const std::vector<core::ScenarioAction>& faults,
                       const core::machine::MachineLoop* loop, bool openLoop, std::string& error);

// The faults of a scenario by scan, gathered once: a run announces the ones
// of each scan before it ("fault at scan 120: Clamped stuck FALSE").
class FaultAnnouncements {
public:
    explicit FaultAnnouncements(const core::Scenario& scenario);
    void print(std::int64_t scan, std::ostream& out) const;

private:
    std::multimap<std::int64_t, std::string> m_faults; // by scan, in file order
};

} // namespace cli
