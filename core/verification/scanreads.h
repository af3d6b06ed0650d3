#pragma once

// The variables one scan of the simulator may read, from the state it starts
// in, for the concrete search of properties (core/verification/concretesearch.h):
// it sets only those inputs, so a scan branches on what it reads rather than
// on every input of the model. An over-approximation: the active GEMMA step's
// transition conditions, every token literal, the property, every variable
// read under an edge, and, when the step has a nested GRAFCET, the
// receptivities of its transitions with an active upstream step (the initial
// steps on entry; all of them under "until stable", which may evolve more
// than once) and the actions of the steps those transitions and the active
// steps concern. Missing one only makes the search less complete, never
// wrong: every run it reports is replayed in the simulator.

#include "core/condition/conditionsyntax.h"

#include <set>
#include <string>

namespace core {

class Simulator;

// Upper-case names of the variables the next scan of `simulator` may read;
// `property` is the parsed property (read at the end of every scan).
std::set<std::string> scanReads(const Simulator& simulator, const cond::Expression& property);

} // namespace core
