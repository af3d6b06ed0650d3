#include "core/templates/packml/packmlmodechecks.h"

#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/templates/packml/packmldiagnostics.h"
#include "core/templates/packml/packmlprogramname.h"
#include "core/templates/packml/packmlrules.h"

#include <string>

namespace core::packml {

namespace {

std::string joinedStateNames(const std::vector<State>& states)
{
    std::string result;
    for (const State state : states)
        result += (result.empty() ? "" : ", ") + std::string(stateName(state));
    return result;
}

// GEMMA's generator names (GEMMA, its configuration...) are free in a PackML
// model; PackML's own are isReservedName's.
bool isIdentifier(std::string_view name)
{
    const IdentifierProblem problem = identifierProblem(name);
    return problem == IdentifierProblem::None || problem == IdentifierProblem::GeneratorName;
}

class ModeChecker {
public:
    explicit ModeChecker(const Model& model)
        : m_configuration(*model.packml())
        , m_programName(programName(model))
        , m_modeNames(modeNames(m_configuration))
    {
        for (const Mode& mode : m_configuration.modes)
            m_enabled.push_back(enabledStates(mode.disabled));
    }

    std::vector<Diagnostic> run()
    {
        for (std::size_t i = 0; i < m_configuration.modes.size(); ++i) {
            const Mode& mode = m_configuration.modes[i];
            checkNumber(i);
            checkName(i);
            checkListing(mode, m_enabled[i]);
            checkModeChanges(mode, m_enabled[i].enabled);
            checkEverCurrent(i);
            checkGrafcetChoices(mode, m_enabled[i].enabled);
        }
        return std::move(m_result);
    }

private:
    void addMode(const Mode& mode, Finding finding) { m_result.push_back(modeDiagnostic(mode, std::move(finding))); }

    void addModeState(const Mode& mode, State state, Finding finding)
    {
        m_result.push_back(modeStateDiagnostic(mode, state, std::move(finding)));
    }

    // The model's mutators keep numbers in 1..31 and each once; a
    // configuration built otherwise (a library user, a future loader) is
    // still reported rather than trusted.
    void checkNumber(std::size_t index)
    {
        const Mode& mode = m_configuration.modes[index];
        const std::string number = std::to_string(mode.number);
        if (mode.number < kMinModeNumber || mode.number > kMaxModeNumber)
            addMode(mode, {"PM002", Severity::Error, "number",
                           "unit mode " + number + " is outside 1..31 (PackTags UnitMode)", {number, "out-of-range"}});
        for (std::size_t before = 0; before < index; ++before)
            if (m_configuration.modes[before].number == mode.number) {
                addMode(mode, {"PM002", Severity::Error, "number", "unit mode " + number + " is given twice",
                               {number, "repeated"}});
                break;
            }
    }

    void checkName(std::size_t index)
    {
        const Mode& mode = m_configuration.modes[index];
        const std::string number = std::to_string(mode.number);
        if (mode.number < kFirstUserMode) {
            if (!mode.name.empty())
                addMode(mode, {"PM002", Severity::Error, "name",
                               "unit mode " + number + " is named " + std::string(baseModeName(mode.number))
                                   + ", not '" + mode.name + "'",
                               {number, "fixed-name", mode.name}});
            return;
        }
        if (!isIdentifier(mode.name)) {
            addMode(mode, {"PM002", Severity::Error, "name",
                           "the name '" + mode.name + "' of unit mode " + number
                               + " is not an IEC identifier, and it becomes part of the names of function blocks",
                           {number, "not-identifier", mode.name}});
            return;
        }
        if (isReservedName(mode.name, m_programName, m_modeNames)) {
            addMode(mode, {"PM002", Severity::Error, "name",
                           "the name '" + mode.name + "' of unit mode " + number + " is one the generated code uses",
                           {number, "reserved", mode.name}});
            return;
        }
        for (std::size_t other = 0; other < m_configuration.modes.size(); ++other)
            if (other != index && equalsIgnoreCase(m_configuration.modes[other].displayName(), mode.name)
                && (m_configuration.modes[other].number < kFirstUserMode || other < index)) {
                const std::string otherName(m_configuration.modes[other].displayName());
                addMode(mode, {"PM002", Severity::Error, "name",
                               "unit mode " + number + " is named '" + mode.name + "' as unit mode "
                                   + std::to_string(m_configuration.modes[other].number) + " (" + otherName
                                   + "), ignoring case",
                               {number, "duplicate-name", mode.name, otherName}});
                return;
            }
    }

