#include "editor/commands/packml/removemodecommand.h"

#include "editor/commands/commandids.h"
#include "editor/commands/packml/packmlcommandlabels.h"
#include "editor/document.h"

#include "core/model/model.h"

namespace editor {

namespace {

using core::packml::GrafcetChoice;

constexpr int kProduction = 1;

} // namespace

RemoveModeCommand::RemoveModeCommand(Document& document, int mode)
    : ModelCommand(document, [title = modeTitleOf(document.model(), mode)] { return tr("Remove mode %1").arg(title); })
    , m_mode(mode)
{
}

int RemoveModeCommand::id() const
{
    return RemoveModeId;
}

void RemoveModeCommand::capture()
{
    const core::packml::Configuration& configuration = *model().packml();
    m_removed = *configuration.mode(m_mode);
    m_wasInitialMode = configuration.initialMode == m_mode;
    for (const core::packml::StateInfo& info : core::packml::states()) {
        const std::string key = core::packml::grafcetKey(m_mode, info.state);
        if (const core::Grafcet* grafcet = model().grafcet(key))
            m_grafcets.emplace(key, *grafcet);
    }
    for (const core::packml::Mode& other : configuration.modes)
        for (const core::packml::StateInfo& info : core::packml::states()) {
            const GrafcetChoice& choice = other.grafcetChoice(info.state);
            if (choice.kind == GrafcetChoice::Kind::SameAs && choice.sameAsMode == m_mode)
                m_redirected.push_back({other.number, info.state});
        }
}

core::Status RemoveModeCommand::apply()
{
    if (m_mode == kProduction)
        return core::Status::failure("production-mode", "Production (1) is the mode every unit has; it stays");
    if (firstRun()) {
        if (!model().packml())
            return model().removeMode(m_mode); // says why
        if (!model().packml()->mode(m_mode))
            return model().removeMode(m_mode);
        capture();
    }
    if (core::Status status = model().removeMode(m_mode); !status)
        return status;
    // The initial mode goes to Production, as for a new model (spec §3.1).
    return m_wasInitialMode ? model().setPackMLInitialMode(kProduction) : core::Status::success();
}

core::Status RemoveModeCommand::revert()
{
    core::Model& edited = model();
    if (core::Status status = edited.addMode(m_mode, m_removed.name); !status)
        return status;
    edited.setModeComment(m_mode, m_removed.comment);
    edited.setModeRequest(m_mode, m_removed.request);
    edited.setModeDisabled(m_mode, m_removed.disabled);
    edited.setModeChangeStates(m_mode, m_removed.modeChange);
    for (const core::packml::StateInfo& info : core::packml::states())
        if (core::packml::holdsGrafcet(info.state))
            edited.setGrafcetChoice(m_mode, info.state, m_removed.grafcetChoice(info.state));
    for (const auto& [key, grafcet] : m_grafcets)
        edited.setGrafcet(key, grafcet);
    for (const Redirected& choice : m_redirected)
        edited.setGrafcetChoice(choice.mode, choice.state, GrafcetChoice::sameAs(m_mode));
    if (m_wasInitialMode)
        edited.setPackMLInitialMode(m_mode);
    return core::Status::success();
}

} // namespace editor
