// The Model's PackML operations (model.h): the configuration's mutators, the
// GRAFCET keys of (mode, state) and what the invariants add for PackML.

#include "core/model/model.h"

#include "core/condition/conditionparser.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <algorithm>

namespace core {

namespace {

using packml::GrafcetChoice;

Status unknownMode(int number)
{
    return Status::failure("unknown-mode", "there is no unit mode " + std::to_string(number));
}

bool validModeNumber(int number)
{
    return number >= packml::kMinModeNumber && number <= packml::kMaxModeNumber;
}

Status modeNumberOutOfRange(int number)
{
    return Status::failure("mode-out-of-range",
                           "unit mode " + std::to_string(number) + " is outside 1..31 (PackTags UnitMode)");
}

// Assigns and tells whether anything changed.
template <typename Value>
bool assignChanged(Value& target, Value value)
{
    if (target == value)
        return false;
    target = std::move(value);
    return true;
}

} // namespace

// ---- helpers of the GRAFCET storage ------------------------------------------

bool Model::ownsGrafcetKey(std::string_view key) const
{
    if (!m_packml)
        return step(key) != nullptr;
    const auto parsed = packml::parseGrafcetKey(key);
    return parsed && packml::holdsGrafcet(parsed->second) && m_packml->mode(parsed->first) != nullptr;
}

Status Model::unknownGrafcetOwner(std::string_view key) const
{
    if (!m_packml)
        return Status::failure("unknown-step", "there is no step '" + std::string(key) + "' in the GEMMA template");
    return Status::failure("unknown-step", "'" + std::string(key)
                                               + "' names no unit mode of the model and state that holds a GRAFCET "
                                                 "(MODE/STATE, such as 1/Execute)");
}

const Grafcet* Model::effectivePackMLGrafcet(std::string_view key) const
{
    if (!ownsGrafcetKey(key))
        return nullptr;
    const auto [number, state] = *packml::parseGrafcetKey(key);
    const packml::Mode& mode = *m_packml->mode(number);
    if (state != packml::State::Execute && mode.disabled.contains(state))
        return nullptr; // acting states are enabled exactly when not listed (spec §3.2)
    const GrafcetChoice& choice = mode.grafcetChoice(state);
    switch (choice.kind) {
    case GrafcetChoice::Kind::Own: return grafcet(key);
    case GrafcetChoice::Kind::SameAs: return grafcet(packml::grafcetKey(choice.sameAsMode, state)); // k's own only
    case GrafcetChoice::Kind::None: break;
    }
    return nullptr;
}

Status Model::notPackML() const
{
    return Status::failure("not-packml", "this is a GEMMA model; the operation is for PackML models");
}

packml::Mode* Model::mutableMode(int number)
{
    return m_packml ? m_packml->mode(number) : nullptr;
}

Status Model::findMutableMode(int number, packml::Mode*& mode)
{
    if (!m_packml)
        return notPackML();
    mode = mutableMode(number);
    return mode ? Status::success() : unknownMode(number);
}

// ---- settings and commands ---------------------------------------------------

Status Model::setPackMLOptions(packml::Options options)
{
    if (!m_packml)
        return notPackML();
    if (assignChanged(m_packml->options, options))
        notify(ModelChange::Kind::PackMLSettings);
    return Status::success();
}

Status Model::setPackMLInitialState(packml::State state)
{
    if (!m_packml)
        return notPackML();
    if (assignChanged(m_packml->initialState, state))
        notify(ModelChange::Kind::PackMLSettings);
    return Status::success();
}

Status Model::setPackMLInitialMode(int mode)
{
    if (!m_packml)
        return notPackML();
    if (!validModeNumber(mode))
        return modeNumberOutOfRange(mode);
    if (assignChanged(m_packml->initialMode, mode))
        notify(ModelChange::Kind::PackMLSettings);
    return Status::success();
}

Status Model::setCommandCondition(packml::Command command, std::string condition)
{
    if (!m_packml)
        return notPackML();
    if (assignChanged(m_packml->command(command).condition, std::move(condition)))
        notify(ModelChange::Kind::PackMLCommand, std::string(packml::commandName(command)));
    return Status::success();
}

Status Model::setCommandComment(packml::Command command, std::string comment)
{
    if (!m_packml)
        return notPackML();
    if (assignChanged(m_packml->command(command).comment, std::move(comment)))
        notify(ModelChange::Kind::PackMLCommand, std::string(packml::commandName(command)));
    return Status::success();
}

// ---- modes -----------------------------------------------------------------------

Status Model::addMode(int number, std::string name)
{
    if (!m_packml)
        return notPackML();
    if (!validModeNumber(number))
        return modeNumberOutOfRange(number);
    if (m_packml->mode(number))
        return Status::failure("duplicate-mode", "the model already has unit mode " + std::to_string(number));
    if (number < packml::kFirstUserMode && !name.empty())
        return Status::failure("fixed-mode-name", "unit mode " + std::to_string(number) + " is named "
                                                      + std::string(packml::baseModeName(number)) + "; only user modes (4..31) take a name");
    packml::Mode mode = packml::defaultMode(number);
    mode.name = std::move(name);
    auto& modes = m_packml->modes;
    const auto at = std::find_if(modes.begin(), modes.end(), [&](const packml::Mode& m) { return m.number > number; });
    modes.insert(at, std::move(mode));
    notify(ModelChange::Kind::PackMLModes, std::to_string(number));
    return Status::success();
}

Status Model::removeMode(int number)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    std::vector<std::string> removedKeys;
    for (const packml::StateInfo& info : packml::states()) {
        const std::string key = packml::grafcetKey(number, info.state);
        if (m_grafcets.erase(key) > 0)
            removedKeys.push_back(key);
    }
    std::erase_if(m_packml->modes, [&](const packml::Mode& m) { return m.number == number; });
    std::vector<int> redirected;
    for (packml::Mode& other : m_packml->modes) {
        bool changed = false;
        for (GrafcetChoice& choice : other.grafcets) {
            if (choice.kind == GrafcetChoice::Kind::SameAs && choice.sameAsMode == number) {
                choice = GrafcetChoice::none();
                changed = true;
            }
        }
        if (changed)
            redirected.push_back(other.number);
    }
    // Observers hear of it only once the model is whole again.
    for (const std::string& key : removedKeys)
        notifyGrafcet(key, {});
    for (int other : redirected)
        notify(ModelChange::Kind::PackMLMode, std::to_string(other));
    notify(ModelChange::Kind::PackMLModes, std::to_string(number));
    return Status::success();
}

