#pragma once

#include "core/templates/templateengines.h"

namespace core::packml {

// PackML's checks, property checks and code generator.
const TemplateEngines& engines();

} // namespace core::packml
