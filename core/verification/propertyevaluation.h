#pragma once

// A property read on the simulator after a scan (docs/verification.md,
// "Properties"): what confirms that a counterexample replays to the
// violation it claims.

#include "core/verification/property.h"

#include <cstdint>

namespace core {

class Model;
class Simulator;

// Whether the property is violated at the end of the simulator's last scan:
// `never P` with P TRUE, or `always P` with P FALSE. The property must parse.
bool propertyViolatedOn(const Model& model, const ParsedProperty& property, const Simulator& simulator);
// The same in a run with single faults: `faultScan` is the scan before which
// the fault was applied (0: none yet), for `faulted` and `T/faulted`.
bool propertyViolatedOn(const Model& model, const ParsedProperty& property, const Simulator& simulator,
                        std::int64_t faultScan);

} // namespace core
