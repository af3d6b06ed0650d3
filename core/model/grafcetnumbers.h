#pragma once

// How the GRAFCET's files and its checks look up and name step and
// transition numbers.

#include "core/model/status.h"

#include <algorithm>
#include <string>
#include <vector>

namespace core::grafcetnumbers {

inline bool contains(const std::vector<int>& numbers, int number)
{
    return std::find(numbers.begin(), numbers.end(), number) != numbers.end();
}

inline std::string stepName(int number)
{
    return "step " + std::to_string(number);
}

inline std::string transitionLabel(int number)
{
    return "T" + std::to_string(number);
}

inline Status unknownStep(int number)
{
    return Status::failure("unknown-step", "the GRAFCET has no step " + std::to_string(number));
}

inline Status unknownTransition(int number)
{
    return Status::failure("unknown-transition", "the GRAFCET has no transition T" + std::to_string(number));
}

} // namespace core::grafcetnumbers
