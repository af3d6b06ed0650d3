#pragma once

// The checks of a PackML model's command and request conditions (spec
// packml.md §2.2, §3.4, §7): GG201–GG204 as GEMMA conditions get them, read
// with the PackTags globals of §5.2 declared; PM019 (X<n>, Complete, an edge
// or t/X<n>: the texts of nested GRAFCETs only), PM012 (an output read) and
// PM011 (two commands, or two requests, with the same condition).

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {
class Model;
}

namespace core::packml {

// The edition's commands in number order (each: its condition's findings),
// then the modes' request conditions in mode order. A 2015 model's Complete
// is PM017's business; a blank request is no request.
std::vector<Diagnostic> checkConditions(const Model& model);

} // namespace core::packml
