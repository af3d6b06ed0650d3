#include "core/model/grafcetlinking.h"

#include "core/model/grafcetnumbers.h"
#include <algorithm>
#include <string>

namespace core {

namespace {

using grafcetnumbers::contains;
using grafcetnumbers::stepName;
using grafcetnumbers::transitionLabel;

Status refuse(std::string_view code, std::string message)
{
    return Status::failure(std::string(code), std::move(message));
}

// Step onto transition (stepIsUpstream) or transition onto step.
Status checkStepTransition(const Grafcet& grafcet, int step, int transition, bool stepIsUpstream)
{
    const GrafcetTransition* t = grafcet.transition(transition);
    if (!grafcet.step(step) || !t)
        return refuse(kLinkUnknownElement, "no such step or transition");
    const std::vector<int>& joined = stepIsUpstream ? t->upstream : t->downstream;
    const std::vector<int>& other = stepIsUpstream ? t->downstream : t->upstream;
    if (contains(joined, step))
        return refuse(kLinkExists, stepName(step) + (stepIsUpstream ? " already precedes " : " already follows ")
                                       + transitionLabel(transition));
    if (contains(other, step))
        return refuse(kLinkStepToItself, stepName(step) + " would be linked to itself through "
                                             + transitionLabel(transition));
    return Status::success();
}

Status checkStepStep(const Grafcet& grafcet, int from, int to)
{
    if (!grafcet.step(from) || !grafcet.step(to))
        return refuse(kLinkUnknownElement, "no such step");
    if (from == to)
        return refuse(kLinkStepToItself, stepName(from) + " would be linked to itself through one transition");
    for (const GrafcetTransition* t : grafcet.transitionsFrom(from))
        if (contains(t->downstream, to))
            return refuse(kLinkExists, transitionLabel(t->number) + " already leads from " + stepName(from) + " to "
                                           + stepName(to));
    return Status::success();
}

} // namespace

Status checkLink(const Grafcet& grafcet, GrafcetLinkEnd from, GrafcetLinkEnd to)
{
    if (from.isStep() && to.isStep())
        return checkStepStep(grafcet, from.number, to.number);
    if (from.isStep())
        return checkStepTransition(grafcet, from.number, to.number, true);
    if (to.isStep())
        return checkStepTransition(grafcet, to.number, from.number, false);
    return refuse(kLinkTransitionToTransition,
                  "a transition cannot follow a transition: steps and transitions alternate");
}

Status link(Grafcet& grafcet, GrafcetLinkEnd from, GrafcetLinkEnd to, GrafcetCreated* created)
{
    if (Status status = checkLink(grafcet, from, to); !status)
        return status;
    if (from.isStep() && to.isStep())
        return addJump(grafcet, from.number, to.number, created);
    const int step = from.isStep() ? from.number : to.number;
    const GrafcetTransition& transition = *grafcet.transition(from.isStep() ? to.number : from.number);
    if (from.isStep()) {
        std::vector<int> upstream = transition.upstream;
        upstream.push_back(step);
        return grafcet.setUpstream(transition.number, std::move(upstream));
    }
    std::vector<int> downstream = transition.downstream;
    downstream.push_back(step);
    return grafcet.setDownstream(transition.number, std::move(downstream));
}

} // namespace core
