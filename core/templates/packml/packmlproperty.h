#pragma once

// The engineer's properties on a PackML model (docs/packml.md,
// "Verification"): `never P` / `always P` as for GEMMA models
// (core/verification/property.h), where P may read
//   in S          the state S (PackTags name) is active at the end of the scan;
//   mode M        M (its name) is the current unit mode at the end of the scan;
//   <Mode>_<State>.Xn   that instance's state is active in its mode, its FB
//                 has run in the scan (Entry is FALSE) and step n of its
//                 GRAFCET is active;
// and the variables, PackTags included.

#include "core/verification/property.h"

#include <string>
#include <string_view>
#include <vector>

namespace core {
class Model;
}

namespace core::packml {

class PackmlSimulator;
struct PackmlProgram;

// A property parsed and resolved against a program.
struct PackmlProperty {
    ParsedProperty parsed;
    // By expression node: the mode number (`mode M`), the state number
    // (`in S`) or the instance index (`I.Xn`); -1 otherwise or unknown.
    std::vector<int> resolved;
    std::vector<bool> isMode; // by node: an InStep node written `mode M`
    std::vector<std::string> reads; // variable names, as written
};

// Parses `mode M` as a state predicate of its own, keeping the spans of the
// text as written.
PackmlProperty parsePackmlProperty(std::string_view text, const PackmlProgram& program);

// Syntax, names (GP003 for an unknown state, mode or instance; GP004 an
// instance without GRAFCET; GP005 a step it does not have) and types.
std::vector<PropertyProblem> checkPackmlProperty(const Model& model, std::string_view text);

// `never P` with P TRUE, or `always P` with P FALSE, after the simulator's last scan.
bool packmlPropertyViolated(const PackmlProperty& property, const PackmlSimulator& simulator);

} // namespace core::packml
