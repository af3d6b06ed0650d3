#pragma once

// Models for the PLCopen tests and the schema-validation samples, beside
// those of tests/support/modelfactory.h: the GG-Generator paper case study
// (tokens, all three step types, six function blocks) and seeded random ones.

#include "core/model/model.h"

#include <cstdint>

namespace samples {

// The filling-and-capping machine of the GG-Generator paper: F1-F5 and D3
// with nested behaviour, F6 hidden, tokens on F1 -> A2 (NOT Stop) and F1 -> F3.
core::Model caseStudyModel();

// A random model the checks accept without error: random step types, hidden
// steps and transitions, conditions over declared BOOL and numeric variables,
// negations, tokens, priorities, comments full of XML and ST delimiters.
// The same seed gives the same model.
core::Model randomModel(std::uint32_t seed);

} // namespace samples
