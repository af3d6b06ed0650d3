#pragma once

// Both layers of the program as a Promela model, so that SPIN can check,
// independently of core/verification/programexplorer.cpp, what the
// exploration of both layers claims (docs/verification.md, "SPIN
// cross-check of both layers").
//
// One iteration of the scan process's `do` loop is one PLC scan of the
// generated program (spec grafcet-layer.md §4), written from
// core::GemmaProgram and its NestedGrafcets as the spec words it, not from
// the explorer's code:
// - the state between scans: State (gState, 0 when no visible step is
//   active), Entry, the tokens; for each nested GRAFCET its situation (S_Xn),
//   its function block's outputs (S_o_V) and Complete (S_C) and its TONs
//   (S_Tk); the stored BOOL variables (v_V) and the edge memories (p_V). A
//   GRAFCET whose step is not active is all zero: the Initialization call of
//   the step's entry scan starts it afresh.
// - inputs are chosen when the scan first reads them (inline rd_V), so that a
//   scan branches only on what it reads, and forgotten after it; a numeric
//   variable takes one value per combination of the comparisons with
//   constants on it (n_V indexes them); any other comparison is a free BOOL
//   per canonical text (o_k); a TON longer than one cycle may or may not have
//   elapsed from its second run on, unless time is counted in scans (an
//   `int` per TON, whatever its duration: core/verification/tonscans.h).
// - each claim of the exploration has a marker line (PromelaMarker): a
//   statement alone on its line, reached in SPIN's exhaustive search iff the
//   claim holds somewhere; readSpinReport and SpinReport::reached read them.
//   For GV103 and GV104 the scan where a GEMMA transition fires also reads
//   the conditions after it (Fails, Overlap), as the explorer's probe does;
//   the generated code does not, and nothing read there changes the state.

#include "core/verification/promela.h"
#include "core/verification/tonscans.h"

#include <map>
#include <string>
#include <vector>

namespace core {

class Model;

namespace machine {
struct Machine;
}

struct ProgramPromelaOptions {
    // Complete of the macro/enclosing steps without nested GRAFCET (Free when not listed).
    std::map<std::string, CompleteAssumption> complete;
    // The properties to mark (core/verification/property.h); one that does
    // not pass checkProperty gets no marker.
    std::vector<std::string> properties;
    // TONs elapse in exactly the scan the PLC's would, counted in scans.
    bool exactTime = false;
    // With exactTime: a TON is counted up to this many runs, then may or may
    // not have elapsed (explore::Options::maxCountedTimerRuns, which it must equal).
    std::int64_t maxCountedTimerRuns = tonscans::kMaxCountedRuns;
    // Closed loop (docs/verification.md, "Closed loop (--machine)"): the
    // inputs this machine's sensors drive read its state, and it runs one
    // cycle after each scan, counted in scans with exactTime, else
    // abstracted as explore::AbstractMachine is. nullptr or empty: open loop.
    const machine::Machine* machine = nullptr;
    // With the machine: any one sensor stuck TRUE, stuck FALSE or flickering,
    // or one cylinder or conveyor jammed, may begin before any scan and stays
    // (explore::Options::singleFaults; docs/verification.md, "Single faults").
    // `flt` is the fault in effect (0 none), `flk` a flickering sensor's
    // reading, `fc` the scans since it began (for `T/faulted`).
    bool singleFaults = false;
};

PromelaModel buildProgramPromela(const Model& model, const ProgramPromelaOptions& options = {});

} // namespace core
