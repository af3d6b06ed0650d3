#include "core/model/model.h"

#include "core/condition/conditionparser.h"
#include "core/templates/packml/packmlmodel.h"

#include <algorithm>
#include <stdexcept>
#include <set>

namespace core {

namespace {

Status unknownStep(std::string_view id)
{
    return Status::failure("unknown-step", "there is no step '" + std::string(id) + "' in the GEMMA template");
}

Status unknownTransition(std::string_view id)
{
    return Status::failure("unknown-transition",
                           "there is no transition '" + std::string(id) + "' in the GEMMA template");
}

Status unknownVariable(std::string_view name)
{
    return Status::failure("unknown-variable", "there is no variable '" + std::string(name) + "'");
}

Status noGrafcet(std::string_view stepId)
{
    return Status::failure("no-grafcet", "step " + std::string(stepId) + " has no nested GRAFCET");
}

bool containsIgnoreCase(const std::vector<std::string>& names, std::string_view name)
{
    return std::any_of(names.begin(), names.end(),
                       [&](const std::string& candidate) { return equalsIgnoreCase(candidate, name); });
}

} // namespace

std::string_view dialectName(Dialect dialect)
{
    return dialect == Dialect::Codesys ? "codesys" : "iec";
}

bool parseDialect(std::string_view name, Dialect& dialect)
{
    if (equalsIgnoreCase(name, "iec")) {
        dialect = Dialect::Iec;
        return true;
    }
    if (equalsIgnoreCase(name, "codesys")) {
        dialect = Dialect::Codesys;
        return true;
    }
    return false;
}

std::string_view variableKindName(VariableKind kind)
{
    switch (kind) {
    case VariableKind::Output: return "output";
    case VariableKind::Internal: return "internal";
    case VariableKind::Input: break;
    }
    return "input";
}

bool parseVariableKind(std::string_view name, VariableKind& kind)
{
    for (VariableKind candidate : {VariableKind::Input, VariableKind::Output, VariableKind::Internal}) {
        if (name == variableKindName(candidate)) {
            kind = candidate;
            return true;
        }
    }
    return false;
}

std::string_view evolutionRuleName(EvolutionRule rule)
{
    return rule == EvolutionRule::UntilStable ? "until-stable" : "one-per-scan";
}

bool parseEvolutionRule(std::string_view name, EvolutionRule& rule)
{
    for (EvolutionRule candidate : {EvolutionRule::OneEvolutionPerScan, EvolutionRule::UntilStable}) {
        if (name == evolutionRuleName(candidate)) {
            rule = candidate;
            return true;
        }
    }
    return false;
}

Model::Model()
{
    for (const TemplateState& state : templateStates()) {
        Step step;
        step.id = state.id;
        step.number = state.number;
        step.family = state.family;
        step.type = state.defaultType;
        step.initial = state.defaultInitial;
        m_steps.push_back(std::move(step));
    }
    for (const TemplateTransition& t : templateTransitions()) {
        Transition transition;
        transition.id = makeTransitionId(t.source, t.target);
        transition.source = t.source;
        transition.target = t.target;
        transition.order = t.defaultPriority;
        transition.negated = t.defaultNegated;
        m_transitions.push_back(std::move(transition));
    }
}

Model::Model(const Model& other)
    : m_steps(other.m_steps)
    , m_transitions(other.m_transitions)
    , m_variables(other.m_variables)
    , m_grafcets(other.m_grafcets)
    , m_settings(other.m_settings)
    , m_properties(other.m_properties)
    , m_packml(other.m_packml)
    , m_machine(other.m_machine)
{
}

Model::Model(packml::Configuration configuration)
    : m_packml(std::move(configuration))
{
    m_settings.name = std::string(packml::kDefaultProgramName);
}

// ---- queries ---------------------------------------------------------------

const Step* Model::step(std::string_view id) const
{
    auto found = std::find_if(m_steps.begin(), m_steps.end(), [&](const Step& s) { return s.id == id; });
    return found == m_steps.end() ? nullptr : &*found;
}

const Transition* Model::transition(std::string_view id) const
{
    auto found = std::find_if(m_transitions.begin(), m_transitions.end(),
                              [&](const Transition& t) { return t.id == id; });
    return found == m_transitions.end() ? nullptr : &*found;
}

const Variable* Model::variable(std::string_view name) const
{
    int index = variableIndex(name);
    return index < 0 ? nullptr : &m_variables[static_cast<std::size_t>(index)];
}

int Model::variableIndex(std::string_view name) const
{
    for (std::size_t i = 0; i < m_variables.size(); ++i) {
        if (equalsIgnoreCase(m_variables[i].name, name))
            return static_cast<int>(i);
    }
    return -1;
}

const Step& Model::initialStep() const
{
    auto found = std::find_if(m_steps.begin(), m_steps.end(), [](const Step& s) { return s.initial; });
    // A GEMMA model's invariant guarantees exactly one; a PackML model has
    // none, and asking is a programming error, not undefined behaviour.
    if (found == m_steps.end())
        throw std::logic_error("Model::initialStep: a PackML model has no GEMMA steps");
    return *found;
}

bool Model::isEffective(const Transition& transition) const
{
    if (transition.hidden)
        return false;
    const Step* target = step(transition.target);
    if (!target || target->hidden)
        return false;
    if (transition.isFamilyTransition())
        return true; // the F frame itself is always shown
    const Step* source = step(transition.source);
    return source && !source->hidden;
}

bool Model::isEffective(std::string_view transitionId) const
{
    const Transition* t = transition(transitionId);
    return t && isEffective(*t);
}

std::vector<const Transition*> Model::outgoing(std::string_view source) const
{
    std::vector<const Transition*> result;
    for (const Transition& t : m_transitions) {
        if (t.source == source)
            result.push_back(&t);
    }
    std::stable_sort(result.begin(), result.end(),
                     [](const Transition* a, const Transition* b) { return a->order < b->order; });
    return result;
}

std::vector<const Transition*> Model::effectiveOutgoing(std::string_view source) const
{
    std::vector<const Transition*> result = outgoing(source);
    std::erase_if(result, [this](const Transition* t) { return !isEffective(*t); });
    return result;
}

std::vector<const Transition*> Model::incoming(std::string_view target) const
{
    std::vector<const Transition*> result;
    for (const Transition& t : m_transitions) {
        if (t.target == target)
            result.push_back(&t);
    }
    return result;
}

int Model::priority(std::string_view transitionId) const
{
    const Transition* t = transition(transitionId);
    if (!t || !isEffective(*t))
        return 0;
    int rank = 0;
    for (const Transition* candidate : effectiveOutgoing(t->source)) {
        ++rank;
        if (candidate == t)
            return rank;
    }
    return 0;
}

const Grafcet* Model::grafcet(std::string_view stepId) const
{
    const auto found = m_grafcets.find(stepId);
    return found == m_grafcets.end() ? nullptr : &found->second;
}

const Grafcet* Model::effectiveGrafcet(std::string_view stepId) const
{
    if (m_packml)
        return effectivePackMLGrafcet(stepId);
    const Step* s = step(stepId);
    if (!s || s->hidden || s->type == StepType::Simple)
        return nullptr;
    return grafcet(stepId);
}

// ---- nested GRAFCETs ---------------------------------------------------------

Status Model::setGrafcet(std::string_view stepId, Grafcet grafcet)
{
    if (!ownsGrafcetKey(stepId))
        return unknownGrafcetOwner(stepId);
    if (const std::vector<std::string> problems = grafcet.invariantViolations(); !problems.empty())
        return Status::failure("invalid-grafcet", "the GRAFCET of " + std::string(stepId) + " is invalid: " + problems.front());
    const auto found = m_grafcets.find(stepId);
    if (found != m_grafcets.end() && found->second.sameContent(grafcet))
        return Status::success();
    m_grafcets.insert_or_assign(std::string(stepId), std::move(grafcet));
    notifyGrafcet(stepId, {});
    if (m_packml) {
        const auto [mode, state] = *packml::parseGrafcetKey(stepId);
        packml::GrafcetChoice& choice = mutableMode(mode)->grafcets[static_cast<std::size_t>(state)];
        if (choice != packml::GrafcetChoice::own()) {
            choice = packml::GrafcetChoice::own();
            notify(ModelChange::Kind::PackMLMode, std::to_string(mode));
        }
    }
    return Status::success();
}

Status Model::removeGrafcet(std::string_view stepId)
{
    const auto found = m_grafcets.find(stepId);
    if (found == m_grafcets.end())
        return ownsGrafcetKey(stepId) ? noGrafcet(stepId) : unknownGrafcetOwner(stepId);
    m_grafcets.erase(found);
    notifyGrafcet(stepId, {});
    if (m_packml) {
        const auto [mode, state] = *packml::parseGrafcetKey(stepId);
        mutableMode(mode)->grafcets[static_cast<std::size_t>(state)] = packml::GrafcetChoice::none();
        notify(ModelChange::Kind::PackMLMode, std::to_string(mode));
    }
    return Status::success();
}

template <typename Edit>
Status Model::editGrafcet(std::string_view stepId, Edit edit)
{
    const auto found = m_grafcets.find(stepId);
    if (found == m_grafcets.end())
        return ownsGrafcetKey(stepId) ? noGrafcet(stepId) : unknownGrafcetOwner(stepId);
    Status status = edit(found->second);
    if (status.ok && !found->second.lastChanges().empty())
        notifyGrafcet(stepId, found->second.lastChanges());
    return status;
}

Status Model::addGrafcetStep(std::string_view stepId, GrafcetStep newStep)
{
    if (m_packml) // an Own choice always has its GRAFCET
        return editGrafcet(stepId, [&](Grafcet& g) { return g.addStep(std::move(newStep)); });
    const Step* s = step(stepId);
    if (!s)
        return unknownStep(stepId);
    if (!grafcet(stepId)) {
        if (s->type == StepType::Simple)
            return Status::failure("simple-step", "step " + s->id +
                                                      " is a simple step: make it a macro-step or an enclosing step "
                                                      "to give it a nested GRAFCET");
        Grafcet created;
        if (Status status = created.addStep(std::move(newStep)); !status)
            return status;
        m_grafcets.emplace(std::string(stepId), std::move(created));
        notifyGrafcet(stepId, {});
        return Status::success();
    }
    return editGrafcet(stepId, [&](Grafcet& g) { return g.addStep(std::move(newStep)); });
}

Status Model::removeGrafcetStep(std::string_view stepId, int number)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.removeStep(number); });
}

