#pragma once

#include "core/templates/templateengines.h"

namespace core {

// GEMMA's checks, property checks and code generator.
const TemplateEngines& gemmaEngines();

} // namespace core
