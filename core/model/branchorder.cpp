#include "core/model/branchorder.h"

#include "core/model/grafcetwalk.h"

#include "core/model/grafcetediting.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace core {

namespace {

// Each branch's steps less those above the divergence and those two
// branches share (they are past a join).
std::vector<std::set<int>> ownSteps(std::vector<std::set<int>> branches, const std::set<int>& above)
{
    std::map<int, int> owners;
    for (const std::set<int>& branch : branches)
        for (int step : branch)
            ++owners[step];
    for (std::set<int>& branch : branches)
        for (auto it = branch.begin(); it != branch.end();)
            it = (above.count(*it) || owners[*it] > 1) ? branch.erase(it) : std::next(it);
    return branches;
}

struct Divergence {
    BranchPlace::Kind kind = BranchPlace::Kind::Selection;
    int number = 0; // the step or the transition
    std::vector<std::set<int>> branches;
};

Divergence selectionAt(const Grafcet& grafcet, int step)
{
    // selectionJoin names a step even when a single branch reaches it: that one is no join.
    int join = selectionJoin(grafcet, step);
    int reaching = 0;
    for (const GrafcetTransition* t : grafcet.transitionsFrom(step))
        reaching += reachableSteps(grafcet, t->downstream, {step}).count(join) > 0 ? 1 : 0;
    if (reaching < 2)
        join = step;
    std::vector<std::set<int>> branches;
    for (const GrafcetTransition* t : grafcet.transitionsFrom(step))
        branches.push_back(reachableSteps(grafcet, t->downstream, {step, join}));
    const std::set<int> above = reachableSteps(grafcet, walkStarts(grafcet, step), {step});
    return {BranchPlace::Kind::Selection, step, ownSteps(std::move(branches), above)};
}

Divergence parallelAt(const Grafcet& grafcet, const GrafcetTransition& transition)
{
    const int convergence = simultaneousConvergence(grafcet, transition.number);
    const std::set<int> blocked(transition.upstream.begin(), transition.upstream.end());
    std::vector<std::set<int>> branches;
    for (int first : transition.downstream)
        branches.push_back(reachableSteps(grafcet, {first}, blocked, convergence));
    const std::set<int> above = reachableSteps(grafcet, walkStarts(grafcet, 0), {}, transition.number);
    return {BranchPlace::Kind::Parallel, transition.number, ownSteps(std::move(branches), above)};
}

std::vector<Divergence> divergences(const Grafcet& grafcet)
{
    std::vector<Divergence> result;
    for (const GrafcetStep& step : grafcet.steps())
        if (grafcet.transitionsFrom(step.number).size() >= 2)
            result.push_back(selectionAt(grafcet, step.number));
    for (const GrafcetTransition& t : grafcet.transitions())
        if (t.downstream.size() >= 2)
            result.push_back(parallelAt(grafcet, t));
    return result;
}

// `order` with the element at `from` moved to `to`, the others in their order.
template <typename T>
std::vector<T> movedTo(std::vector<T> order, int from, int to)
{
    T moving = order[static_cast<std::size_t>(from)];
    order.erase(order.begin() + from);
    order.insert(order.begin() + to, moving);
    return order;
}

// The transitions leaving `step` take their places in the list in `order`.
Status reorderSelection(Grafcet& grafcet, int step, const std::vector<int>& order)
{
    std::vector<GrafcetTransition> transitions;
    std::size_t next = 0;
    for (const GrafcetTransition& t : grafcet.transitions()) {
        const bool leaves = std::find(t.upstream.begin(), t.upstream.end(), step) != t.upstream.end();
        transitions.push_back(leaves ? *grafcet.transition(order[next++]) : t);
    }
    Grafcet rebuilt;
    for (const GrafcetStep& s : grafcet.steps())
        if (Status status = rebuilt.addStep(s); !status)
            return status;
    for (const GrafcetTransition& t : transitions)
        if (Status status = rebuilt.addTransition(t); !status)
            return status;
    grafcet = std::move(rebuilt);
    return Status::success();
}

// The convergence's upstream steps that end branches, in the branches' new
// order (each branch's steps in their order), in the places they held.
std::vector<int> convergenceOrder(const std::vector<int>& upstream, const std::vector<std::set<int>>& newBranches)
{
    const auto branchOf = [&newBranches](int step) {
        for (std::size_t i = 0; i < newBranches.size(); ++i)
            if (newBranches[i].count(step))
                return static_cast<int>(i);
        return -1;
    };
    std::vector<int> onBranches;
    for (int step : upstream)
        if (branchOf(step) >= 0)
            onBranches.push_back(step);
    std::stable_sort(onBranches.begin(), onBranches.end(),
                     [&branchOf](int a, int b) { return branchOf(a) < branchOf(b); });
    std::vector<int> result = upstream;
    std::size_t next = 0;
    for (int& step : result)
        if (branchOf(step) >= 0)
            step = onBranches[next++];
    return result;
}

Status reorderParallel(Grafcet& grafcet, const Divergence& divergence, int from, int to)
{
    const GrafcetTransition& transition = *grafcet.transition(divergence.number);
    const int convergence = simultaneousConvergence(grafcet, transition.number);
    const std::vector<int> downstream = movedTo(transition.downstream, from, to);
    if (Status status = grafcet.setDownstream(transition.number, downstream); !status)
        return status;
    if (convergence == 0)
        return Status::success();
    const std::vector<std::set<int>> newBranches = movedTo(divergence.branches, from, to);
    return grafcet.setUpstream(convergence, convergenceOrder(grafcet.transition(convergence)->upstream, newBranches));
}

} // namespace