Status Model::renumberGrafcetStep(std::string_view stepId, int number, int newNumber)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.renumberStep(number, newNumber); });
}

Status Model::setGrafcetStepInitial(std::string_view stepId, int number, bool initial)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setStepInitial(number, initial); });
}

Status Model::setGrafcetInitialSteps(std::string_view stepId, const std::vector<int>& numbers)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setInitialSteps(numbers); });
}

Status Model::setGrafcetStepComment(std::string_view stepId, int number, std::string comment)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setStepComment(number, std::move(comment)); });
}

Status Model::addGrafcetAction(std::string_view stepId, int stepNumber, GrafcetAction action, int index)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.addAction(stepNumber, std::move(action), index); });
}

Status Model::setGrafcetAction(std::string_view stepId, int stepNumber, int index, GrafcetAction action)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setAction(stepNumber, index, std::move(action)); });
}

Status Model::removeGrafcetAction(std::string_view stepId, int stepNumber, int index)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.removeAction(stepNumber, index); });
}

Status Model::moveGrafcetAction(std::string_view stepId, int stepNumber, int from, int to)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.moveAction(stepNumber, from, to); });
}

Status Model::addGrafcetTransition(std::string_view stepId, GrafcetTransition newTransition)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.addTransition(std::move(newTransition)); });
}

