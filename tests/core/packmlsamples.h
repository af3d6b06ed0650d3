#pragma once

// Random PackML models for the agreement and property tests (issue 34).

#include "core/model/model.h"

#include <cstdint>

namespace samples {

// A random PackML model whose program has no problem (its conditions and
// GRAFCETs are all usable): either edition with random options, the base
// modes (Maintenance sometimes removed) and sometimes a user mode, random
// disabled states kept consistent as the editor keeps them, random
// mode-change states and request conditions (some empty, some on an INT
// selector), command conditions that are the default input, an OR with an
// input shared by several commands, a NOT, or FALSE (CntrlCmd only), a random initial state
// and mode, and on enabled acting states and Execute random GRAFCETs (those
// of addValidRandomNestedGrafcets), some shared by "same as". The same seed
// gives the same model.
core::Model randomPackmlModel(std::uint32_t seed);

} // namespace samples