bool findBranch(const Grafcet& grafcet, int step, BranchPlace& place)
{
    bool found = false;
    std::size_t smallest = 0;
    for (const Divergence& divergence : divergences(grafcet))
        for (std::size_t i = 0; i < divergence.branches.size(); ++i) {
            const std::set<int>& branch = divergence.branches[i];
            if (!branch.count(step) || (found && branch.size() >= smallest))
                continue;
            found = true;
            smallest = branch.size();
            place = {divergence.kind, divergence.number, static_cast<int>(i),
                     static_cast<int>(divergence.branches.size()), {branch.begin(), branch.end()}};
        }
    return found;
}

bool canMoveBranch(const Grafcet& grafcet, int step, int offset)
{
    BranchPlace place;
    if (offset == 0 || !findBranch(grafcet, step, place))
        return false;
    const int to = place.index + offset;
    return to >= 0 && to < place.count;
}

namespace {

// The transition's place among the branches of the step it leaves, -1 when it starts no selection branch.
int selectionIndex(const Grafcet& grafcet, int transition, std::vector<int>& order)
{
    const GrafcetTransition* t = grafcet.transition(transition);
    if (!t || t->upstream.size() != 1)
        return -1;
    order.clear();
    for (const GrafcetTransition* leaving : grafcet.transitionsFrom(t->upstream.front()))
        order.push_back(leaving->number);
    const auto found = std::find(order.begin(), order.end(), transition);
    return order.size() < 2 ? -1 : static_cast<int>(found - order.begin());
}

} // namespace

bool canMoveSelectionBranch(const Grafcet& grafcet, int transition, int offset)
{
    std::vector<int> order;
    const int index = selectionIndex(grafcet, transition, order);
    const int to = index + offset;
    return index >= 0 && offset != 0 && to >= 0 && to < static_cast<int>(order.size());
}

Status moveSelectionBranch(Grafcet& grafcet, int transition, int offset)
{
    if (!canMoveSelectionBranch(grafcet, transition, offset))
        return Status::failure("cannot-move-branch", "T" + std::to_string(transition)
                                                         + " starts no selection branch that can move "
                                                         + std::to_string(offset) + " place(s)");
    std::vector<int> order;
    const int index = selectionIndex(grafcet, transition, order);
    Grafcet work = grafcet;
    if (Status status = reorderSelection(work, grafcet.transition(transition)->upstream.front(),
                                         movedTo(order, index, index + offset));
        !status)
        return status;
    grafcet = std::move(work);
    return Status::success();
}

Status moveBranch(Grafcet& grafcet, int step, int offset)
{
    if (!canMoveBranch(grafcet, step, offset))
        return Status::failure("cannot-move-branch", "step " + std::to_string(step)
                                                         + " is on no branch that can move "
                                                         + std::to_string(offset) + " place(s)");
    BranchPlace place;
    findBranch(grafcet, step, place);
    const int to = place.index + offset;
    Grafcet work = grafcet;
    Status status = Status::success();
    if (place.kind == BranchPlace::Kind::Selection) {
        std::vector<int> order;
        for (const GrafcetTransition* t : work.transitionsFrom(place.divergence))
            order.push_back(t->number);
        status = reorderSelection(work, place.divergence, movedTo(order, place.index, to));
    } else {
        for (const Divergence& divergence : divergences(work))
            if (divergence.kind == BranchPlace::Kind::Parallel && divergence.number == place.divergence)
                status = reorderParallel(work, divergence, place.index, to);
    }
    if (!status)
        return status;
    grafcet = std::move(work);
    return Status::success();
}

} // namespace core
