#pragma once

// Values as the PackML simulator holds them, one cond::Value per variable
// in its IEC type: the initial value of a declaration, whether a value given
// from outside fits the variable, and a number read from a DINT tag.

#include "core/condition/conditionevaluator.h"
#include "core/model/model.h"

#include <cstdint>
#include <optional>
#include <string>

namespace core::packml {

// A number as CntrlCmd or UnitMode carries it (a BOOL is 0 or 1, a REAL truncated; 0 when it has none).
std::int64_t integerOf(const cond::Value& value);

// The variable's declared default, or the implicit one of its type when the
// default does not fit, as the generated code declares it.
cond::Value defaultValueOf(const Variable& variable);

// nullopt when `value` is of the variable's type and range (an integer given
// for a REAL becomes a real); else why not, in English.
std::optional<std::string> fitValue(const Variable& variable, cond::Value& value);

} // namespace core::packml