Status Model::renameMode(int number, std::string name)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    if (number < packml::kFirstUserMode)
        return Status::failure("fixed-mode-name", "unit mode " + std::to_string(number) + " is named "
                                                      + std::string(packml::baseModeName(number)) + "; only user modes (4..31) are renamed");
    if (assignChanged(mode->name, std::move(name)))
        notify(ModelChange::Kind::PackMLMode, std::to_string(number));
    return Status::success();
}

Status Model::setModeComment(int number, std::string comment)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    if (assignChanged(mode->comment, std::move(comment)))
        notify(ModelChange::Kind::PackMLMode, std::to_string(number));
    return Status::success();
}

Status Model::setModeRequest(int number, std::string condition)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    if (assignChanged(mode->request, std::move(condition)))
        notify(ModelChange::Kind::PackMLMode, std::to_string(number));
    return Status::success();
}

Status Model::setModeDisabled(int number, packml::StateSet disabled)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    if (assignChanged(mode->disabled, disabled))
        notify(ModelChange::Kind::PackMLMode, std::to_string(number));
    return Status::success();
}

Status Model::setModeChangeStates(int number, packml::StateSet states)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    if (assignChanged(mode->modeChange, states))
        notify(ModelChange::Kind::PackMLMode, std::to_string(number));
    return Status::success();
}

Status Model::setGrafcetChoice(int number, packml::State state, GrafcetChoice choice)
{
    packml::Mode* mode = nullptr;
    if (Status status = findMutableMode(number, mode); !status)
        return status;
    if (!packml::holdsGrafcet(state))
        return Status::failure("no-grafcet-state", std::string(packml::stateName(state))
                                                       + " holds no GRAFCET; only the acting states and Execute do");
    if (choice.kind == GrafcetChoice::Kind::SameAs && !validModeNumber(choice.sameAsMode))
        return modeNumberOutOfRange(choice.sameAsMode);
    if (choice.kind != GrafcetChoice::Kind::SameAs)
        choice.sameAsMode = 0;
    GrafcetChoice& current = mode->grafcets[static_cast<std::size_t>(state)];
    if (current == choice)
        return Status::success();
    const bool wasOwn = current.kind == GrafcetChoice::Kind::Own;
    current = choice;
    const std::string key = packml::grafcetKey(number, state);
    if (choice.kind == GrafcetChoice::Kind::Own)
        m_grafcets.emplace(key, Grafcet());
    else if (wasOwn)
        m_grafcets.erase(key);
    if (wasOwn || choice.kind == GrafcetChoice::Kind::Own)
        notifyGrafcet(key, {});
    notify(ModelChange::Kind::PackMLMode, std::to_string(number));
    return Status::success();
}

// ---- variables and invariants ------------------------------------------------------

void Model::renameInPackMLConditions(const std::string& previous, const std::string& newName)
{
    if (!m_packml)
        return;
    for (const packml::CommandInfo& info : packml::allCommands()) {
        std::string& condition = m_packml->command(info.command).condition;
        if (assignChanged(condition, cond::renameIdentifier(condition, previous, newName)))
            notify(ModelChange::Kind::PackMLCommand, std::string(info.name));
    }
    for (packml::Mode& mode : m_packml->modes) {
        if (assignChanged(mode.request, cond::renameIdentifier(mode.request, previous, newName)))
            notify(ModelChange::Kind::PackMLMode, std::to_string(mode.number));
    }
}

void Model::packMLInvariantViolations(std::vector<std::string>& problems) const
{
    if (!m_steps.empty() || !m_transitions.empty())
        problems.push_back("a PackML model holds GEMMA steps or transitions");
    for (const std::string& problem : packml::structureProblems(*m_packml))
        problems.push_back(problem);
    for (const packml::Mode& mode : m_packml->modes) {
        for (const packml::StateInfo& info : packml::states()) {
            const bool own = mode.grafcetChoice(info.state).kind == GrafcetChoice::Kind::Own;
            const std::string key = packml::grafcetKey(mode.number, info.state);
            if (own != (grafcet(key) != nullptr))
                problems.push_back("the GRAFCET of " + key + (own ? " is chosen but missing" : " is stored but not chosen"));
        }
    }
}

} // namespace core
