#pragma once

// PackML models the tests and benchmarks share (issue 34's figures).

#include "core/model/model.h"

namespace factory {

// Issue 34's PackML stress model: all 31 unit modes (Production,
// Maintenance, Manual and User4 ... User31), every state enabled, mode
// changes in Stopped, Idle and Aborted, a request condition per mode
// (`ModeKey = n`), and in Production an own GRAFCET of `steps` steps in every
// acting state and Execute (a sequence over BOOL inputs In1 ... In<steps>,
// continuous outputs Out1 ... Out<steps>, the last step sets Complete but in
// Execute, where it loops), which every other mode runs as "same as 1". So
// 341 instances of 11 function blocks: the size of a large line, generated
// the way a real model shares its procedures.
core::Model packmlStressModel(int steps = 40);

} // namespace factory
