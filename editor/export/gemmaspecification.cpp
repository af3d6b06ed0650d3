#include "editor/export/gemmaspecification.h"

#include "editor/chart/gemma/chartscene.h"
#include "editor/document.h"
#include "editor/export/chartexport.h"
#include "editor/machine/machinescene.h"
#include "editor/machine/machinetext.h"
#include "editor/simulation/simulationsession.h"
#include "editor/stdstring.h"
#include "editor/text/elementlabels.h"
#include "editor/text/gemmastatenames.h"

#include "core/codegen/plcproject.h"
#include "core/model/model.h"

#include <QImage>
#include <QPainter>

#include <algorithm>

namespace editor::specification {

QString GemmaSpecificationPages::stateLabel(const QString& id)
{
    return id + QLatin1Char(' ') + officialStateName(id);
}

GemmaSpecificationPages::GemmaSpecificationPages(Document& document, const QDateTime& date,
                                                 QPagedPaintDevice& device, const QSizeF& printable,
                                                 double dotsPerPoint)
    : SpecificationPages(document, date, device, printable, dotsPerPoint)
    , m_titleSection(tr("Specification"))
    , m_chartSection(tr("GEMMA chart"))
    , m_tablesSection(tr("States, transitions and variables"))
    , m_machineSection(tr("Machine"))
    , m_grafcetSection(tr("Nested GRAFCETs"))
    , m_codeSection(tr("Generated code"))
{
    m_chartScene = &keepScene(std::make_unique<ChartScene>(&document, &m_selection));
    if (!m_model.machine().empty()) {
        // The machine at rest: a session that never runs, owned by the scene
        // so that it outlives the scene's items.
        auto* rest = new SimulationSession(&document);
        m_machineScene = &keepScene(std::make_unique<MachineScene>(&document, rest));
        rest->setParent(m_machineScene);
    }
    setSectionNames({m_titleSection, m_chartSection, m_tablesSection, m_machineSection, m_grafcetSection,
                     m_codeSection});
    for (const core::Step& step : m_model.steps()) {
        if (m_model.effectiveGrafcet(step.id))
            m_grafcetSteps << fromStd(step.id);
    }
    // The contents, whose pages the sections fill in.
    m_chartEntry = addContentsEntry(tr("GEMMA chart"));
    m_statesEntry = addContentsEntry(tr("States"));
    m_transitionsEntry = addContentsEntry(tr("Transitions"));
    m_variablesEntry = addContentsEntry(tr("Variables"));
    if (m_machineScene)
        m_machineEntry = addContentsEntry(tr("Machine"));
    if (!m_grafcetSteps.isEmpty()) {
        m_grafcetsEntry = addContentsEntry(tr("Nested GRAFCETs"));
        for (const QString& id : std::as_const(m_grafcetSteps))
            addContentsEntry(stateLabel(id), true);
    }
    m_codeEntry = addContentsEntry(tr("Generated code"));
}

std::vector<SpecificationPages::Section> GemmaSpecificationPages::sections()
{
    std::vector<Section> sections{[this] { planTitlePage(); }, [this] { planChart(); }, [this] { planStates(); },
                                  [this] { planTransitions(); }, [this] { planVariables(m_variablesEntry); }};
    if (m_machineScene)
        sections.push_back([this] { planMachine(); });
    for (qsizetype i = 0; i < m_grafcetSteps.size(); ++i)
        sections.push_back([this, i] { planGrafcet(i); });
    sections.push_back([this] { planCode(); });
    return sections;
}

void GemmaSpecificationPages::planTitlePage()
{
    const core::ModelSettings& settings = m_model.settings();
    QList<QStringList> facts{{tr("Initial state"), stateLabel(fromStd(m_model.initialStep().id))}};
    facts << cycleAndDialectFacts();
    facts << QStringList{tr("Nested GRAFCET evolution"), settings.evolution == core::EvolutionRule::UntilStable
                                                             ? tr("Until stable, in one call of its function block")
                                                             : tr("One evolution per PLC scan")};
    SpecificationPages::planTitlePage(m_titleSection, tr("GEMMA-GRAFCET specification"), facts);
}

// The GEMMA chart on a landscape page, its Conditions list on the next
// pages when it does not fit under it.
void GemmaSpecificationPages::planChart()
{
    Flow& flow = *m_flow;
    flow.newPage(QPageLayout::Landscape, m_chartSection);
    startsHere(m_chartEntry);
    const QFontMetricsF heading = m_style.metrics(TextStyle::Heading);
    const double band = heading.lineSpacing() + m_style.pt(6);
    placeBand(flow, band, m_style.font(TextStyle::Heading), heading.ascent(), inkColor(), tr("GEMMA chart"));
    const QSizeF area(flow.body().width(), flow.room());
    auto pages = std::make_shared<ChartExport::Pages>(*m_chartScene, area);
    for (qsizetype i = 0; i < pages->count(); ++i) {
        if (i > 0) {
            flow.continuePage();
            placeBand(flow, band, m_style.font(TextStyle::Small), m_style.metrics(TextStyle::Small).ascent(),
                      mutedColor(), tr("GEMMA chart, continued"));
        }
        flow.place(area.height(), [pages, i](QPainter& painter, const QPointF& at) {
            painter.translate(at);
            pages->paint(painter, i);
        });
    }
}

void GemmaSpecificationPages::planStates()
{
    m_flow->newPage(QPageLayout::Portrait, m_tablesSection);
    Table states(m_style,
                 {{tr("State"), 38}, {tr("Name"), 118}, {tr("Type"), 84}, {tr("GRAFCET"), 52}, {tr("Comment"), 0}},
                 m_width);
    for (const core::Step& step : m_model.steps()) {
        if (step.hidden)
            continue;
        const QString id = fromStd(step.id);
        QString type = stepTypeText(step.type);
        if (step.initial)
            type = tr("%1, initial").arg(type);
        QString grafcet;
        if (const core::Grafcet* nested = m_model.effectiveGrafcet(step.id))
            grafcet = tr("%n step(s)", nullptr, int(nested->steps().size()));
        states.addRow({id, officialStateName(id), type, orDash(grafcet), orDash(fromStd(step.comment))});
    }
    planTable(m_statesEntry, tr("States"),
              tr("The visible states of the GEMMA chart, in state order. A macro-step or an enclosing "
                 "step runs its nested GRAFCET while it is active."),
              states, QString());
}

// The transitions that take part, by source and priority.
void GemmaSpecificationPages::planTransitions()
{
    Table transitions(m_style,
                      {{tr("Transition"), 92}, {tr("Priority"), 58}, {tr("Condition"), 0}, {tr("Tokens"), 96}},
                      m_width);
    for (const core::Transition& transition : m_model.transitions()) {
        if (!m_model.isEffective(transition))
            continue;
        QString priority = QString::number(m_model.priority(transition.id));
        if (transition.negated)
            priority = tr("%1, negated").arg(priority);
        QStringList tokens;
        for (const std::string& token : transition.tokens)
            tokens << fromStd(token);
        transitions.addRow({transitionLabel(transition), priority, orDash(fromStd(transition.condition)),
                            orDash(tokens.join(QStringLiteral(", ")))});
    }
    planTable(m_transitionsEntry, tr("Transitions"),
              tr("The transitions that take part: visible, between visible states. A state evaluates "
                 "its transitions by priority, 1 first; a negated transition fires when its condition "
                 "is FALSE."),
              transitions, tr("No transition takes part."));
}

// The machine the simulation and `verify --machine` run the program
// against: its components and their wiring, then its schematic at rest.
void GemmaSpecificationPages::planMachine()
{
    namespace machine = core::machine;
    m_flow->newPage(QPageLayout::Portrait, m_machineSection);
    Table components(m_style, {{tr("Component"), 86}, {tr("Kind"), 96}, {tr("Wiring"), 0}, {tr("Settings"), 130}},
                     m_width);
    for (const machine::Component& component : m_model.machine().components) {
        const machine::ComponentKindSpec& spec = machine::kindSpec(component.kind);
        QStringList wiring;
        for (std::size_t i = 0; i < spec.roles.size() && i < component.wires.size(); ++i) {
            if (!component.wires[i].empty())
                wiring << tr("%1: %2").arg(machinetext::roleName(spec.roles[i].key), fromStd(component.wires[i]));
        }
        QStringList settings;
        for (std::size_t i = 0; i < spec.parameters.size() && i < component.parameters.size(); ++i) {
            const std::int64_t value = component.parameters[i];
            const QString shown = value == machine::kUnlimitedParts ? tr("unlimited") : QString::number(value);
            settings << tr("%1: %2").arg(machinetext::parameterName(spec.parameters[i].key), shown);
        }
        if (spec.hasContact)
            settings << machinetext::contactName(component.contact);
        if (spec.feedsConveyor && !component.conveyor.empty())
            settings << tr("Feeds %1").arg(fromStd(component.conveyor));
        components.addRow({fromStd(component.name), machinetext::kindName(component.kind),
                           orDash(wiring.join(QLatin1Char('\n'))), orDash(settings.join(QLatin1Char('\n')))});
    }
    planTable(m_machineEntry, tr("Machine"),
              tr("The virtual machine the simulation runs the program against, in closed loop: after each "
                 "scan the components move one cycle time from the outputs wired to them and set the "
                 "sensors the next scan reads; operator inputs stay the user's. Times are in "
                 "milliseconds, counted in whole cycles."),
              components, QString());
    planMachineDrawing();
}

// The Machine tab's schematic at rest, as wide as the page, at most half its
// height. Drawn as a picture: the tab elides a label to its cell, while the
// PDF's text is never cut short (the table above names everything in full).
void GemmaSpecificationPages::planMachineDrawing()
{
    Flow& flow = *m_flow;
    const QRectF source = m_machineScene->itemsBoundingRect();
    if (source.isEmpty())
        return;
    const double scale = std::min(m_width / source.width(), flow.body().height() / 2 / source.height());
    const QSizeF size = source.size() * scale;
    constexpr double kPixelsPerPoint = 3; // 216 dpi
    QImage picture((size * (kPixelsPerPoint / m_style.pt(1))).toSize(), QImage::Format_ARGB32_Premultiplied);
    picture.fill(Qt::white);
    {
        QPainter painter(&picture);
        painter.setRenderHint(QPainter::Antialiasing);
        m_machineScene->render(&painter, QRectF(QPointF(), picture.size()), source);
    }
    addHeading(flow, m_style, TextStyle::Subheading, tr("The machine at rest"), size.height());
    flow.place(size.height(), [picture, size](QPainter& painter, const QPointF& at) {
        painter.drawImage(QRectF(at, size), picture);
    });
}

void GemmaSpecificationPages::planGrafcet(qsizetype index)
{
    const QString id = m_grafcetSteps[index];
    const core::Step* step = m_model.step(id.toStdString());
    GrafcetPart part{id,
                     stateLabel(id),
                     {stepTypeText(step->type)},
                     tr("Nested GRAFCET of %1, continued").arg(id),
                     tr("Steps of %1").arg(id),
                     id + QStringLiteral("_FB"),
                     {}};
    if (index == 0)
        part.contentsEntries.push_back(m_grafcetsEntry);
    part.contentsEntries.push_back(m_grafcetsEntry + 1 + std::size_t(index));
    SpecificationPages::planGrafcet(m_grafcetSection, part);
}

void GemmaSpecificationPages::planCode()
{
    SpecificationPages::planCode(
        m_codeSection, m_codeEntry, m_variablesEntry,
        tr("GG Studio generates the PLC program as IEC 61131-3 Structured Text by the "
           "Hierarchical Design Pattern: the program %1 holds the active GEMMA state and evaluates "
           "its transitions by priority, and each visible macro-step or enclosing step is a "
           "function block that %1 calls while that state is active. This outline gives the "
           "program organisation units and their interfaces; File > Export Structured Text and "
           "Export PLCopen XML write the code itself."),
        [this](const core::PlcPou& pou, const QString& program) { return describePou(pou, program); });
}

QString GemmaSpecificationPages::describePou(const core::PlcPou& pou, const QString& program) const
{
    if (pou.kind == core::PouKind::Program) {
        return tr("The GEMMA layer: it holds the active state in State, evaluates that "
                  "state's transitions by priority and calls the function block of a state "
                  "with nested behaviour while that state is active.");
    }
    QString stepId = fromStd(pou.name);
    stepId.chop(3); // "_FB"
    const auto page = m_grafcetPages.find(stepId);
    if (page != m_grafcetPages.end()) {
        return tr("The nested GRAFCET of %1 (page %2). %3 calls it through its "
                  "instance %4 while %4 is active.")
            .arg(stateLabel(stepId), QString::number(page->second), program, stepId);
    }
    return tr("The nested behaviour of %1, not written yet: until it is, the "
              "function block completes at once. %2 calls it through its instance "
              "%3.")
        .arg(stateLabel(stepId), program, stepId);
}

} // namespace editor::specification
