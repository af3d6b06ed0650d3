#include "packmlsamples.h"

#include "samplemodels.h"

#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlrules.h"

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace samples {

namespace {

using core::packml::Command;
using core::packml::GrafcetChoice;
using core::packml::State;
using core::packml::StateSet;

class RandomPackmlBuilder {
public:
    explicit RandomPackmlBuilder(std::mt19937& random) : m_random(random) {}

    core::Model build()
    {
        const core::packml::Edition edition = chance(2) ? core::packml::Edition::Y2015 : core::packml::Edition::Y2022;
        core::Model model = core::packml::newModel(edition);
        core::packml::Options options = model.packml()->options;
        options.holdInSuspended = chance(2);
        options.completeInSuspendedHeld = edition == core::packml::Edition::Y2022 && chance(2);
        requireBuilt(model.setPackMLOptions(options));
        declareInputs(model);
        chooseModes(model);
        for (const core::packml::Mode& mode : std::vector<core::packml::Mode>(model.packml()->modes))
            configureMode(model, mode.number);
        chooseCommands(model);
        const std::vector<core::packml::Mode>& modes = model.packml()->modes;
        requireBuilt(model.setPackMLInitialMode(modes[static_cast<std::size_t>(pick(static_cast<int>(modes.size())))].number));
        const State initialStates[] = {State::Stopped, State::Idle, State::Aborted};
        requireBuilt(model.setPackMLInitialState(initialStates[pick(3)]));
        addGrafcets(model);
        return model;
    }

private:
    int pick(int count) { return static_cast<int>(m_random() % static_cast<unsigned>(count)); }
    bool chance(int in) { return pick(in) == 0; }

    void declareInputs(core::Model& model)
    {
        core::Variable selector{"ModeKey", core::IecType::Int, "", "mode selector"};
        requireBuilt(model.addVariable(selector));
        requireBuilt(model.addVariable(core::Variable{"AnyCommand", core::IecType::Bool, "", "a shared command input"}));
    }

    void chooseModes(core::Model& model)
    {
        if (chance(3))
            requireBuilt(model.removeMode(2));
        if (chance(2))
            requireBuilt(model.addMode(4 + pick(5), "User"));
    }

    void configureMode(core::Model& model, int number)
    {
        StateSet listing;
        for (int toggles = pick(6); toggles > 0; --toggles)
            listing = core::packml::consistentListing(listing, static_cast<State>(1 + pick(core::packml::kStateCount)));
        requireBuilt(model.setModeDisabled(number, listing));
        StateSet modeChange;
        for (const State state : {State::Stopped, State::Idle, State::Aborted, State::Held, State::Suspended,
                                  State::Complete, State::Execute})
            if (chance(2))
                modeChange.insert(state);
        requireBuilt(model.setModeChangeStates(number, modeChange));
        switch (pick(3)) {
        case 0: requireBuilt(model.setModeRequest(number, "")); break;
        case 1: requireBuilt(model.setModeRequest(number, "ModeKey = " + std::to_string(number))); break;
        default: requireBuilt(model.setModeRequest(number, "ModeKey >= " + std::to_string(number))); break;
        }
    }

    void chooseCommands(core::Model& model)
    {
        for (const core::packml::CommandInfo& info : core::packml::allCommands()) {
            if (!core::packml::commandInEdition(info.command, model.packml()->options.edition))
                continue;
            const std::string input(info.defaultInput);
            switch (pick(6)) {
            case 0: requireBuilt(model.setCommandCondition(info.command, "FALSE")); break;
            case 1: requireBuilt(model.setCommandCondition(info.command, input + " OR AnyCommand")); break;
            case 2: requireBuilt(model.setCommandCondition(info.command, "NOT " + input)); break;
            default: break; // the default input
            }
        }
    }

    // Own on about half the enabled states that hold one, "same as" an
    // earlier mode's own GRAFCET on some others.
    void addGrafcets(core::Model& model)
    {
        std::vector<std::string> keys;
        std::vector<std::pair<int, State>> owners;
        for (const core::packml::Mode& mode : std::vector<core::packml::Mode>(model.packml()->modes)) {
            const StateSet enabled = core::packml::enabledStates(mode.disabled).enabled;
            for (const State state : enabled.list()) {
                if (!core::packml::holdsGrafcet(state))
                    continue;
                if (chance(2)) {
                    requireBuilt(model.setGrafcetChoice(mode.number, state, GrafcetChoice::own()));
                    keys.push_back(core::packml::grafcetKey(mode.number, state));
                    owners.emplace_back(mode.number, state);
                    continue;
                }
                for (const auto& [owner, ownerState] : owners)
                    if (ownerState == state && chance(2)) {
                        requireBuilt(model.setGrafcetChoice(mode.number, state, GrafcetChoice::sameAs(owner)));
                        break;
                    }
            }
        }
        addRandomGrafcetsAt(model, m_random, keys);
    }

    std::mt19937& m_random;
};

} // namespace

core::Model randomPackmlModel(std::uint32_t seed)
{
    std::mt19937 random(seed * 2654435761u + 7u);
    for (int attempt = 0; attempt < 50; ++attempt) {
        core::Model model = RandomPackmlBuilder(random).build();
        if (core::packml::buildPackmlProgram(model).problems.empty())
            return model;
    }
    throw std::logic_error("randomPackmlModel: no model without problems in 50 draws for seed " + std::to_string(seed));
}

} // namespace samples