Status Model::removeGrafcetTransition(std::string_view stepId, int number)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.removeTransition(number); });
}

Status Model::setGrafcetUpstream(std::string_view stepId, int number, std::vector<int> steps)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setUpstream(number, std::move(steps)); });
}

Status Model::setGrafcetDownstream(std::string_view stepId, int number, std::vector<int> steps)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setDownstream(number, std::move(steps)); });
}

Status Model::setReceptivity(std::string_view stepId, int number, std::string receptivity)
{
    return editGrafcet(stepId, [&](Grafcet& g) { return g.setReceptivity(number, std::move(receptivity)); });
}

// ---- steps -------------------------------------------------------------------

Status Model::setStepType(std::string_view stepId, StepType type)
{
    Step* s = mutableStep(stepId);
    if (!s)
        return unknownStep(stepId);
    if (s->type != type) {
        s->type = type;
        notify(ModelChange::Kind::Step, s->id);
    }
    return Status::success();
}

Status Model::setInitialStep(std::string_view stepId)
{
    Step* s = mutableStep(stepId);
    if (!s)
        return unknownStep(stepId);
    if (s->initial)
        return Status::success();
    // Change both steps before telling anyone, so that observers never see a
    // model without exactly one initial step.
    std::vector<std::string> previous;
    for (Step& other : m_steps) {
        if (other.initial) {
            other.initial = false;
            previous.push_back(other.id);
        }
    }
    s->initial = true;
    for (const std::string& id : previous)
        notify(ModelChange::Kind::Step, id);
    notify(ModelChange::Kind::Step, s->id);
    return Status::success();
}

