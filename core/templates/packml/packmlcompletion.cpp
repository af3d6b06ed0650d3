#include "core/templates/packml/packmlcompletion.h"

#include <deque>
#include <set>
#include <utility>

namespace core::packml {

namespace {

// Backwards from the nodes with a completing edge `usable` accepts, along
// the staying edges it accepts.
std::vector<char> reachesComplete(const PackmlExplorer& explorer, const std::vector<char>& usable)
{
    const auto& edges = explorer.edges();
    std::vector<std::vector<std::uint32_t>> staysInto(explorer.nodes().size());
    std::vector<char> reaches(explorer.nodes().size(), 0);
    std::deque<std::uint32_t> queue;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const ExploredEdge& edge = edges[e];
        if (!usable[e])
            continue;
        if (edge.stays)
            staysInto[edge.to].push_back(edge.from);
        if (edge.completes && !reaches[edge.from]) {
            reaches[edge.from] = 1;
            queue.push_back(edge.from);
        }
    }
    while (!queue.empty()) {
        const std::uint32_t n = queue.front();
        queue.pop_front();
        for (std::uint32_t from : staysInto[n])
            if (!reaches[from]) {
                reaches[from] = 1;
                queue.push_back(from);
            }
    }
    return reaches;
}

constexpr std::int32_t kNoTimer = -1;

// The edges a configuration of their source surely takes (see the header).
std::vector<char> sureEdges(const PackmlExplorer& explorer)
{
    const auto& edges = explorer.edges();
    std::set<std::pair<std::uint32_t, std::int32_t>> waits; // node, TON it waits on (kNoTimer: any)
    for (const ExploredEdge& edge : edges) {
        if (edge.from != edge.to || !edge.stays || edge.decidedElapsed)
            continue;
        if (edge.decisions == 0)
            waits.insert({edge.from, kNoTimer});
        else if (edge.decidedTimer >= 0)
            waits.insert({edge.from, edge.decidedTimer});
    }
    std::vector<char> sure(edges.size(), 0);
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const ExploredEdge& edge = edges[e];
        sure[e] = edge.decisions == 0
                  || (!edge.decidedRunning && edge.decidedTimer >= 0
                      && (waits.count({edge.from, kNoTimer}) || waits.count({edge.from, edge.decidedTimer})));
    }
    return sure;
}

} // namespace

Completion completion(const PackmlExplorer& explorer)
{
    Completion result;
    result.possible = reachesComplete(explorer, std::vector<char>(explorer.edges().size(), 1));
    result.sure = explorer.timeAbstracted() ? reachesComplete(explorer, sureEdges(explorer)) : result.possible;
    return result;
}

} // namespace core::packml