    void checkListing(const Mode& mode, const EnabledStates& enabled)
    {
        const std::string label = modeLabel(mode);
        for (const State state : enabled.ignoredListings.list()) {
            const std::string name(stateName(state));
            addMode(mode, {"PM004", Severity::Warning, "disabled",
                           "mode " + label + " lists " + name + " as disabled, which every unit needs: ignored",
                           {label, name}});
        }
        for (const ForcedWaitState& forced : enabled.forced) {
            const std::string name(stateName(forced.state));
            const std::string acting = joinedStateNames(forced.enabledActing);
            addMode(mode, {"PM005", Severity::Warning, "disabled",
                           "mode " + label + " lists " + name + " as disabled, but it stays enabled while " + acting
                               + " is enabled",
                           {label, name, acting}});
        }
    }

    void checkModeChanges(const Mode& mode, const StateSet& enabled)
    {
        const std::string label = modeLabel(mode);
        for (const State state : mode.modeChange.list()) {
            const std::string name(stateName(state));
            if (!mayAllowModeChange(state))
                addMode(mode, {"PM006", Severity::Warning, "modeChange",
                               "mode " + label + " allows a mode change in " + name
                                   + ", an acting state, half-way through its GRAFCET: ignored",
                               {label, name, "acting"}});
            else if (!enabled.contains(state))
                addMode(mode, {"PM006", Severity::Warning, "modeChange",
                               "mode " + label + " allows a mode change in " + name
                                   + ", which it disables: no effect",
                               {label, name, "disabled"}});
        }
    }

    // PM007: not the initial mode, and no mode may change into it.
    void checkEverCurrent(std::size_t index)
    {
        const Mode& mode = m_configuration.modes[index];
        if (mode.number == m_configuration.initialMode)
            return;
        for (const Mode& other : m_configuration.modes)
            if (other.number != mode.number
                && !modeChangeStates(other.modeChange, mode.modeChange, m_enabled[index].enabled).empty())
                return;
        const std::string label = modeLabel(mode);
        addMode(mode, {"PM007", Severity::Warning, "modeChange",
                       "mode " + label
                           + " can never be current: it is not the initial mode, and no state allows a change "
                             "into it from another mode",
                       {label}});
    }

    void checkGrafcetChoices(const Mode& mode, const StateSet& enabled)
    {
        for (const StateInfo& info : states()) {
            const GrafcetChoice& choice = mode.grafcetChoice(info.state);
            if (choice.kind == GrafcetChoice::Kind::Own && !enabled.contains(info.state))
                addModeState(mode, info.state,
                             {"PM014", Severity::Info, "grafcet",
                              "the GRAFCET of " + modeLabel(mode) + ": " + std::string(info.name)
                                  + " is kept, but the mode disables the state: it generates no code",
                              {modeLabel(mode), std::string(info.name)}});
            if (choice.kind == GrafcetChoice::Kind::SameAs && enabled.contains(info.state))
                checkSameAs(mode, info.state, choice.sameAsMode);
        }
    }

    void checkSameAs(const Mode& mode, State state, int owner)
    {
        const Mode* ownerMode = m_configuration.mode(owner);
        const char* reason = ownerMode == nullptr   ? "no-mode"
            : owner == mode.number                  ? "itself"
            : ownerMode->grafcetChoice(state).kind != GrafcetChoice::Kind::Own ? "not-own"
                                                                                : nullptr;
        if (reason == nullptr)
            return;
        const std::string label = modeLabel(mode);
        const std::string name(stateName(state));
        const std::string k = std::to_string(owner);
        const std::string why = ownerMode == nullptr ? "there is no mode " + k
            : owner == mode.number                   ? "that is the mode itself"
                                                     : "mode " + k + " has no GRAFCET of its own there";
        addModeState(mode, state,
                     {"PM015", Severity::Error, "grafcet",
                      label + ": " + name + " runs the same GRAFCET as mode " + k + ", but " + why,
                      {label, name, k, reason}});
    }

    const Configuration& m_configuration;
    std::string m_programName;
    std::vector<std::string> m_modeNames;
    std::vector<EnabledStates> m_enabled; // by mode index
    std::vector<Diagnostic> m_result;
};

} // namespace

std::vector<Diagnostic> checkModes(const Model& model)
{
    return ModeChecker(model).run();
}

} // namespace core::packml