Status Model::setStepHidden(std::string_view stepId, bool hidden)
{
    Step* s = mutableStep(stepId);
    if (!s)
        return unknownStep(stepId);
    if (s->hidden != hidden) {
        s->hidden = hidden;
        notify(ModelChange::Kind::Step, s->id);
    }
    return Status::success();
}

Status Model::setStepComment(std::string_view stepId, std::string comment)
{
    Step* s = mutableStep(stepId);
    if (!s)
        return unknownStep(stepId);
    if (s->comment != comment) {
        s->comment = std::move(comment);
        notify(ModelChange::Kind::Step, s->id);
    }
    return Status::success();
}

// ---- transitions -------------------------------------------------------------

Status Model::setTransitionHidden(std::string_view transitionId, bool hidden)
{
    Transition* t = mutableTransition(transitionId);
    if (!t)
        return unknownTransition(transitionId);
    if (t->hidden != hidden) {
        t->hidden = hidden;
        notify(ModelChange::Kind::Transition, t->id);
    }
    return Status::success();
}

Status Model::setPriority(std::string_view transitionId, int newPriority)
{
    Transition* t = mutableTransition(transitionId);
    if (!t)
        return unknownTransition(transitionId);
    if (!isEffective(*t))
        return Status::failure("not-effective", "transition " + t->id +
                                                    " is not effective (it or one of its steps is hidden), "
                                                    "so it has no priority");
    std::vector<Transition*> ordered = mutableOutgoing(t->source);
    std::vector<Transition*> effective;
    for (Transition* candidate : ordered) {
        if (isEffective(*candidate))
            effective.push_back(candidate);
    }
    const int count = static_cast<int>(effective.size());
    if (newPriority < 1 || newPriority > count)
        return Status::failure("priority-out-of-range", "priority " + std::to_string(newPriority) +
                                                            " is out of range for " + t->id + " (1.." +
                                                            std::to_string(count) + ")");
    // Reorder like a list: take t out, then put it just before the effective
    // transition now holding that rank (or just after the last effective one),
    // so hidden transitions keep their place relative to their neighbours.
    std::erase(ordered, t);
    std::erase(effective, t);
    auto anchor = static_cast<std::size_t>(newPriority - 1) < effective.size()
        ? std::find(ordered.begin(), ordered.end(), effective[static_cast<std::size_t>(newPriority - 1)])
        : (effective.empty() ? ordered.end()
                             : std::next(std::find(ordered.begin(), ordered.end(), effective.back())));
    ordered.insert(anchor, t);
    renumberOrders(ordered);
    return Status::success();
}

Status Model::setOrder(std::string_view transitionId, int order)
{
    Transition* t = mutableTransition(transitionId);
    if (!t)
        return unknownTransition(transitionId);
    std::vector<Transition*> ordered = mutableOutgoing(t->source);
    const int count = static_cast<int>(ordered.size());
    if (order < 1 || order > count)
        return Status::failure("order-out-of-range", "order " + std::to_string(order) + " is out of range for " +
                                                         t->id + " (1.." + std::to_string(count) + ")");
    std::erase(ordered, t);
    ordered.insert(ordered.begin() + (order - 1), t);
    renumberOrders(ordered);
    return Status::success();
}

void Model::renumberOrders(const std::vector<Transition*>& ordered)
{
    int order = 0;
    for (Transition* t : ordered) {
        ++order;
        if (t->order != order) {
            t->order = order;
            notify(ModelChange::Kind::Transition, t->id);
        }
    }
}

