#pragma once

// What each template gives the engines every model goes through. The shared
// entry points (checkModel, checkProperty, buildPlcProject) read the model's template here
// instead of branching on it: a template is its data (gemmatemplate.h,
// packmltemplate.h) plus these engines, each in its own folder. Its verifier
// is in a table of its own (templateverification.h), in the verification
// library, so that what needs no verifier (the fuzzers) does not build it.
// The native file format reads the template from the file
// (core/formats/nativeformat.cpp) before there is a model to ask.

#include "core/checks/diagnostic.h"
#include "core/codegen/plcproject.h"
#include "core/verification/property.h"

#include <string_view>
#include <vector>

namespace core {

class Model;

struct TemplateEngines {
    std::vector<Diagnostic> (*checkModel)(const Model& model);
    std::vector<PropertyProblem> (*checkProperty)(const Model& model, std::string_view text);
    PlcProject (*buildPlcProject)(const Model& model, Dialect dialect);
};

// The engines of the model's template.
const TemplateEngines& enginesOf(const Model& model);

} // namespace core
