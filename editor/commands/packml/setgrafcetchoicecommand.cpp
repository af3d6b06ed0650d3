#include "editor/commands/packml/setgrafcetchoicecommand.h"

#include "editor/commands/commandids.h"
#include "editor/commands/packml/packmlcommandlabels.h"
#include "editor/document.h"

#include "core/model/model.h"

namespace editor {

namespace {

using core::packml::GrafcetChoice;

QString describe(const QString& mode, core::packml::State state, const GrafcetChoice& choice)
{
    const QString stateName = toQString(core::packml::stateName(state));
    switch (choice.kind) {
    case GrafcetChoice::Kind::Own:
        return SetGrafcetChoiceCommand::tr("Give %1 its own GRAFCET in mode %2").arg(stateName, mode);
    case GrafcetChoice::Kind::SameAs:
        return SetGrafcetChoiceCommand::tr("Run in %1 of mode %2 the GRAFCET of mode %3")
            .arg(stateName, mode)
            .arg(choice.sameAsMode);
    case GrafcetChoice::Kind::None: break;
    }
    return SetGrafcetChoiceCommand::tr("Remove the GRAFCET of %1 in mode %2").arg(stateName, mode);
}

} // namespace

SetGrafcetChoiceCommand::SetGrafcetChoiceCommand(Document& document, int mode, core::packml::State state,
                                                 GrafcetChoice choice)
    : ModelCommand(document,
                   [title = modeTitleOf(document.model(), mode), state, choice] { return describe(title, state, choice); })
    , m_mode(mode)
    , m_state(state)
    , m_choice(choice)
{
}

int SetGrafcetChoiceCommand::id() const
{
    return SetGrafcetChoiceId;
}

core::Status SetGrafcetChoiceCommand::apply()
{
    if (firstRun() && model().packml()) {
        if (const core::packml::Mode* mode = model().packml()->mode(m_mode))
            m_previous = mode->grafcetChoice(m_state);
        if (const core::Grafcet* grafcet = model().grafcet(core::packml::grafcetKey(m_mode, m_state)))
            m_previousGrafcet = *grafcet;
    }
    return model().setGrafcetChoice(m_mode, m_state, m_choice);
}

core::Status SetGrafcetChoiceCommand::revert()
{
    if (m_previous.kind == GrafcetChoice::Kind::Own && m_previousGrafcet)
        return model().setGrafcet(core::packml::grafcetKey(m_mode, m_state), *m_previousGrafcet);
    return model().setGrafcetChoice(m_mode, m_state, m_previous);
}

} // namespace editor