Status Model::setCondition(std::string_view transitionId, std::string condition)
{
    Transition* t = mutableTransition(transitionId);
    if (!t)
        return unknownTransition(transitionId);
    if (t->condition != condition) {
        t->condition = std::move(condition);
        notify(ModelChange::Kind::Transition, t->id);
    }
    return Status::success();
}

Status Model::setNegated(std::string_view transitionId, bool negated)
{
    Transition* t = mutableTransition(transitionId);
    if (!t)
        return unknownTransition(transitionId);
    if (t->negated != negated) {
        t->negated = negated;
        notify(ModelChange::Kind::Transition, t->id);
    }
    return Status::success();
}

Status Model::setTokens(std::string_view transitionId, std::vector<std::string> tokens)
{
    Transition* t = mutableTransition(transitionId);
    if (!t)
        return unknownTransition(transitionId);
    std::vector<std::string> unique;
    for (std::string& token : tokens) {
        if (token.empty())
            return Status::failure("empty-token", "a token of " + t->id + " names no variable");
        if (containsIgnoreCase(unique, token))
            return Status::failure("duplicate-token", "variable '" + token + "' has two tokens on " + t->id);
        unique.push_back(std::move(token));
    }
    if (t->tokens != unique) {
        t->tokens = std::move(unique);
        notify(ModelChange::Kind::Transition, t->id);
    }
    return Status::success();
}

// ---- variables ---------------------------------------------------------------

Status Model::addVariable(Variable variable, int index)
{
    if (variable.name.empty())
        return Status::failure("empty-name", "a variable needs a name");
    if (const Variable* existing = this->variable(variable.name))
        return Status::failure("duplicate-name", "a variable named '" + existing->name +
                                                     "' already exists (IEC names ignore case)");
    const int count = static_cast<int>(m_variables.size());
    if (index < -1 || index > count)
        return Status::failure("index-out-of-range", "variable position " + std::to_string(index) +
                                                         " is out of range (0.." + std::to_string(count) + ")");
    const std::string name = variable.name;
    auto position = index < 0 ? m_variables.end() : m_variables.begin() + index;
    m_variables.insert(position, std::move(variable));
    notify(ModelChange::Kind::VariableList);
    notify(ModelChange::Kind::Variable, name);
    return Status::success();
}

Status Model::removeVariable(std::string_view name)
{
    const int index = variableIndex(name);
    if (index < 0)
        return unknownVariable(name);
    m_variables.erase(m_variables.begin() + index);
    notify(ModelChange::Kind::VariableList);
    return Status::success();
}

Status Model::moveVariable(std::string_view name, int index)
{
    const int from = variableIndex(name);
    if (from < 0)
        return unknownVariable(name);
    const int count = static_cast<int>(m_variables.size());
    if (index < 0 || index >= count)
        return Status::failure("index-out-of-range", "variable position " + std::to_string(index) +
                                                         " is out of range (0.." + std::to_string(count - 1) + ")");
    if (from == index)
        return Status::success();
    Variable moved = std::move(m_variables[static_cast<std::size_t>(from)]);
    m_variables.erase(m_variables.begin() + from);
    m_variables.insert(m_variables.begin() + index, std::move(moved));
    notify(ModelChange::Kind::VariableList);
    return Status::success();
}

