#pragma once

#include <optional>
#include <string_view>

namespace cli {

// Milliseconds of a duration written as engineers write task intervals:
// "20ms", "1s", "1s500ms", "2m", "T#20ms", "t#1.5s", or a bare number of
// milliseconds. nullopt when the text is not such a duration or is not a
// whole number of milliseconds.
std::optional<int> parseCycleTime(std::string_view text);

} // namespace cli
