#pragma once

// The PROGRAM of a PackML model (spec packml.md §6.2-§6.4): its
// declarations and its body, sections 1 (commands) to 6 (edge memories).

#include "core/codegen/plcproject.h"
#include "core/templates/packml/packmlprogram.h"

#include <string>
#include <vector>

namespace core::packml {

// `declared`: declaredGlobalNames(program).
PlcPou buildPackmlProgramPou(const PackmlProgram& program, const std::vector<std::string>& declared, Dialect dialect);

} // namespace core::packml
