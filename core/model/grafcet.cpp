#include "core/model/grafcet.h"

#include "core/condition/conditionparser.h"
#include "core/model/grafcetnumbers.h"

#include <algorithm>
#include <set>

namespace core {

namespace {

using grafcetnumbers::contains;
using grafcetnumbers::stepName;
using grafcetnumbers::unknownStep;
using grafcetnumbers::unknownTransition;

std::string namedTransition(int number)
{
    return "transition " + grafcetnumbers::transitionLabel(number);
}

Status badNumber(int number)
{
    return Status::failure("invalid-number", "numbers start at 1, not " + std::to_string(number));
}

std::string activity(int number)
{
    return "X" + std::to_string(number);
}

// Rewrites one text, reporting whether it changed.
bool rewrite(std::string& text, std::string_view oldName, std::string_view newName)
{
    std::string renamed = cond::renameIdentifier(text, oldName, newName, {cond::Context::Nested});
    if (renamed == text)
        return false;
    text = std::move(renamed);
    return true;
}

bool actionIndexValid(const GrafcetStep& step, int index)
{
    return index >= 0 && static_cast<std::size_t>(index) < step.actions.size();
}

Status badActionIndex(int stepNumber, int index)
{
    return Status::failure("invalid-action", stepName(stepNumber) + " has no action " + std::to_string(index + 1));
}

} // namespace

const GrafcetStep* Grafcet::step(int number) const
{
    const auto found = std::find_if(m_steps.begin(), m_steps.end(),
                                    [number](const GrafcetStep& s) { return s.number == number; });
    return found == m_steps.end() ? nullptr : &*found;
}

const GrafcetTransition* Grafcet::transition(int number) const
{
    const auto found = std::find_if(m_transitions.begin(), m_transitions.end(),
                                    [number](const GrafcetTransition& t) { return t.number == number; });
    return found == m_transitions.end() ? nullptr : &*found;
}

GrafcetStep* Grafcet::mutableStep(int number)
{
    return const_cast<GrafcetStep*>(step(number));
}

GrafcetTransition* Grafcet::mutableTransition(int number)
{
    return const_cast<GrafcetTransition*>(transition(number));
}

std::vector<int> Grafcet::initialSteps() const
{
    std::vector<int> numbers;
    for (const GrafcetStep& s : m_steps)
        if (s.initial)
            numbers.push_back(s.number);
    return numbers;
}

std::vector<const GrafcetTransition*> Grafcet::transitionsFrom(int stepNumber) const
{
    std::vector<const GrafcetTransition*> found;
    for (const GrafcetTransition& t : m_transitions)
        if (contains(t.upstream, stepNumber))
            found.push_back(&t);
    return found;
}

std::vector<const GrafcetTransition*> Grafcet::transitionsTo(int stepNumber) const
{
    std::vector<const GrafcetTransition*> found;
    for (const GrafcetTransition& t : m_transitions)
        if (contains(t.downstream, stepNumber))
            found.push_back(&t);
    return found;
}

int Grafcet::nextStepNumber() const
{
    int largest = 0;
    for (const GrafcetStep& s : m_steps)
        largest = std::max(largest, s.number);
    return largest + 1;
}

int Grafcet::nextTransitionNumber() const
{
    int largest = 0;
    for (const GrafcetTransition& t : m_transitions)
        largest = std::max(largest, t.number);
    return largest + 1;
}

Status Grafcet::addStep(GrafcetStep newStep)
{
    if (newStep.number < 1)
        return badNumber(newStep.number);
    if (step(newStep.number))
        return Status::failure("duplicate-step", "the GRAFCET already has a " + stepName(newStep.number));
    beginChanges();
    const int number = newStep.number;
    m_steps.push_back(std::move(newStep));
    changed(GrafcetChange::Kind::StepList);
    changed(GrafcetChange::Kind::Step, number);
    return Status::success();
}

Status Grafcet::removeStep(int number)
{
    if (!step(number))
        return unknownStep(number);
    beginChanges();
    std::erase_if(m_steps, [number](const GrafcetStep& s) { return s.number == number; });
    bool transitionRemoved = false;
    for (auto t = m_transitions.begin(); t != m_transitions.end();) {
        const bool touched = contains(t->upstream, number) || contains(t->downstream, number);
        std::erase(t->upstream, number);
        std::erase(t->downstream, number);
        if (t->upstream.empty() || t->downstream.empty()) {
            t = m_transitions.erase(t);
            transitionRemoved = true;
            continue;
        }
        if (touched)
            changed(GrafcetChange::Kind::Transition, t->number);
        ++t;
    }
    changed(GrafcetChange::Kind::StepList);
    if (transitionRemoved)
        changed(GrafcetChange::Kind::TransitionList);
    return Status::success();
}

Status Grafcet::renumberStep(int number, int newNumber)
{
    GrafcetStep* s = mutableStep(number);
    if (!s)
        return unknownStep(number);
    if (newNumber < 1)
        return badNumber(newNumber);
    if (newNumber == number)
        return Status::success();
    if (step(newNumber))
        return Status::failure("duplicate-step", "the GRAFCET already has a " + stepName(newNumber));
    beginChanges();
    s->number = newNumber;
    changed(GrafcetChange::Kind::StepList);
    changed(GrafcetChange::Kind::Step, newNumber);
    const std::string oldActivity = activity(number);
    const std::string newActivity = activity(newNumber);
    for (GrafcetTransition& t : m_transitions) {
        bool touched = false;
        for (std::vector<int>* set : {&t.upstream, &t.downstream})
            for (int& n : *set)
                if (n == number) {
                    n = newNumber;
                    touched = true;
                }
        touched = rewrite(t.receptivity, oldActivity, newActivity) || touched;
        if (touched)
            changed(GrafcetChange::Kind::Transition, t.number);
    }
    for (GrafcetStep& other : m_steps) {
        bool touched = false;
        for (GrafcetAction& action : other.actions)
            touched = rewrite(action.text, oldActivity, newActivity) || touched;
        if (touched && other.number != newNumber)
            changed(GrafcetChange::Kind::Step, other.number);
    }
    return Status::success();
}

Status Grafcet::setStepInitial(int number, bool initial)
{
    GrafcetStep* s = mutableStep(number);
    if (!s)
        return unknownStep(number);
    beginChanges();
    if (s->initial != initial) {
        s->initial = initial;
        changed(GrafcetChange::Kind::Step, number);
    }
    return Status::success();
}

Status Grafcet::setInitialSteps(const std::vector<int>& numbers)
{
    for (int number : numbers)
        if (!step(number))
            return unknownStep(number);
    beginChanges();
    for (GrafcetStep& s : m_steps) {
        const bool initial = contains(numbers, s.number);
        if (s.initial != initial) {
            s.initial = initial;
            changed(GrafcetChange::Kind::Step, s.number);
        }
    }
    return Status::success();
}

Status Grafcet::setStepComment(int number, std::string comment)
{
    GrafcetStep* s = mutableStep(number);
    if (!s)
        return unknownStep(number);
    beginChanges();
    if (s->comment != comment) {
        s->comment = std::move(comment);
        changed(GrafcetChange::Kind::Step, number);
    }
    return Status::success();
}

Status Grafcet::addAction(int stepNumber, GrafcetAction action, int index)
{
    GrafcetStep* s = mutableStep(stepNumber);
    if (!s)
        return unknownStep(stepNumber);
    if (index == -1)
        index = static_cast<int>(s->actions.size());
    if (index < 0 || static_cast<std::size_t>(index) > s->actions.size())
        return badActionIndex(stepNumber, index);
    beginChanges();
    s->actions.insert(s->actions.begin() + index, std::move(action));
    changed(GrafcetChange::Kind::Step, stepNumber);
    return Status::success();
}

Status Grafcet::setAction(int stepNumber, int index, GrafcetAction action)
{
    GrafcetStep* s = mutableStep(stepNumber);
    if (!s)
        return unknownStep(stepNumber);
    if (!actionIndexValid(*s, index))
        return badActionIndex(stepNumber, index);
    beginChanges();
    GrafcetAction& current = s->actions[static_cast<std::size_t>(index)];
    if (!(current == action)) {
        current = std::move(action);
        changed(GrafcetChange::Kind::Step, stepNumber);
    }
    return Status::success();
}

Status Grafcet::removeAction(int stepNumber, int index)
{
    GrafcetStep* s = mutableStep(stepNumber);
    if (!s)
        return unknownStep(stepNumber);
    if (!actionIndexValid(*s, index))
        return badActionIndex(stepNumber, index);
    beginChanges();
    s->actions.erase(s->actions.begin() + index);
    changed(GrafcetChange::Kind::Step, stepNumber);
    return Status::success();
}

Status Grafcet::moveAction(int stepNumber, int from, int to)
{
    GrafcetStep* s = mutableStep(stepNumber);
    if (!s)
        return unknownStep(stepNumber);
    if (!actionIndexValid(*s, from))
        return badActionIndex(stepNumber, from);
    if (!actionIndexValid(*s, to))
        return badActionIndex(stepNumber, to);
    beginChanges();
    if (from == to)
        return Status::success();
    GrafcetAction moved = std::move(s->actions[static_cast<std::size_t>(from)]);
    s->actions.erase(s->actions.begin() + from);
    s->actions.insert(s->actions.begin() + to, std::move(moved));
    changed(GrafcetChange::Kind::Step, stepNumber);
    return Status::success();
}

Status Grafcet::checkStepSet(const std::vector<int>& steps, std::string_view which) const
{
    if (steps.empty())
        return Status::failure("empty-" + std::string(which),
                               "a transition needs at least one " + std::string(which) + " step");
    std::set<int> seen;
    for (int number : steps) {
        if (!step(number))
            return unknownStep(number);
        if (!seen.insert(number).second)
            return Status::failure("repeated-step",
                                   stepName(number) + " is named twice among the " + std::string(which) + " steps");
    }
    return Status::success();
}

Status Grafcet::addTransition(GrafcetTransition newTransition)
{
    if (newTransition.number < 1)
        return badNumber(newTransition.number);
    if (transition(newTransition.number))
        return Status::failure("duplicate-transition",
                               "the GRAFCET already has a " + namedTransition(newTransition.number));
    if (Status status = checkStepSet(newTransition.upstream, "upstream"); !status)
        return status;
    if (Status status = checkStepSet(newTransition.downstream, "downstream"); !status)
        return status;
    beginChanges();
    const int number = newTransition.number;
    m_transitions.push_back(std::move(newTransition));
    changed(GrafcetChange::Kind::TransitionList);
    changed(GrafcetChange::Kind::Transition, number);
    return Status::success();
}

Status Grafcet::removeTransition(int number)
{
    if (!transition(number))
        return unknownTransition(number);
    beginChanges();
    std::erase_if(m_transitions, [number](const GrafcetTransition& t) { return t.number == number; });
    changed(GrafcetChange::Kind::TransitionList);
    return Status::success();
}

Status Grafcet::setUpstream(int number, std::vector<int> steps)
{
    return setStepSet(number, std::move(steps), &GrafcetTransition::upstream, "upstream");
}

Status Grafcet::setDownstream(int number, std::vector<int> steps)
{
    return setStepSet(number, std::move(steps), &GrafcetTransition::downstream, "downstream");
}

Status Grafcet::setStepSet(int number, std::vector<int> steps, std::vector<int> GrafcetTransition::*set,
                           std::string_view which)
{
    GrafcetTransition* t = mutableTransition(number);
    if (!t)
        return unknownTransition(number);
    if (Status status = checkStepSet(steps, which); !status)
        return status;
    beginChanges();
    if (t->*set != steps) {
        t->*set = std::move(steps);
        changed(GrafcetChange::Kind::Transition, number);
    }
    return Status::success();
}

Status Grafcet::setReceptivity(int number, std::string receptivity)
{
    GrafcetTransition* t = mutableTransition(number);
    if (!t)
        return unknownTransition(number);
    beginChanges();
    if (t->receptivity != receptivity) {
        t->receptivity = std::move(receptivity);
        changed(GrafcetChange::Kind::Transition, number);
    }
    return Status::success();
}

void Grafcet::renameIdentifier(std::string_view oldName, std::string_view newName,
                               std::vector<int>& changedSteps, std::vector<int>& changedTransitions)
{
    for (GrafcetTransition& t : m_transitions)
        if (rewrite(t.receptivity, oldName, newName))
            changedTransitions.push_back(t.number);
    for (GrafcetStep& s : m_steps) {
        bool touched = false;
        for (GrafcetAction& action : s.actions)
            touched = rewrite(action.text, oldName, newName) || touched;
        if (touched)
            changedSteps.push_back(s.number);
    }
}

std::vector<std::string> Grafcet::invariantViolations() const
{
    std::vector<std::string> violations;
    std::set<int> stepNumbers;
    for (const GrafcetStep& s : m_steps) {
        if (s.number < 1)
            violations.push_back(stepName(s.number) + ": numbers start at 1");
        if (!stepNumbers.insert(s.number).second)
            violations.push_back(stepName(s.number) + " appears twice");
    }
    std::set<int> transitionNumbers;
    for (const GrafcetTransition& t : m_transitions) {
        const std::string name = namedTransition(t.number);
        if (t.number < 1)
            violations.push_back(name + ": numbers start at 1");
        if (!transitionNumbers.insert(t.number).second)
            violations.push_back(name + " appears twice");
        for (const auto& [set, which] : {std::pair{&t.upstream, "upstream"}, std::pair{&t.downstream, "downstream"}}) {
            if (set->empty())
                violations.push_back(name + " has no " + which + " step");
            std::set<int> seen;
            for (int number : *set) {
                if (!stepNumbers.count(number))
                    violations.push_back(name + ": " + which + " " + stepName(number) + " does not exist");
                if (!seen.insert(number).second)
                    violations.push_back(name + ": " + which + " " + stepName(number) + " is named twice");
            }
        }
    }
    return violations;
}

bool Grafcet::sameContent(const Grafcet& other) const
{
    return m_steps == other.m_steps && m_transitions == other.m_transitions;
}

} // namespace core
