#include "core/model/grafcetwalk.h"

#include "core/model/grafcetadjacency.h"

#include <deque>

namespace core {

std::set<int> reachableSteps(const Grafcet& grafcet, const std::vector<int>& from, const std::set<int>& blocked,
                             int skippedTransition)
{
    std::set<int> seen;
    std::deque<int> queue;
    for (int step : from)
        if (!blocked.count(step) && seen.insert(step).second)
            queue.push_back(step);
    const GrafcetAdjacency adjacency(grafcet);
    while (!queue.empty()) {
        const int step = queue.front();
        queue.pop_front();
        for (const GrafcetTransition* t : adjacency.leaving(step)) {
            if (t->number == skippedTransition)
                continue;
            for (int next : t->downstream)
                if (!blocked.count(next) && seen.insert(next).second)
                    queue.push_back(next);
        }
    }
    return seen;
}

std::vector<int> walkStarts(const Grafcet& grafcet, int except)
{
    const GrafcetAdjacency adjacency(grafcet);
    std::vector<int> starts;
    for (const GrafcetStep& step : grafcet.steps())
        if (step.number != except && (step.initial || adjacency.entering(step.number).empty()))
            starts.push_back(step.number);
    return starts;
}

} // namespace core
