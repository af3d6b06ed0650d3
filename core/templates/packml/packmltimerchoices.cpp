#include "core/templates/packml/packmltimerchoices.h"

#include <utility>

namespace core::packml {

void TimerChoices::start(std::vector<char> prefix)
{
    m_prefix = std::move(prefix);
    m_decisions.clear();
}

bool TimerChoices::elapsed(const NestedTimer& timer, std::size_t index)
{
    if (timer.durationMs <= m_cycleMs)
        return true;
    const std::size_t asked = m_decisions.size();
    const bool answer = asked < m_prefix.size() && m_prefix[asked] != 0;
    m_decisions.push_back({index, answer});
    return answer;
}

std::vector<char> TimerChoices::answers() const
{
    std::vector<char> values;
    values.reserve(m_decisions.size());
    for (const TimerDecision& decision : m_decisions)
        values.push_back(decision.elapsed ? 1 : 0);
    return values;
}

bool TimerChoices::advance(std::vector<char>& prefix) const
{
    prefix = answers();
    while (!prefix.empty() && prefix.back())
        prefix.pop_back();
    if (prefix.empty())
        return false;
    prefix.back() = 1;
    return true;
}

} // namespace core::packml
