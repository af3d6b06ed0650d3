#pragma once

// The PackML explorer's timer abstraction (docs/packml.md, "Verification"):
// a TON longer than one cycle may or may not have elapsed from its second run
// on; once elapsed it stays so while its step stays active; a step that
// enters resets it (NestedEngine does that part). The simulator asks this
// oracle for the Q of each such TON its scan reads; the explorer runs the
// scan once per way of answering, depth first: the first run answers FALSE
// to every question, each next one replays a prefix of the answers with its
// last FALSE turned TRUE. A TON no longer than one cycle has elapsed at its
// second run whatever the cycle's jitter below it: no question.

#include "core/simulation/nestedengine.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace core::packml {

struct TimerDecision {
    std::size_t timer = 0; // index in its GRAFCET's timers (one instance runs per scan)
    bool elapsed = false;
};

class TimerChoices final : public TimerOracle {
public:
    explicit TimerChoices(std::int64_t cycleMs) : m_cycleMs(cycleMs) {}

    // Before a scan: the answers to give first, in the order asked.
    void start(std::vector<char> prefix);
    bool elapsed(const NestedTimer& timer, std::size_t index) override;
    // After the scan: every answer it took, in the order asked.
    const std::vector<TimerDecision>& decisions() const { return m_decisions; }
    // The answers of the scan just run, as a prefix for start().
    std::vector<char> answers() const;
    // Prepares the next way of answering (the prefix for start()): false
    // when every way has been run.
    bool advance(std::vector<char>& prefix) const;

private:
    std::int64_t m_cycleMs;
    std::vector<char> m_prefix;
    std::vector<TimerDecision> m_decisions;
};

} // namespace core::packml
