#pragma once

// Looks for a real violation of a property where the exploration of both
// layers found only an abstract one (docs/verification.md, "Undecided
// properties"): a breadth-first search of the simulator's own runs, so
// numeric memories (`Count := Count + 1`) and timers are tracked exactly.
// At every scan each input the scan may read (core/verification/scanreads.h)
// takes each of a few values (BOOL: both; numbers: the default and the
// constants the model's conditions compare with, and their neighbours), the
// others keep theirs, and the Complete of a free step without GRAFCET takes
// both values. Bounded in states and time: not finding a violation proves
// nothing, so the property then stays undecided.

#include "core/verification/verification.h"

#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace core {

class Model;

struct ConcreteSearchOptions {
    std::map<std::string, CompleteAssumption> complete; // as VerificationOptions::complete
    std::size_t maxStates = 20'000; // distinct simulator states kept
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    std::function<bool()> cancelled;
};

struct ConcreteSearchResult {
    // A run from reset whose last scan violates the property, replayed in the
    // simulator (confirmed) with the property read on the replay; or none.
    std::optional<Counterexample> counterexample;
    std::size_t states = 0; // distinct states searched
    std::string reason;     // without a counterexample: why the search ended (English)
};

// `title`: the scenario's leading comment. The property must pass checkProperty.
ConcreteSearchResult searchPropertyViolation(const Model& model, const std::string& property,
                                             const std::string& title, const ConcreteSearchOptions& options);

} // namespace core
