#include "core/model/grafcetediting.h"

#include "core/model/grafcetnumbers.h"
#include "core/model/grafcetwalk.h"

#include "core/layout/grafcetlayout.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <map>
#include <set>
#include <string>
#include <tuple>

namespace core {

namespace {

using grafcetnumbers::contains;
using grafcetnumbers::unknownStep;
using grafcetnumbers::unknownTransition;

// `number` in `set` replaced, at its place, by those of `with` not in the set yet.
std::vector<int> replaced(const std::vector<int>& set, int number, const std::vector<int>& with)
{
    std::vector<int> result;
    for (int n : set) {
        if (n != number) {
            if (!contains(result, n))
                result.push_back(n);
            continue;
        }
        for (int w : with)
            if (!contains(result, w) && !contains(set, w))
                result.push_back(w);
    }
    return result;
}

GrafcetStep plainStep(int number)
{
    GrafcetStep step;
    step.number = number;
    return step;
}

GrafcetTransition newTransition(int number, std::vector<int> upstream, std::vector<int> downstream)
{
    return {number, std::move(upstream), std::move(downstream), std::string(kNewTransitionReceptivity)};
}

std::vector<int> numbersOf(const std::vector<const GrafcetTransition*>& transitions)
{
    std::vector<int> numbers;
    for (const GrafcetTransition* t : transitions)
        numbers.push_back(t->number);
    return numbers;
}

// A GRAFCET of exactly these steps and transitions, in this order.
Status assemble(const std::vector<GrafcetStep>& steps, const std::vector<GrafcetTransition>& transitions,
                Grafcet& result)
{
    Grafcet built;
    for (const GrafcetStep& step : steps)
        if (Status status = built.addStep(step); !status)
            return status;
    for (const GrafcetTransition& transition : transitions)
        if (Status status = built.addTransition(transition); !status)
            return status;
    result = std::move(built);
    return Status::success();
}

// Replaces `step` by `with` in the upstream (or downstream) set of each transition.
Status redirect(Grafcet& grafcet, const std::vector<int>& transitions, int step, const std::vector<int>& with,
                bool upstream)
{
    for (int number : transitions) {
        const GrafcetTransition* t = grafcet.transition(number);
        const Status status = upstream ? grafcet.setUpstream(number, replaced(t->upstream, step, with))
                                       : grafcet.setDownstream(number, replaced(t->downstream, step, with));
        if (!status)
            return status;
    }
    return Status::success();
}

// Removes the steps reached from `start` that `others` no longer reach.
Status removeCutOff(Grafcet& grafcet, const std::vector<int>& start, std::vector<int> others)
{
    const std::set<int> kept = reachableSteps(grafcet, others);
    for (int step : reachableSteps(grafcet, start))
        if (!kept.count(step))
            if (Status status = grafcet.removeStep(step); !status)
                return status;
    return Status::success();
}

// The steps of the fragment no transition of it reaches (entries) or leaves (exits).
std::vector<int> fragmentEnds(const Grafcet& fragment, bool entries)
{
    std::vector<int> ends;
    for (const GrafcetStep& step : fragment.steps()) {
        const bool linked = entries ? !fragment.transitionsTo(step.number).empty()
                                    : !fragment.transitionsFrom(step.number).empty();
        if (!linked)
            ends.push_back(step.number);
    }
    return ends;
}

// The largest number written in the texts (digits after X, or anywhere:
// renumbering through numbers above it never meets a reference).
int largestNumberInTexts(const Grafcet& grafcet)
{
    int largest = 0;
    const auto scan = [&largest](const std::string& text) {
        long value = 0;
        for (char c : text + ' ') {
            if (std::isdigit(static_cast<unsigned char>(c))) {
                value = std::min(value * 10 + (c - '0'), 100'000'000L);
                continue;
            }
            largest = std::max(largest, static_cast<int>(value));
            value = 0;
        }
    };
    for (const GrafcetTransition& t : grafcet.transitions())
        scan(t.receptivity);
    for (const GrafcetStep& step : grafcet.steps())
        for (const GrafcetAction& action : step.actions)
            scan(action.text);
    return largest;
}

// Renumbers steps old → new at once (through numbers above everything in
// use, so that no two steps ever share a number and no reference is taken
// for another's), with their references.
Status renumberSteps(Grafcet& grafcet, const std::map<int, int>& mapping)
{
    std::set<int> targets;
    int largest = std::max(grafcet.nextStepNumber(), largestNumberInTexts(grafcet));
    for (const auto& [from, to] : mapping) {
        if (!grafcet.step(from))
            return unknownStep(from);
        if (!targets.insert(to).second || (grafcet.step(to) && !mapping.count(to)))
            return Status::failure("duplicate-step", "step " + std::to_string(to) + " would appear twice");
        largest = std::max(largest, to);
    }
    int temporary = largest + 1;
    std::map<int, int> parked; // temporary → final
    for (const auto& [from, to] : mapping) {
        if (Status status = grafcet.renumberStep(from, temporary); !status)
            return status;
        parked[temporary++] = to;
    }
    for (const auto& [from, to] : parked)
        if (Status status = grafcet.renumberStep(from, to); !status)
            return status;
    return Status::success();
}

// The transitions in their order with new numbers.
Status renumberTransitions(Grafcet& grafcet, const std::map<int, int>& mapping)
{
    std::vector<GrafcetTransition> transitions = grafcet.transitions();
    for (GrafcetTransition& t : transitions)
        t.number = mapping.at(t.number);
    return assemble(grafcet.steps(), transitions, grafcet);
}

// Groups steps connected by transitions (union-find), for numbering each
// independent part of the drawing on its own.
std::map<int, int> parts(const Grafcet& grafcet)
{
    std::map<int, int> parent;
    for (const GrafcetStep& step : grafcet.steps())
        parent[step.number] = step.number;
    const auto find = [&parent](int n) {
        while (parent[n] != n)
            n = parent[n] = parent[parent[n]];
        return n;
    };
    for (const GrafcetTransition& t : grafcet.transitions()) {
        const int first = find(t.upstream.front());
        for (const std::vector<int>* set : {&t.upstream, &t.downstream})
            for (int n : *set)
                parent[find(n)] = first;
    }
    std::map<int, int> part;
    for (const GrafcetStep& step : grafcet.steps())
        part[step.number] = find(step.number);
    return part;
}

double monospaceWidth(std::string_view text)
{
    return 7.0 * static_cast<double>(text.size());
}

// Status of a failed precondition, or success, for chaining.
Status require(bool condition, std::string code, std::string message)
{
    return condition ? Status::success() : Status::failure(std::move(code), std::move(message));
}

// Runs an edit on a copy, which replaces the GRAFCET only when it succeeds.
template <typename Edit>
Status onCopy(Grafcet& grafcet, GrafcetCreated* created, Edit edit)
{
    Grafcet work = grafcet;
    GrafcetCreated made;
    if (Status status = edit(work, made); !status)
        return status;
    grafcet = std::move(work);
    if (created)
        *created = std::move(made);
    return Status::success();
}

// Adds a new plain step with the next number.
int addNewStep(Grafcet& grafcet, GrafcetCreated& made)
{
    const int number = grafcet.nextStepNumber();
    grafcet.addStep(plainStep(number));
    made.steps.push_back(number);
    return number;
}

Status addNewTransition(Grafcet& grafcet, std::vector<int> upstream, std::vector<int> downstream,
                        GrafcetCreated& made)
{
    const int number = grafcet.nextTransitionNumber();
    made.transitions.push_back(number);
    return grafcet.addTransition(newTransition(number, std::move(upstream), std::move(downstream)));
}

// Moves the transitions `moved` (in their order) right after `anchor` in the list.
Status placeAfter(Grafcet& grafcet, int anchor, const std::vector<int>& moved)
{
    std::vector<GrafcetTransition> ordered;
    for (const GrafcetTransition& t : grafcet.transitions()) {
        if (contains(moved, t.number))
            continue;
        ordered.push_back(t);
        if (t.number == anchor)
            for (int number : moved)
                ordered.push_back(*grafcet.transition(number));
    }
    return assemble(grafcet.steps(), ordered, grafcet);
}

// The nearest transition below `transition` that closes its simultaneous divergence; 0 for none.
int parallelConvergence(const Grafcet& grafcet, const GrafcetTransition& divergence)
{
    if (divergence.downstream.size() == 1) {
        const auto leaving = grafcet.transitionsFrom(divergence.downstream.front());
        return leaving.size() == 1 && leaving.front()->upstream.size() == 1 ? leaving.front()->number : 0;
    }
    const std::set<int> branches = reachableSteps(grafcet, divergence.downstream, {}, divergence.number);
    std::set<int> seen;
    std::deque<int> queue(divergence.downstream.begin(), divergence.downstream.end());
    std::set<int> visited(queue.begin(), queue.end());
    while (!queue.empty()) {
        const int step = queue.front();
        queue.pop_front();
        for (const GrafcetTransition* t : grafcet.transitionsFrom(step)) {
            if (t->number == divergence.number || !seen.insert(t->number).second)
                continue;
            const bool closes = t->upstream.size() >= 2
                             && std::all_of(t->upstream.begin(), t->upstream.end(),
                                            [&branches](int n) { return branches.count(n) > 0; });
            if (closes)
                return t->number;
            for (int next : t->downstream)
                if (visited.insert(next).second)
                    queue.push_back(next);
        }
    }
    return 0;
}

// The drawing's numbering order: part by part (left to right), then rows, then columns.
template <typename Key>
std::map<int, int> numberingBy(std::vector<std::pair<Key, int>> keyed)
{
    std::sort(keyed.begin(), keyed.end());
    std::map<int, int> mapping;
    int next = 1;
    for (const auto& [key, number] : keyed)
        mapping[number] = next++;
    return mapping;
}

} // namespace

Status insertStepAfterStep(Grafcet& grafcet, int step, GrafcetCreated* created)
{
    if (!grafcet.step(step))
        return unknownStep(step);
    return onCopy(grafcet, created, [step](Grafcet& g, GrafcetCreated& made) {
        const std::vector<int> leaving = numbersOf(g.transitionsFrom(step));
        const int added = addNewStep(g, made);
        if (Status status = redirect(g, leaving, step, {added}, true); !status)
            return status;
        return addNewTransition(g, {step}, {added}, made);
    });
}

Status insertStepBeforeStep(Grafcet& grafcet, int step, GrafcetCreated* created)
{
    if (!grafcet.step(step))
        return unknownStep(step);
    return onCopy(grafcet, created, [step](Grafcet& g, GrafcetCreated& made) {
        const std::vector<int> reaching = numbersOf(g.transitionsTo(step));
        const bool initial = g.step(step)->initial;
        const int added = addNewStep(g, made);
        if (Status status = redirect(g, reaching, step, {added}, false); !status)
            return status;
        if (initial) {
            g.setStepInitial(step, false);
            g.setStepInitial(added, true);
        }
        return addNewTransition(g, {added}, {step}, made);
    });
}

Status insertStepAfterTransition(Grafcet& grafcet, int transition, GrafcetCreated* created)
{
    if (!grafcet.transition(transition))
        return unknownTransition(transition);
    return onCopy(grafcet, created, [transition](Grafcet& g, GrafcetCreated& made) {
        const std::vector<int> downstream = g.transition(transition)->downstream;
        const int added = addNewStep(g, made);
        if (Status status = g.setDownstream(transition, {added}); !status)
            return status;
        return addNewTransition(g, {added}, downstream, made);
    });
}

Status insertStepBeforeTransition(Grafcet& grafcet, int transition, GrafcetCreated* created)
{
    if (!grafcet.transition(transition))
        return unknownTransition(transition);
    return onCopy(grafcet, created, [transition](Grafcet& g, GrafcetCreated& made) {
        const std::vector<int> upstream = g.transition(transition)->upstream;
        const int added = addNewStep(g, made);
        if (Status status = g.setUpstream(transition, {added}); !status)
            return status;
        return addNewTransition(g, upstream, {added}, made);
    });
}

int selectionJoin(const Grafcet& grafcet, int step)
{
    const auto leaving = grafcet.transitionsFrom(step);
    if (leaving.empty())
        return 0;
    struct Reach {
        int branches = 0;
        int farthest = 0; // the longest of the shortest walks from the branches
        int firstSeen = 0;
    };
    std::map<int, Reach> reach;
    int order = 0;
    for (const GrafcetTransition* t : leaving) {
        std::map<int, int> distance;
        std::deque<int> queue;
        for (int d : t->downstream)
            if (d != step && distance.emplace(d, 0).second)
                queue.push_back(d);
        while (!queue.empty()) {
            const int current = queue.front();
            queue.pop_front();
            Reach& r = reach[current];
            if (r.branches++ == 0)
                r.firstSeen = order++;
            r.farthest = std::max(r.farthest, distance[current]);
            for (const GrafcetTransition* next : grafcet.transitionsFrom(current))
                for (int d : next->downstream)
                    if (d != step && distance.emplace(d, distance[current] + 1).second)
                        queue.push_back(d);
        }
    }
    if (reach.empty())
        return step;
    const auto best = std::min_element(reach.begin(), reach.end(), [](const auto& a, const auto& b) {
        return std::tuple(-a.second.branches, a.second.farthest, a.second.firstSeen)
             < std::tuple(-b.second.branches, b.second.farthest, b.second.firstSeen);
    });
    return best->first;
}

Status addBranchEndingOnStep(Grafcet& grafcet, int step, GrafcetCreated* created)
{
    if (!grafcet.step(step))
        return unknownStep(step);
    return onCopy(grafcet, created, [step](Grafcet& g, GrafcetCreated& made) {
        const int added = addNewStep(g, made);
        return addNewTransition(g, {step}, {added}, made);
    });
}

int simultaneousConvergence(const Grafcet& grafcet, int transition)
{
    const GrafcetTransition* t = grafcet.transition(transition);
    return t ? parallelConvergence(grafcet, *t) : 0;
}

Status addSelectionBranchAtStep(Grafcet& grafcet, int step, GrafcetCreated* created)
{
    if (!grafcet.step(step))
        return unknownStep(step);
    const int join = selectionJoin(grafcet, step);
    if (Status status = require(join != 0, "no-branch", "step " + std::to_string(step) + " has no branch to add to");
        !status)
        return status;
    return onCopy(grafcet, created, [step, join](Grafcet& g, GrafcetCreated& made) {
        const int added = addNewStep(g, made);
        if (Status status = addNewTransition(g, {step}, {added}, made); !status)
            return status;
        return addNewTransition(g, {added}, {join}, made);
    });
}

Status addSelectionBranchAtTransition(Grafcet& grafcet, int transition, GrafcetCreated* created)
{
    const GrafcetTransition* t = grafcet.transition(transition);
    if (!t)
        return unknownTransition(transition);
    if (Status status = require(t->upstream.size() == 1, "not-a-selection",
                                "T" + std::to_string(transition) + " does not leave a single step");
        !status)
        return status;
    const int step = t->upstream.front();
    const int join = selectionJoin(grafcet, step);
    return onCopy(grafcet, created, [transition, step, join](Grafcet& g, GrafcetCreated& made) {
        const int added = addNewStep(g, made);
        if (Status status = addNewTransition(g, {step}, {added}, made); !status)
            return status;
        if (Status status = addNewTransition(g, {added}, {join}, made); !status)
            return status;
        return placeAfter(g, transition, made.transitions);
    });
}

Status addParallelBranch(Grafcet& grafcet, int transition, GrafcetCreated* created)
{
    const GrafcetTransition* t = grafcet.transition(transition);
    if (!t)
        return unknownTransition(transition);
    const int convergence = parallelConvergence(grafcet, *t);
    return onCopy(grafcet, created, [transition, convergence](Grafcet& g, GrafcetCreated& made) {
        const int added = addNewStep(g, made);
        std::vector<int> downstream = g.transition(transition)->downstream;
        downstream.push_back(added);
        if (Status status = g.setDownstream(transition, downstream); !status)
            return status;
        if (convergence == 0)
            return Status::success();
        std::vector<int> upstream = g.transition(convergence)->upstream;
        upstream.push_back(added);
        return g.setUpstream(convergence, upstream);
    });
}

Status addJump(Grafcet& grafcet, int fromStep, int toStep, GrafcetCreated* created)
{
    if (!grafcet.step(fromStep))
        return unknownStep(fromStep);
    if (!grafcet.step(toStep))
        return unknownStep(toStep);
    for (const GrafcetTransition* t : grafcet.transitionsFrom(fromStep))
        if (t->upstream == std::vector<int>{fromStep} && t->downstream == std::vector<int>{toStep})
            return Status::failure("duplicate-link", "T" + std::to_string(t->number) + " already leads from step "
                                                         + std::to_string(fromStep) + " to step "
                                                         + std::to_string(toStep));
    return onCopy(grafcet, created, [fromStep, toStep](Grafcet& g, GrafcetCreated& made) {
        return addNewTransition(g, {fromStep}, {toStep}, made);
    });
}

Status removeStepWithRepair(Grafcet& grafcet, int step)
{
    if (!grafcet.step(step))
        return unknownStep(step);
    return onCopy(grafcet, nullptr, [step](Grafcet& g, GrafcetCreated&) {
        const auto leaving = g.transitionsFrom(step);
        const auto reaching = g.transitionsTo(step);
        const bool initial = g.step(step)->initial;
        if (leaving.size() == 1 && leaving.front()->upstream.size() == 1 && !contains(leaving.front()->downstream, step)) {
            const GrafcetTransition outgoing = *leaving.front();
            if (Status status = redirect(g, numbersOf(reaching), step, outgoing.downstream, false); !status)
                return status;
            g.removeTransition(outgoing.number);
            if (initial)
                for (int next : outgoing.downstream)
                    g.setStepInitial(next, true);
        } else if (reaching.size() == 1 && reaching.front()->downstream.size() == 1
                   && !contains(reaching.front()->upstream, step)) {
            const GrafcetTransition incoming = *reaching.front();
            if (Status status = redirect(g, numbersOf(leaving), step, incoming.upstream, true); !status)
                return status;
            g.removeTransition(incoming.number);
        }
        return g.removeStep(step);
    });
}

Status removeSelectionBranch(Grafcet& grafcet, int firstTransition)
{
    const GrafcetTransition* t = grafcet.transition(firstTransition);
    if (!t)
        return unknownTransition(firstTransition);
    const bool branch = t->upstream.size() == 1 && grafcet.transitionsFrom(t->upstream.front()).size() >= 2;
    if (Status status = require(branch, "not-a-branch",
                                "T" + std::to_string(firstTransition) + " is not a branch of a selection");
        !status)
        return status;
    return onCopy(grafcet, nullptr, [firstTransition](Grafcet& g, GrafcetCreated&) {
        const GrafcetTransition removed = *g.transition(firstTransition);
        std::vector<int> others = walkStarts(g);
        others.push_back(removed.upstream.front());
        g.removeTransition(firstTransition);
        return removeCutOff(g, removed.downstream, others);
    });
}

Status removeParallelBranch(Grafcet& grafcet, int firstStep)
{
    if (!grafcet.step(firstStep))
        return unknownStep(firstStep);
    int divergence = 0;
    for (const GrafcetTransition* t : grafcet.transitionsTo(firstStep))
        if (t->downstream.size() >= 2 && divergence == 0)
            divergence = t->number;
    if (Status status = require(divergence != 0, "not-a-branch",
                                "step " + std::to_string(firstStep) + " does not start a parallel branch");
        !status)
        return status;
    return onCopy(grafcet, nullptr, [firstStep, divergence](Grafcet& g, GrafcetCreated&) {
        std::vector<int> others;
        for (int root : walkStarts(g))
            if (root != firstStep)
                others.push_back(root);
        const std::vector<int>& upstream = g.transition(divergence)->upstream;
        others.insert(others.end(), upstream.begin(), upstream.end());
        std::vector<int> downstream = g.transition(divergence)->downstream;
        std::erase(downstream, firstStep);
        if (Status status = g.setDownstream(divergence, downstream); !status)
            return status;
        return removeCutOff(g, {firstStep}, others);
    });
}

Status renumberAll(Grafcet& grafcet)
{
    return onCopy(grafcet, nullptr, [](Grafcet& g, GrafcetCreated&) {
        const GrafcetLayout layout = layoutGrafcet(g, monospaceWidth);
        const std::map<int, int> part = parts(g);
        std::map<int, double> partLeft; // the left of each part's drawing
        for (const GrafcetStepLayout& step : layout.steps) {
            const double left = step.box.left();
            const auto [it, inserted] = partLeft.emplace(part.at(step.number), left);
            if (!inserted)
                it->second = std::min(it->second, left);
        }
        using Key = std::tuple<double, int, double, double>;
        std::vector<std::pair<Key, int>> steps;
        for (const GrafcetStepLayout& step : layout.steps) {
            const int p = part.at(step.number);
            steps.push_back({{partLeft[p], p, step.box.top(), step.box.left()}, step.number});
        }
        std::vector<std::pair<Key, int>> transitions;
        for (const GrafcetTransitionLayout& t : layout.transitions) {
            const int p = part.at(g.transition(t.number)->upstream.front());
            transitions.push_back({{partLeft[p], p, t.barCenter.y, t.barCenter.x}, t.number});
        }
        if (Status status = renumberSteps(g, numberingBy(steps)); !status)
            return status;
        return renumberTransitions(g, numberingBy(transitions));
    });
}

Status connectDirectly(Grafcet& grafcet, int transition, std::vector<int> upstream, std::vector<int> downstream)
{
    if (!grafcet.transition(transition))
        return unknownTransition(transition);
    return onCopy(grafcet, nullptr, [&](Grafcet& g, GrafcetCreated&) {
        if (Status status = g.setUpstream(transition, std::move(upstream)); !status)
            return status;
        return g.setDownstream(transition, std::move(downstream));
    });
}

GrafcetFragment copyFragment(const Grafcet& grafcet, const std::vector<int>& steps)
{
    GrafcetFragment fragment;
    std::set<int> copied;
    for (const GrafcetStep& step : grafcet.steps())
        if (contains(steps, step.number) && copied.insert(step.number).second)
            fragment.steps.push_back(step);
    const auto inside = [&copied](const std::vector<int>& set) {
        return std::all_of(set.begin(), set.end(), [&copied](int n) { return copied.count(n) > 0; });
    };
    for (const GrafcetTransition& t : grafcet.transitions())
        if (inside(t.upstream) && inside(t.downstream))
            fragment.transitions.push_back(t);
    return fragment;
}

Status pasteFragment(Grafcet& grafcet, const GrafcetFragment& fragment, int afterStep, GrafcetCreated* created)
{
    if (fragment.empty())
        return Status::failure("empty-fragment", "there is nothing to paste");
    if (afterStep != 0 && !grafcet.step(afterStep))
        return unknownStep(afterStep);
    Grafcet pasted;
    if (Status status = assemble(fragment.steps, fragment.transitions, pasted); !status)
        return status;
    // Fresh numbers in the order of the old ones, so that 2, 3, 4 become 7, 8, 9.
    std::vector<int> old;
    for (const GrafcetStep& step : pasted.steps())
        old.push_back(step.number);
    std::sort(old.begin(), old.end());
    std::map<int, int> stepNumbers;
    for (int n : old)
        stepNumbers[n] = grafcet.nextStepNumber() + static_cast<int>(stepNumbers.size());
    if (Status status = renumberSteps(pasted, stepNumbers); !status)
        return status;
    std::map<int, int> transitionNumbers;
    for (const GrafcetTransition& t : pasted.transitions())
        transitionNumbers[t.number] = grafcet.nextTransitionNumber() + static_cast<int>(transitionNumbers.size());
    if (Status status = renumberTransitions(pasted, transitionNumbers); !status)
        return status;
    const std::vector<int> entries = fragmentEnds(pasted, true);
    const std::vector<int> exits = fragmentEnds(pasted, false);
    if (afterStep != 0)
        if (Status status = require(entries.size() == 1 && exits.size() == 1, "not-a-sequence",
                                    "only one sequence with one first and one last step can be pasted after a step");
            !status)
            return status;
    return onCopy(grafcet, created, [&](Grafcet& g, GrafcetCreated& made) {
        const std::vector<int> leaving = afterStep != 0 ? numbersOf(g.transitionsFrom(afterStep)) : std::vector<int>{};
        for (GrafcetStep step : pasted.steps()) {
            step.initial = false;
            made.steps.push_back(step.number);
            if (Status status = g.addStep(std::move(step)); !status)
                return status;
        }
        for (const GrafcetTransition& t : pasted.transitions()) {
            made.transitions.push_back(t.number);
            if (Status status = g.addTransition(t); !status)
                return status;
        }
        if (afterStep == 0)
            return Status::success();
        if (Status status = redirect(g, leaving, afterStep, exits, true); !status)
            return status;
        return addNewTransition(g, {afterStep}, entries, made);
    });
}

Grafcet usualGrafcet()
{
    Grafcet grafcet;
    GrafcetStep first = plainStep(1);
    first.initial = true;
    grafcet.addStep(std::move(first));
    grafcet.addStep(plainStep(2));
    GrafcetStep exit = plainStep(3);
    exit.actions.push_back({ActionTiming::OnActivation, "S Complete"});
    grafcet.addStep(std::move(exit));
    grafcet.addTransition(newTransition(1, {1}, {2}));
    grafcet.addTransition(newTransition(2, {2}, {3}));
    return grafcet;
}

} // namespace core
