#pragma once

// The texts of the PackML chart that depend on the mode shown: the labels of
// its arrows and the tooltips of its states and arrows, in the UI language.

#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlrules.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>

namespace editor {

class PackmlChartTexts {
    Q_DECLARE_TR_FUNCTIONS(editor::PackmlChartTexts)

public:
    // "1 Production": how the mode selector and the tooltips name a mode.
    static QString modeTitle(int number, const QString& name);
    static QString modeTitle(const core::packml::Mode& mode);

    // What an arrow's label may say, longest first (PackmlArrowItem picks
    // the first that fits): "Reset", "SC"; where the target is skipped
    // "Reset → Idle" then "→ Idle".
    static QStringList transitionLabels(const core::packml::TemplateTransition& transition,
                                        const std::optional<core::packml::Destination>& destination);
    // A frame's arrow: "Abort", with its condition when not the default
    // ("Abort: Cmd_Abort OR NOT EStopOK"), and "→ Aborted" after the command
    // when Aborting is skipped; one text, elided at its end if need be.
    static QStringList frameLabels(core::packml::Command command, const QString& condition, bool defaultCondition,
                                   const std::optional<core::packml::Destination>& destination);

    // The state's name, kind and meaning, and whether the mode shown
    // disables it (`mode` empty: the template, no mode); for a state that
    // holds a GRAFCET, what runs there in that mode (`grafcet` nullopt: no
    // mode shown).
    static QString stateToolTip(core::packml::State state, const QString& displayName, bool disabled,
                                const QString& mode, const std::optional<core::packml::GrafcetChoice>& grafcet);
    // Source → target, the command and what it does (or what SC means),
    // whether it is optional, and where it leads in the mode shown.
    static QString transitionToolTip(const core::packml::TemplateTransition& transition,
                                     const std::optional<core::packml::Destination>& destination, const QString& mode);
    // The frame's command, what it does, which states accept it, its condition.
    static QString frameToolTip(core::packml::Command command, const QString& condition,
                                const std::optional<core::packml::Destination>& destination, const QString& mode);
};

} // namespace editor