Status Model::renameVariable(std::string_view oldName, std::string newName)
{
    Variable* v = mutableVariable(oldName);
    if (!v)
        return unknownVariable(oldName);
    if (newName.empty())
        return Status::failure("empty-name", "a variable needs a name");
    // Conditions are rewritten to the new name: one that is no identifier
    // ("Stop 2", "AND") would leave them unparsable, and a second rename
    // could not find it in them again.
    if (const IdentifierProblem problem = identifierProblem(newName); problem != IdentifierProblem::None)
        return Status::failure("invalid-name", identifierProblemMessage(problem, newName));
    const Variable* clash = variable(newName);
    if (clash && clash != v)
        return Status::failure("duplicate-name", "a variable named '" + clash->name +
                                                     "' already exists (IEC names ignore case)");
    if (v->name == newName)
        return Status::success();
    const std::string previous = v->name;
    v->name = newName;
    for (Transition& t : m_transitions) {
        bool changed = false;
        std::string renamed = cond::renameIdentifier(t.condition, previous, newName);
        if (renamed != t.condition) {
            t.condition = std::move(renamed);
            changed = true;
        }
        for (std::string& token : t.tokens) {
            if (equalsIgnoreCase(token, previous)) {
                token = newName;
                changed = true;
            }
        }
        if (changed)
            notify(ModelChange::Kind::Transition, t.id);
    }
    for (auto& [stepId, nested] : m_grafcets) {
        std::vector<int> steps;
        std::vector<int> transitions;
        nested.renameIdentifier(previous, newName, steps, transitions);
        std::vector<GrafcetChange> changes;
        for (int number : steps)
            changes.push_back({GrafcetChange::Kind::Step, number});
        for (int number : transitions)
            changes.push_back({GrafcetChange::Kind::Transition, number});
        if (!changes.empty())
            notifyGrafcet(stepId, std::move(changes));
    }
    renameInPackMLConditions(previous, newName);
    if (m_machine.renameVariable(previous, newName))
        notify(ModelChange::Kind::Machine);
    notify(ModelChange::Kind::Variable, newName);
    notify(ModelChange::Kind::VariableList);
    return Status::success();
}

Status Model::setVariableType(std::string_view name, IecType type)
{
    Variable* v = mutableVariable(name);
    if (!v)
        return unknownVariable(name);
    if (v->type != type) {
        v->type = type;
        notify(ModelChange::Kind::Variable, v->name);
    }
    return Status::success();
}

Status Model::setVariableDefault(std::string_view name, std::string defaultValue)
{
    Variable* v = mutableVariable(name);
    if (!v)
        return unknownVariable(name);
    if (v->defaultValue != defaultValue) {
        v->defaultValue = std::move(defaultValue);
        notify(ModelChange::Kind::Variable, v->name);
    }
    return Status::success();
}

Status Model::setVariableComment(std::string_view name, std::string comment)
{
    Variable* v = mutableVariable(name);
    if (!v)
        return unknownVariable(name);
    if (v->comment != comment) {
        v->comment = std::move(comment);
        notify(ModelChange::Kind::Variable, v->name);
    }
    return Status::success();
}

Status Model::setVariableKind(std::string_view name, VariableKind kind)
{
    Variable* v = mutableVariable(name);
    if (!v)
        return unknownVariable(name);
    if (v->kind != kind) {
        v->kind = kind;
        notify(ModelChange::Kind::Variable, v->name);
    }
    return Status::success();
}

// ---- properties --------------------------------------------------------------

namespace {

Status noProperty(int index, std::size_t count)
{
    return Status::failure("unknown-property", "no property " + std::to_string(index + 1) + " (the model has " + std::to_string(count)
                           + ")");
}

} // namespace

Status Model::addProperty(UserProperty property, int index)
{
    if (index < -1 || index > static_cast<int>(m_properties.size()))
        return noProperty(index, m_properties.size());
    const auto at = index < 0 ? m_properties.end() : m_properties.begin() + index;
    m_properties.insert(at, std::move(property));
    notify(ModelChange::Kind::Properties);
    return Status::success();
}

Status Model::setPropertyText(int index, std::string text)
{
    if (index < 0 || index >= static_cast<int>(m_properties.size()))
        return noProperty(index, m_properties.size());
    UserProperty& property = m_properties[static_cast<std::size_t>(index)];
    if (property.text != text) {
        property.text = std::move(text);
        notify(ModelChange::Kind::Properties);
    }
    return Status::success();
}

Status Model::setPropertyComment(int index, std::string comment)
{
    if (index < 0 || index >= static_cast<int>(m_properties.size()))
        return noProperty(index, m_properties.size());
    UserProperty& property = m_properties[static_cast<std::size_t>(index)];
    if (property.comment != comment) {
        property.comment = std::move(comment);
        notify(ModelChange::Kind::Properties);
    }
    return Status::success();
}

Status Model::removeProperty(int index)
{
    if (index < 0 || index >= static_cast<int>(m_properties.size()))
        return noProperty(index, m_properties.size());
    m_properties.erase(m_properties.begin() + index);
    notify(ModelChange::Kind::Properties);
    return Status::success();
}

