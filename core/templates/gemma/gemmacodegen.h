#pragma once

// GEMMA's Structured Text by the Hierarchical Design Pattern (spec §6, §7):
// one PROGRAM GEMMA, one FUNCTION_BLOCK per visible macro/enclosing step,
// the globals and a configuration. core::buildPlcProject gives this for a
// GEMMA model; core/codegen/stgenerator.h prints it.

#include "core/codegen/plcproject.h"
#include "core/codegen/stgenerator.h"

namespace core {

class Model;

PlcProject buildGemmaPlcProject(const Model& model, Dialect dialect);

// The GEMMA POU as the editor previews it, with the lines each element
// produced.
StPreview previewGemmaProgram(const Model& model, Dialect dialect);

} // namespace core
