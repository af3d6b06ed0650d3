#pragma once

// How the verifier counts a TON in scans when time is counted exactly
// (spec grafcet-layer.md §4.4), shared by the explorer and the Promela model
// of both layers so that the two count alike (docs/verification.md, "Both
// layers").

#include <cstdint>

namespace core::tonscans {

// The largest run count stored: what a Promela `int` holds, less one value
// kept for "elapsed" (kMaxCountedRuns + 1). A TON that needs more runs is
// counted up to this many, then may or may not have elapsed: sound (it can
// only elapse later than it truly does, never sooner) and, at one state per
// run, far beyond what any exploration budget reaches.
inline constexpr std::int64_t kMaxCountedRuns = 2'147'483'646;

// The runs with IN TRUE after which Q is TRUE: ceil(duration / cycle) + 1
// (the run that starts the TON counts). Exact for every duration the
// condition language accepts (up to INT64_MAX ms): no intermediate overflows.
constexpr std::int64_t runsToElapse(std::int64_t durationMs, int cycleMs)
{
    const std::int64_t cycle = cycleMs < 1 ? 1 : cycleMs;
    return durationMs / cycle + (durationMs % cycle != 0 ? 1 : 0) + 1;
}

// What is stored for a TON of `runs`: counts up to this many runs.
constexpr std::int64_t countLimit(std::int64_t runs, std::int64_t maxCounted)
{
    return runs < maxCounted ? runs : maxCounted;
}

// Whether the TON is counted only up to `maxCounted` runs, then chosen.
constexpr bool countedPartly(std::int64_t runs, std::int64_t maxCounted)
{
    return runs > maxCounted;
}

} // namespace core::tonscans
