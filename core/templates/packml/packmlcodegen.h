#pragma once

// The generated code of a PackML model (spec packml.md §6, §6.7) as a
// PlcProject, so that the printers of core/codegen (formatPou,
// formatSingleFileIec, the ST folder export, the PLCopen XML writer) serve
// both templates: the skeleton function blocks, the function blocks of the
// nested GRAFCETs, the PROGRAM, the globals and the configuration
// PackMLConfiguration. buildPlcProject calls it for a PackML model.

#include "core/codegen/plcproject.h"
#include "core/model/model.h"

namespace core::packml {

PlcProject buildPackmlPlcProject(const Model& model, Dialect dialect);

} // namespace core::packml