Status Model::moveProperty(int from, int to)
{
    const int count = static_cast<int>(m_properties.size());
    if (from < 0 || from >= count)
        return noProperty(from, m_properties.size());
    if (to < 0 || to >= count)
        return noProperty(to, m_properties.size());
    if (from == to)
        return Status::success();
    UserProperty moved = std::move(m_properties[static_cast<std::size_t>(from)]);
    m_properties.erase(m_properties.begin() + from);
    m_properties.insert(m_properties.begin() + to, std::move(moved));
    notify(ModelChange::Kind::Properties);
    return Status::success();
}

// ---- settings ----------------------------------------------------------------

Status Model::setName(std::string name)
{
    if (m_settings.name != name) {
        m_settings.name = std::move(name);
        notify(ModelChange::Kind::Settings);
    }
    return Status::success();
}

Status Model::setCycleTimeMs(int cycleTimeMs)
{
    if (cycleTimeMs < kMinCycleTimeMs || cycleTimeMs > kMaxCycleTimeMs)
        return Status::failure("cycle-time-out-of-range",
                               "the PLC cycle time must be between " + std::to_string(kMinCycleTimeMs) + " ms and " +
                                   std::to_string(kMaxCycleTimeMs) + " ms, not " + std::to_string(cycleTimeMs) + " ms");
    if (m_settings.cycleTimeMs != cycleTimeMs) {
        m_settings.cycleTimeMs = cycleTimeMs;
        notify(ModelChange::Kind::Settings);
    }
    return Status::success();
}

void Model::setDialect(Dialect dialect)
{
    if (m_settings.dialect != dialect) {
        m_settings.dialect = dialect;
        notify(ModelChange::Kind::Settings);
    }
}

void Model::setEvolutionRule(EvolutionRule rule)
{
    if (m_settings.evolution != rule) {
        m_settings.evolution = rule;
        notify(ModelChange::Kind::Settings);
    }
}

Status Model::setMachine(machine::Machine machine)
{
    if (m_packml && !machine.empty())
        return Status::failure("machine.packml", "a PackML model has no virtual machine yet");
    if (const std::vector<std::string> problems = machine.structuralProblems(); !problems.empty())
        return Status::failure("machine.structure", problems.front());
    if (machine == m_machine)
        return Status::success();
    m_machine = std::move(machine);
    notify(ModelChange::Kind::Machine);
    return Status::success();
}

void Model::resetToTemplate()
{
    if (m_packml)
        assign(packml::newModel(m_packml->options.edition));
    else
        assign(Model());
}

void Model::assign(const Model& other)
{
    if (&other == this)
        return;
    m_steps = other.m_steps;
    m_transitions = other.m_transitions;
    m_variables = other.m_variables;
    m_grafcets = other.m_grafcets;
    m_settings = other.m_settings;
    m_properties = other.m_properties;
    m_packml = other.m_packml;
    m_machine = other.m_machine;
    notify(ModelChange::Kind::Reset);
}

// ---- observers ---------------------------------------------------------------

int Model::addObserver(Observer observer)
{
    const int handle = m_nextObserver++;
    m_observers.emplace(handle, std::move(observer));
    return handle;
}

void Model::removeObserver(int handle)
{
    m_observers.erase(handle);
}

void Model::notify(ModelChange::Kind kind, std::string id)
{
    ++m_revision;
    const ModelChange change{kind, std::move(id)};
    for (const auto& [handle, observer] : m_observers)
        observer(change);
}

void Model::notifyGrafcet(std::string_view stepId, std::vector<GrafcetChange> changes)
{
    ++m_revision;
    const ModelChange change{ModelChange::Kind::Grafcet, std::string(stepId), std::move(changes)};
    for (const auto& [handle, observer] : m_observers)
        observer(change);
}

// ---- invariants --------------------------------------------------------------

