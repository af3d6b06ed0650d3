#include "editor/export/packmlspecification.h"

#include "editor/chart/packml/packmlchartscene.h"
#include "editor/document.h"
#include "editor/export/packmlchartexport.h"
#include "editor/stdstring.h"
#include "editor/text/packmltexts.h"

#include "core/codegen/plcproject.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlrules.h"

namespace editor::specification {

namespace {

QString modeName(const core::packml::Mode& mode)
{
    return fromStd(std::string(mode.displayName()));
}

// "1 Production", as the mode selector names it.
QString modeLabel(const core::packml::Mode& mode)
{
    return QStringLiteral("%1 %2").arg(mode.number).arg(modeName(mode));
}

// The states the mode's code leaves out: those it lists and those its
// listing makes unreachable (spec §3.2).
core::packml::StateSet effectiveDisabled(const core::packml::Mode& mode)
{
    const core::packml::StateSet enabled = core::packml::enabledStates(mode.disabled).enabled;
    core::packml::StateSet disabled;
    for (const core::packml::StateInfo& info : core::packml::states()) {
        if (!enabled.contains(info.state))
            disabled.insert(info.state);
    }
    return disabled;
}

} // namespace

QString PackmlSpecificationPages::grafcetTitle(const core::packml::Mode& mode, core::packml::State state)
{
    return modeName(mode) + QStringLiteral(" · ") + packmltext::stateName(state);
}

PackmlSpecificationPages::PackmlSpecificationPages(Document& document, const QDateTime& date,
                                                   QPagedPaintDevice& device, const QSizeF& printable,
                                                   double dotsPerPoint)
    : SpecificationPages(document, date, device, printable, dotsPerPoint)
    , m_configuration(*m_model.packml())
    , m_titleSection(tr("Specification"))
    , m_chartSection(tr("PackML chart"))
    , m_tablesSection(tr("Commands, modes and variables"))
    , m_grafcetSection(tr("Nested GRAFCETs"))
    , m_codeSection(tr("Generated code"))
{
    m_chartScene = &keepScene(std::make_unique<PackmlChartScene>(&m_model, &m_selection));
    setSectionNames({m_titleSection, m_chartSection, m_tablesSection, m_grafcetSection, m_codeSection});
    for (const core::packml::Mode& mode : m_configuration.modes) {
        for (const core::packml::StateInfo& info : core::packml::states()) {
            const std::string key = core::packml::grafcetKey(mode.number, info.state);
            if (m_model.grafcet(key) && m_model.effectiveGrafcet(key))
                m_grafcets.emplace_back(mode.number, info.state);
        }
    }
    // The contents, whose pages the sections fill in.
    m_chartEntry = addContentsEntry(tr("PackML chart"));
    for (const core::packml::Mode& mode : m_configuration.modes)
        addContentsEntry(tr("Unit mode %1").arg(modeLabel(mode)), true);
    m_commandsEntry = addContentsEntry(tr("Commands"));
    m_modesEntry = addContentsEntry(tr("Unit modes"));
    m_variablesEntry = addContentsEntry(tr("Variables"));
    if (!m_grafcets.empty()) {
        m_grafcetsEntry = addContentsEntry(tr("Nested GRAFCETs"));
        for (const auto& [number, state] : m_grafcets)
            addContentsEntry(grafcetTitle(*m_configuration.mode(number), state), true);
    }
    m_codeEntry = addContentsEntry(tr("Generated code"));
}

std::vector<SpecificationPages::Section> PackmlSpecificationPages::sections()
{
    std::vector<Section> sections{[this] { planTitlePage(); }, [this] { planCharts(); },
                                  [this] { planCommands(); }, [this] { planModes(); },
                                  [this] { planVariables(m_variablesEntry); }};
    for (qsizetype i = 0; i < qsizetype(m_grafcets.size()); ++i)
        sections.push_back([this, i] { planGrafcet(i); });
    sections.push_back([this] { planCode(); });
    return sections;
}

void PackmlSpecificationPages::planTitlePage()
{
    const core::packml::Options& options = m_configuration.options;
    QString edition = options.edition == core::packml::Edition::Y2022 ? tr("PackML, 2022 edition")
                                                                      : tr("PackML, 2015 edition");
    QStringList optional;
    if (options.holdInSuspended)
        optional << tr("Hold accepted in Suspended");
    if (options.completeInSuspendedHeld)
        optional << tr("Complete accepted in Suspended and Held");
    if (!optional.isEmpty())
        edition = tr("%1; options: %2").arg(edition, optional.join(QStringLiteral(", ")));
    const core::packml::Mode* initialMode = m_configuration.mode(m_configuration.initialMode);
    const core::ModelSettings& settings = m_model.settings();
    QList<QStringList> facts{
        {tr("Template"), edition},
        {tr("Initial state"), packmltext::stateName(m_configuration.initialState)},
        {tr("Initial unit mode"), initialMode ? modeLabel(*initialMode) : QString::number(m_configuration.initialMode)}};
    facts << cycleAndDialectFacts();
    facts << QStringList{tr("Nested GRAFCET evolution"), settings.evolution == core::EvolutionRule::UntilStable
                                                             ? tr("Until stable, in one call of its function block")
                                                             : tr("One evolution per PLC scan")};
    SpecificationPages::planTitlePage(m_titleSection, tr("PackML specification"), facts);
}

// The chart of each unit mode on a landscape page of its own, as Export
// Chart draws it for that mode (its disabled states greyed, its skipped
// transitions re-labelled).
void PackmlSpecificationPages::planCharts()
{
    Flow& flow = *m_flow;
    std::size_t entry = m_chartEntry + 1;
    for (const core::packml::Mode& mode : m_configuration.modes) {
        flow.newPage(QPageLayout::Landscape, m_chartSection);
        if (entry == m_chartEntry + 1)
            startsHere(m_chartEntry);
        startsHere(entry++);
        const QSizeF area(flow.body().width(), flow.room());
        flow.place(area.height(), [scene = m_chartScene, number = mode.number, area](QPainter& painter,
                                                                                     const QPointF& at) {
            scene->setMode(number);
            painter.translate(at);
            PackmlChartExport(*scene).paintPage(painter, area);
        });
    }
}

void PackmlSpecificationPages::planCommands()
{
    m_flow->newPage(QPageLayout::Portrait, m_tablesSection);
    Table commands(m_style, {{tr("Command"), 70}, {tr("CntrlCmd"), 50}, {tr("Condition"), 0}, {tr("Comment"), 0}},
                   m_width);
    for (const core::packml::CommandInfo& info : core::packml::allCommands()) {
        if (!core::packml::commandInEdition(info.command, m_configuration.options.edition))
            continue;
        const core::packml::CommandSetting& setting = m_configuration.command(info.command);
        commands.addRow({packmltext::commandName(info.command), QString::number(int(info.command)),
                         orDash(fromStd(setting.condition)), orDash(fromStd(setting.comment))});
    }
    planTable(m_commandsEntry, tr("Commands"),
              tr("The commands of the edition, with the condition whose rising edge issues each one "
                 "(besides CntrlCmd). A command a state does not accept is ignored there."),
              commands, QString());
}

void PackmlSpecificationPages::planModes()
{
    Table modes(m_style,
                {{tr("Mode"), 30},
                 {tr("Name"), 70},
                 {tr("Request condition"), 0},
                 {tr("Disabled states"), 0},
                 {tr("Mode change allowed in"), 0},
                 {tr("Comment"), 0}},
                m_width);
    for (const core::packml::Mode& mode : m_configuration.modes) {
        modes.addRow({QString::number(mode.number), modeName(mode), orDash(fromStd(mode.request)),
                      orDash(stateListText(effectiveDisabled(mode))), orDash(stateListText(mode.modeChange)),
                      orDash(fromStd(mode.comment))});
    }
    planTable(m_modesEntry, tr("Unit modes"),
              tr("The unit modes, in number order. A mode skips its disabled states; the unit changes "
                 "to a mode when its request condition rises while the current mode allows a change in "
                 "the current state."),
              modes, QString());
    for (const core::packml::Mode& mode : m_configuration.modes)
        planModeGrafcets(mode);
}

// Which GRAFCET each acting state and Execute runs in one mode.
void PackmlSpecificationPages::planModeGrafcets(const core::packml::Mode& mode)
{
    Table grafcets(m_style, {{tr("State"), 80}, {tr("Nested GRAFCET"), 0}}, m_width);
    for (const core::packml::StateInfo& info : core::packml::states()) {
        if (core::packml::holdsGrafcet(info.state))
            grafcets.addRow({packmltext::stateName(info.state), grafcetChoiceText(mode, info.state)});
    }
    addHeading(*m_flow, m_style, TextStyle::Subheading, tr("Nested GRAFCETs in %1").arg(modeLabel(mode)),
               grafcets.startHeight());
    grafcets.flowInto(*m_flow);
}

QString PackmlSpecificationPages::grafcetChoiceText(const core::packml::Mode& mode, core::packml::State state) const
{
    if (effectiveDisabled(mode).contains(state))
        return tr("None: the mode disables this state");
    const core::packml::GrafcetChoice& choice = mode.grafcetChoice(state);
    switch (choice.kind) {
    case core::packml::GrafcetChoice::Kind::Own:
        return tr("Own: %1").arg(grafcetTitle(mode, state));
    case core::packml::GrafcetChoice::Kind::SameAs: {
        const core::packml::Mode* owner = m_configuration.mode(choice.sameAsMode);
        return owner ? tr("Same as mode %1: %2").arg(modeLabel(*owner), grafcetTitle(*owner, state))
                     : tr("Same as mode %1, which does not exist").arg(choice.sameAsMode);
    }
    case core::packml::GrafcetChoice::Kind::None:
        break;
    }
    return core::packml::isActing(state) ? tr("None: the state completes at once")
                                         : tr("None: Execute waits for a command");
}

QString PackmlSpecificationPages::stateListText(const core::packml::StateSet& states) const
{
    QStringList names;
    for (const core::packml::State state : states.list())
        names << packmltext::stateName(state);
    return names.join(QStringLiteral(", "));
}

void PackmlSpecificationPages::planGrafcet(qsizetype index)
{
    const auto [number, state] = m_grafcets[std::size_t(index)];
    const core::packml::Mode& mode = *m_configuration.mode(number);
    const QString title = grafcetTitle(mode, state);
    GrafcetPart part{fromStd(core::packml::grafcetKey(number, state)),
                     title,
                     {packmltext::stateKindName(core::packml::stateInfo(state).kind)},
                     tr("Nested GRAFCET %1, continued").arg(title),
                     tr("Steps of %1").arg(title),
                     fromStd(core::packml::grafcetTypeName(mode.displayName(), state)),
                     {}};
    if (index == 0)
        part.contentsEntries.push_back(m_grafcetsEntry);
    part.contentsEntries.push_back(m_grafcetsEntry + 1 + std::size_t(index));
    SpecificationPages::planGrafcet(m_grafcetSection, part);
}

void PackmlSpecificationPages::planCode()
{
    SpecificationPages::planCode(
        m_codeSection, m_codeEntry, m_variablesEntry,
        tr("GG Studio generates the PLC program as IEC 61131-3 Structured Text by the PackML design "
           "pattern: the program %1 is the state and mode manager, with the PackTags interface; it "
           "calls, in each acting state and Execute, the function block instance of the current "
           "unit mode and state, whose State Complete ends that state. This outline gives the "
           "program organisation units and their interfaces; File > Export Structured Text and "
           "Export PLCopen XML write the code itself."),
        [this](const core::PlcPou& pou, const QString& program) { return describePou(pou, program); });
}

QString PackmlSpecificationPages::describePou(const core::PlcPou& pou, const QString& program) const
{
    if (pou.kind == core::PouKind::Program) {
        return tr("The PackML state and mode manager: it latches the commands and mode requests, "
                  "holds the current state and unit mode in StateCurrent and UnitModeCurrent, "
                  "evaluates the current state's transitions in the current mode and calls the "
                  "function block instance of that mode and state.");
    }
    const std::string name = pou.name;
    for (const auto& [number, state] : m_grafcets) {
        const core::packml::Mode& mode = *m_configuration.mode(number);
        if (core::packml::grafcetTypeName(mode.displayName(), state) != name)
            continue;
        const auto page = m_grafcetPages.find(fromStd(core::packml::grafcetKey(number, state)));
        return tr("The nested GRAFCET %1 (page %2). %3 calls it while the unit is in %4 in a mode that "
                  "runs it; its Complete is that state's State Complete.")
            .arg(grafcetTitle(mode, state), QString::number(page == m_grafcetPages.end() ? 0 : page->second),
                 program, packmltext::stateName(state));
    }
    for (const core::packml::StateInfo& info : core::packml::states()) {
        if (core::packml::holdsGrafcet(info.state) && core::packml::skeletonTypeName(info.state) == name) {
            return tr("The function block of %1 in the modes without a GRAFCET there: %2")
                .arg(packmltext::stateName(info.state),
                     core::packml::isActing(info.state) ? tr("it completes at once.")
                                                        : tr("it does nothing, Execute waits for a command."));
        }
    }
    return QString();
}

} // namespace editor::specification
