#pragma once

// A new PackML model (spec packml.md §2.2, §3.1, §5.1). The Model's PackML
// operations are defined in packmlmodelediting.cpp.

#include "core/model/model.h"
#include "core/templates/packml/packmltemplate.h"

#include <string_view>

namespace core::packml {

inline constexpr std::string_view kDefaultProgramName = "PackML"; // spec §5.3

// Production, Maintenance and Manual with every state enabled and mode
// changes in Stopped, Idle and Aborted; initial state Stopped, initial mode
// 1, the edition's default options; the BOOL inputs Cmd_Reset ... Cmd_Clear
// (and Cmd_Complete in 2022) declared and used as the command conditions.
Model newModel(Edition edition = Edition::Y2015);

} // namespace core::packml