std::vector<std::string> Model::invariantViolations() const
{
    std::vector<std::string> problems;
    if (m_packml)
        packMLInvariantViolations(problems);
    else
        gemmaInvariantViolations(problems);
    std::set<std::string> upperNames;
    for (const Variable& v : m_variables) {
        if (v.name.empty())
            problems.push_back("a variable has an empty name");
        if (!upperNames.insert(toUpperAscii(v.name)).second)
            problems.push_back("two variables are named '" + v.name + "' (ignoring case)");
    }
    for (const Transition& t : m_transitions) {
        std::set<std::string> upperTokens;
        for (const std::string& token : t.tokens) {
            if (token.empty() || !upperTokens.insert(toUpperAscii(token)).second)
                problems.push_back("transition " + t.id + " has an empty or repeated token");
        }
    }
    if (m_settings.cycleTimeMs < kMinCycleTimeMs || m_settings.cycleTimeMs > kMaxCycleTimeMs)
        problems.push_back("the cycle time is out of range");
    for (std::string& problem : m_machine.structuralProblems())
        problems.push_back(std::move(problem));
    if (m_packml && !m_machine.empty())
        problems.push_back("a PackML model has a virtual machine");
    for (const auto& [stepId, nested] : m_grafcets) {
        if (!ownsGrafcetKey(stepId))
            problems.push_back("a nested GRAFCET belongs to '" + stepId + "', which is no template step");
        for (const std::string& problem : nested.invariantViolations())
            problems.push_back("GRAFCET of " + stepId + ": " + problem);
    }
    return problems;
}

void Model::gemmaInvariantViolations(std::vector<std::string>& problems) const
{
    const auto initialCount = std::count_if(m_steps.begin(), m_steps.end(), [](const Step& s) { return s.initial; });
    if (initialCount != 1)
        problems.push_back(std::to_string(initialCount) + " initial steps instead of exactly one");
    if (m_steps.size() != templateStates().size() || m_transitions.size() != templateTransitions().size())
        problems.push_back("the steps or transitions differ from the template");

    std::set<std::string> sources;
    for (const Transition& t : m_transitions)
        sources.insert(t.source);
    for (const std::string& source : sources) {
        const auto ordered = outgoing(source);
        for (std::size_t i = 0; i < ordered.size(); ++i) {
            if (ordered[i]->order != static_cast<int>(i) + 1)
                problems.push_back("the orders of the transitions out of " + source + " do not form 1..m");
        }
        int expected = 0;
        for (const Transition* t : ordered) {
            if (isEffective(*t) && priority(t->id) != ++expected)
                problems.push_back("the priorities out of " + source + " do not form 1..n");
        }
    }
}

bool Model::sameContent(const Model& other) const
{
    return m_steps == other.m_steps && m_transitions == other.m_transitions && m_variables == other.m_variables &&
           m_settings == other.m_settings && m_properties == other.m_properties && m_packml == other.m_packml &&
           m_machine == other.m_machine &&
           std::equal(m_grafcets.begin(), m_grafcets.end(), other.m_grafcets.begin(), other.m_grafcets.end(),
                      [](const auto& a, const auto& b) { return a.first == b.first && a.second.sameContent(b.second); });
}

// ---- private helpers -----------------------------------------------------------

Step* Model::mutableStep(std::string_view id)
{
    return const_cast<Step*>(step(id));
}

Transition* Model::mutableTransition(std::string_view id)
{
    return const_cast<Transition*>(transition(id));
}

Variable* Model::mutableVariable(std::string_view name)
{
    return const_cast<Variable*>(variable(name));
}

std::vector<Transition*> Model::mutableOutgoing(std::string_view source)
{
    std::vector<Transition*> result;
    for (const Transition* t : outgoing(source))
        result.push_back(const_cast<Transition*>(t));
    return result;
}

bool operator==(const Step& a, const Step& b)
{
    return a.id == b.id && a.number == b.number && a.family == b.family && a.type == b.type &&
           a.initial == b.initial && a.hidden == b.hidden && a.comment == b.comment;
}

bool operator==(const Transition& a, const Transition& b)
{
    return a.id == b.id && a.source == b.source && a.target == b.target && a.condition == b.condition &&
           a.order == b.order && a.negated == b.negated && a.hidden == b.hidden && a.tokens == b.tokens;
}

bool operator==(const Variable& a, const Variable& b)
{
    return a.name == b.name && a.type == b.type && a.kind == b.kind && a.defaultValue == b.defaultValue &&
           a.comment == b.comment;
}

bool operator==(const ModelSettings& a, const ModelSettings& b)
{
    return a.name == b.name && a.cycleTimeMs == b.cycleTimeMs && a.dialect == b.dialect && a.evolution == b.evolution;
}

} // namespace core
