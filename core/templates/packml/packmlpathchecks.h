#pragma once

// The checks of a PackML model that follow its state machine and ask where
// a state's GRAFCET writes Complete (spec packml.md §4, §7): PM008 (no way
// to Execute), PM009 (a state no way reaches), PM010 (a GRAFCET that never
// completes) and PM016 (Execute's Complete in 2022, which nothing reads).

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {
class Grafcet;
class Model;
}

namespace core::packml {

// Does an action of the GRAFCET make Complete TRUE (`S Complete`,
// `Complete := ...`, a continuous `Complete`)?
bool setsComplete(const Grafcet& grafcet);

// Per mode, in mode order: PM008, then its states in state order.
std::vector<Diagnostic> checkPaths(const Model& model);

} // namespace core::packml
