#pragma once

// The checks of a PackML model's unit modes that read their lists and
// GRAFCET choices (spec packml.md §3, §4, §7): PM002 (numbers and names),
// PM004 and PM005 (overridden listings), PM006 (mode changes without
// effect), PM007 (a mode never current), PM014 (a GRAFCET kept on a disabled
// state) and PM015 (a "same as" that names no usable GRAFCET).

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {
class Model;
}

namespace core::packml {

// Per mode, in mode order: the mode's own findings, then its states'.
std::vector<Diagnostic> checkModes(const Model& model);

} // namespace core::packml
