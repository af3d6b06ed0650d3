#include "editor/export/specificationpages.h"

#include "editor/docks/variablestablemodel.h"
#include "editor/document.h"
#include "editor/export/exportoptionsdialog.h"
#include "editor/grafcet/grafcetexport.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/stdstring.h"

#include "core/checks/diagnostic.h"
#include "core/codegen/stgenerator.h"
#include "core/model/model.h"

#include <QFileInfo>
#include <QLocale>
#include <QPagedPaintDevice>

#include <algorithm>

namespace editor::specification {

SpecificationPages::SpecificationPages(Document& document, const QDateTime& date, QPagedPaintDevice& device,
                                       const QSizeF& printable, double dotsPerPoint)
    : m_document(document)
    , m_model(document.model())
    , m_style(device, dotsPerPoint)
    , m_width(printable.width())
    , m_modelName(fromStd(m_model.settings().name))
    , m_date(date)
    , m_device(device)
    , m_printable(printable)
    , m_contents(std::make_shared<std::vector<ContentsEntry>>())
{
}

void SpecificationPages::setSectionNames(const QStringList& names)
{
    const QFontMetricsF small = m_style.metrics(TextStyle::Small);
    double sectionWidth = 0;
    for (const QString& section : names)
        sectionWidth = std::max(sectionWidth, small.horizontalAdvance(section));
    m_headerLines = m_style.wrap(TextStyle::Small, m_modelName, m_width - sectionWidth - m_style.pt(12));
    if (m_headerLines.isEmpty())
        m_headerLines << QString();
    m_bodyTop = m_style.pt(kHeaderBand) + double(m_headerLines.size() - 1) * small.lineSpacing();
    m_flow.emplace(m_printable, m_bodyTop + m_style.pt(kFooterBand));
}

std::size_t SpecificationPages::addContentsEntry(const QString& text, bool sub)
{
    m_contents->push_back({text, sub});
    return m_contents->size() - 1;
}

bool SpecificationPages::write(QPainter& painter, const SpecificationExport::Progress& progress)
{
    const std::vector<Section> planned = sections();
    int done = 0;
    const auto tell = [&](int total) { return !progress || progress(++done, total); };
    for (const Section& section : planned) {
        section();
        if (!tell(int(planned.size()) + 1)) // the pages are one more part until counted
            return false;
    }
    const int pages = int(m_flow->pages().size());
    return paint(painter, [&] { return tell(int(planned.size()) + pages); });
}

int SpecificationPages::errorCount() const
{
    int errors = 0;
    for (const core::Diagnostic& diagnostic : m_document.diagnostics())
        errors += diagnostic.severity == core::Severity::Error ? 1 : 0;
    return errors;
}
void SpecificationPages::planTitlePage(const QString& section, const QString& subtitle,
                                       const QList<QStringList>& facts)
{
    Flow& flow = *m_flow;
    flow.newPage(QPageLayout::Portrait, section);
    flow.place(m_style.pt(70), [](QPainter&, const QPointF&) {});
    addText(flow, m_style, TextStyle::Title, m_modelName);
    flow.space(m_style.pt(4));
    addText(flow, m_style, TextStyle::Subtitle, subtitle, 0, mutedColor());
    flow.space(m_style.pt(28));

    int warnings = 0;
    for (const core::Diagnostic& diagnostic : m_document.diagnostics())
        warnings += diagnostic.severity == core::Severity::Warning ? 1 : 0;
    QStringList checks;
    if (const int errors = errorCount(); errors > 0)
        checks << tr("%n error(s)", nullptr, errors);
    if (warnings > 0)
        checks << tr("%n warning(s)", nullptr, warnings);
    const QString file = QFileInfo(m_document.filePath()).fileName();
    Table table(m_style, {{QString(), 150}, {QString(), 0}}, m_width, false, true);
    table.addRow({tr("File"), file.isEmpty() ? tr("not saved yet") : file});
    table.addRow({tr("Date"), QLocale().toString(m_date.date(), QLocale::LongFormat) + QStringLiteral(", ")
                                  + QLocale().toString(m_date.time(), QLocale::ShortFormat)});
    for (const QStringList& fact : facts)
        table.addRow(fact);
    table.addRow({tr("Checks"), checks.isEmpty() ? tr("No problems found") : checks.join(QStringLiteral(", "))});
    table.addRow({tr("Written by"), tr("GG Studio %1").arg(QStringLiteral(GGSTUDIO_VERSION))});
    table.flowInto(flow);

    addHeading(flow, m_style, TextStyle::Subheading, tr("Contents"), bodyLine());
    const QFont font = m_style.font(TextStyle::Body);
    const double spacing = bodyLine() * 1.15;
    const double indent = m_style.pt(16);
    const double width = m_width;
    for (std::size_t i = 0; i < m_contents->size(); ++i) {
        flow.add(spacing, [contents = m_contents, i, font, spacing, indent, width](QPainter& painter,
                                                                                  const QPointF& at) {
            const ContentsEntry& entry = (*contents)[i];
            painter.setFont(font);
            painter.setPen(inkColor());
            const double left = entry.sub ? indent : 0;
            const QRectF line(at.x() + left, at.y(), width - left, spacing);
            painter.drawText(line, Qt::AlignLeft | Qt::AlignVCenter, entry.text);
            painter.drawText(line, Qt::AlignRight | Qt::AlignVCenter, QString::number(entry.page));
        });
    }
}

QList<QStringList> SpecificationPages::cycleAndDialectFacts() const
{
    const core::ModelSettings& settings = m_model.settings();
    return {{tr("PLC task cycle"), tr("%1 ms").arg(settings.cycleTimeMs)},
            {tr("Code dialect"), ExportOptionsDialog::dialectText(settings.dialect)}};
}

void SpecificationPages::planTable(std::size_t entry, const QString& heading, const QString& intro, const Table& table,
                                   const QString& empty)
{
    Flow& flow = *m_flow;
    addHeading(flow, m_style, TextStyle::Heading, heading, 0);
    startsHere(entry);
    addText(flow, m_style, TextStyle::Body, intro, table.startHeight() + m_style.pt(6));
    flow.space(m_style.pt(6));
    if (table.isEmpty())
        addText(flow, m_style, TextStyle::Body, empty);
    else
        table.flowInto(flow);
}

void SpecificationPages::planVariables(std::size_t entry)
{
    Table variables(
        m_style,
        {{tr("Name"), 104}, {tr("Kind"), 54}, {tr("Type"), 44}, {tr("Default"), 58}, {tr("Comment"), 0}},
        m_width);
    for (const core::Variable& variable : m_model.variables()) {
        variables.addRow({fromStd(variable.name), VariablesTableModel::kindText(variable.kind),
                          fromStd(std::string(core::iecTypeName(variable.type))),
                          orDash(fromStd(variable.defaultValue)), orDash(fromStd(variable.comment))});
    }
    planTable(entry, tr("Variables"),
              tr("The declared variables, in declaration order. Inputs are read from the machine, "
                 "outputs written by the actions of the nested GRAFCETs, internal variables are the "
                 "program's memory. A variable without a default starts at its type's (FALSE, 0)."),
              variables, tr("No variables are declared."));
}

// A nested GRAFCET from a new page: its heading, its drawing (over as many
// pages as it needs), its steps' comments.
void SpecificationPages::planGrafcet(const QString& section, const GrafcetPart& part)
{
    Flow& flow = *m_flow;
    const QString& id = part.key;
    const core::Grafcet* grafcet = m_model.effectiveGrafcet(id.toStdString());
    flow.newPage(QPageLayout::Portrait, section);
    for (const std::size_t entry : part.contentsEntries)
        startsHere(entry);
    m_grafcetPages[id] = flow.pageNumber();

    // The heading band: as high on the following pages, which say whose
    // drawing they continue.
    QStringList facts = part.facts;
    facts << tr("%n step(s)", nullptr, int(grafcet->steps().size()))
          << tr("%n transition(s)", nullptr, int(grafcet->transitions().size()));
    if (!part.functionBlock.isEmpty())
        facts << tr("function block %1").arg(part.functionBlock);
    const QStringList titleLines = m_style.wrap(TextStyle::Heading, part.title, m_width);
    const QStringList factLines = m_style.wrap(TextStyle::Small, facts.join(QStringLiteral(" · ")), m_width);
    const QFontMetricsF heading = m_style.metrics(TextStyle::Heading);
    const QFontMetricsF small = m_style.metrics(TextStyle::Small);
    const double band = double(titleLines.size()) * heading.lineSpacing()
                        + double(factLines.size()) * small.lineSpacing() + m_style.pt(10);
    flow.place(band, [=, headingFont = m_style.font(TextStyle::Heading),
                      smallFont = m_style.font(TextStyle::Small)](QPainter& painter, const QPointF& at) {
        painter.setFont(headingFont);
        painter.setPen(inkColor());
        double y = at.y();
        for (const QString& line : titleLines) {
            painter.drawText(QPointF(at.x(), y + heading.ascent()), line);
            y += heading.lineSpacing();
        }
        painter.setFont(smallFont);
        painter.setPen(mutedColor());
        for (const QString& line : factLines) {
            painter.drawText(QPointF(at.x(), y + small.ascent()), line);
            y += small.lineSpacing();
        }
    });

    if (grafcet->steps().empty()) {
        addText(flow, m_style, TextStyle::Body, tr("This GRAFCET has no steps yet."));
    } else {
        GrafcetScene& scene = keepScene(std::make_unique<GrafcetScene>(&m_document, id));
        const QSizeF area(flow.body().width(), flow.room());
        auto pages = std::make_shared<GrafcetExport::Pages>(scene, area, m_style.dotsPerPoint(), kMaxGrafcetText);
        for (qsizetype i = 0; i < pages->count(); ++i) {
            if (i > 0) {
                flow.continuePage();
                placeBand(flow, band, m_style.font(TextStyle::Small), small.ascent(), mutedColor(),
                          part.continued);
            }
            flow.place(pages->height(i), [pages, i](QPainter& painter, const QPointF& at) {
                painter.translate(at);
                pages->paint(painter, i);
            });
        }
    }

    std::vector<core::GrafcetStep> steps = grafcet->steps();
    std::sort(steps.begin(), steps.end(),
              [](const core::GrafcetStep& a, const core::GrafcetStep& b) { return a.number < b.number; });
    if (std::none_of(steps.begin(), steps.end(), [](const core::GrafcetStep& s) { return !s.comment.empty(); }))
        return;
    Table comments(m_style, {{tr("Step"), 70}, {tr("Comment"), 0}}, m_width);
    for (const core::GrafcetStep& nested : steps) {
        const QString number = QString::number(nested.number);
        comments.addRow({nested.initial ? tr("%1, initial").arg(number) : number, orDash(fromStd(nested.comment))});
    }
    addHeading(flow, m_style, TextStyle::Subheading, part.stepsHeading, comments.startHeight());
    comments.flowInto(flow);
}

// The outline of the generated code: the task, each POU with its interface,
// the globals the generator adds.
void SpecificationPages::planCode(const QString& section, std::size_t entry, std::size_t variablesEntry,
                                  const QString& intro, const PouDescription& describe)
{
    Flow& flow = *m_flow;
    flow.newPage(QPageLayout::Portrait, section);
    startsHere(entry);
    const core::Dialect dialect = m_model.settings().dialect;
    const core::PlcProject project = core::buildPlcProject(m_model, dialect);
    // The PROGRAM: first in a GEMMA project, after the function blocks in a PackML one.
    const auto programPou = std::find_if(project.pous.begin(), project.pous.end(),
                                         [](const core::PlcPou& pou) { return pou.kind == core::PouKind::Program; });
    const QString program = programPou == project.pous.end() ? QStringLiteral("GEMMA") : fromStd(programPou->name);
    addHeading(flow, m_style, TextStyle::Heading, tr("Generated code"), 0);
    addText(flow, m_style, TextStyle::Body, intro.arg(program));
    if (const int errors = errorCount(); errors > 0) {
        flow.space(m_style.pt(4));
        addText(flow, m_style, TextStyle::Body,
                tr("The model has %n error(s): the generated code marks each one with a comment.", nullptr, errors));
    }

    Table task(m_style, {{QString(), 150}, {QString(), 0}}, m_width, false, true);
    task.addRow({tr("Code dialect"), ExportOptionsDialog::dialectText(dialect)});
    task.addRow({tr("Configuration"), fromStd(project.configurationName)});
    task.addRow({tr("Resource"), fromStd(project.resourceName)});
    task.addRow({tr("Task"), tr("%1: cyclic, every %2, priority %3")
                                 .arg(fromStd(project.taskName), fromStd(core::formatDuration(project.cycleTimeMs)))
                                 .arg(project.taskPriority)});
    task.addRow({tr("Program instance"), fromStd(project.programInstanceName) + QStringLiteral(" : ") + program});
    if (!project.globalListName.empty())
        task.addRow({tr("Global variable list"), fromStd(project.globalListName)});
    addHeading(flow, m_style, TextStyle::Subheading, tr("Task"), task.startHeight());
    task.flowInto(flow);

    QStringList pouNames;
    for (const core::PlcPou& pou : project.pous)
        pouNames << fromStd(pou.name);
    for (const core::PlcPou& pou : project.pous) {
        const QString name = fromStd(pou.name);
        const bool isProgram = pou.kind == core::PouKind::Program;
        const QString description = describe(pou, program);

        // Its interface (inputs, outputs, the instances it calls); the
        // globals it reads and its other variables by name.
        Table declarations(m_style,
                           {{tr("Declaration"), 76}, {tr("Name"), 104}, {tr("Type"), 64}, {tr("Initial value"), 58},
                            {tr("Comment"), 0}},
                           m_width);
        const auto declare = [&](const char* block, const std::vector<core::PlcVariable>& variables) {
            for (const core::PlcVariable& variable : variables) {
                declarations.addRow({QString::fromLatin1(block), fromStd(variable.name), fromStd(variable.typeName),
                                     orDash(fromStd(variable.initialValue)), orDash(fromStd(variable.comment))});
            }
        };
        declare("VAR_INPUT", pou.inputs);
        declare("VAR_OUTPUT", pou.outputs);
        std::vector<core::PlcVariable> instances;
        QStringList others;
        for (const core::PlcVariable& local : pou.locals) {
            if (pouNames.contains(fromStd(local.typeName)))
                instances.push_back(local);
            else
                others << fromStd(local.name);
        }
        declare("VAR", instances);
        QStringList externals;
        for (const core::PlcVariable& external : pou.externals)
            externals << fromStd(external.name);

        const QString keyword = isProgram ? QStringLiteral("PROGRAM ") : QStringLiteral("FUNCTION_BLOCK ");
        addHeading(flow, m_style, TextStyle::Subheading, keyword + name, 3 * bodyLine());
        addText(flow, m_style, TextStyle::Body, description);
        flow.space(m_style.pt(4));
        if (!declarations.isEmpty())
            declarations.flowInto(flow);
        if (!externals.isEmpty()) {
            flow.space(m_style.pt(4));
            addText(flow, m_style, TextStyle::Body,
                    tr("Global variables it reads (VAR_EXTERNAL): %1.").arg(externals.join(QStringLiteral(", "))));
        }
        if (!others.isEmpty()) {
            flow.space(m_style.pt(4));
            addText(flow, m_style, TextStyle::Body,
                    tr("Its own variables (VAR): %1.").arg(others.join(QStringLiteral(", "))));
        }
    }

    Table added(m_style, {{tr("Name"), 130}, {tr("Type"), 50}, {tr("Initial value"), 64}, {tr("Comment"), 0}},
                m_width);
    for (const core::PlcVariable& global : project.globals) {
        if (!m_model.variable(global.name)) {
            added.addRow({fromStd(global.name), fromStd(global.typeName), orDash(fromStd(global.initialValue)),
                          orDash(fromStd(global.comment))});
        }
    }
    addHeading(flow, m_style, TextStyle::Subheading, tr("Global variables"), 2 * bodyLine());
    const QString where = project.globalListName.empty()
                              ? tr("in the VAR_GLOBAL of the configuration %1").arg(fromStd(project.configurationName))
                              : tr("in the global variable list %1").arg(fromStd(project.globalListName));
    addText(flow, m_style, TextStyle::Body,
            tr("The declared variables (page %1) are the program's global variables, %2.")
                .arg(QString::number(pageOf(variablesEntry)), where));
    if (!added.isEmpty()) {
        flow.space(m_style.pt(4));
        addText(flow, m_style, TextStyle::Body, tr("The generator adds these:"), added.startHeight());
        flow.space(m_style.pt(4));
        added.flowInto(flow);
    }
}

// Every page with its running header and foot, then its blocks.
bool SpecificationPages::paint(QPainter& painter, const std::function<bool()>& pageDone) const
{
    const std::vector<Page>& pages = m_flow->pages();
    const QFont font = m_style.font(TextStyle::Small);
    const QFontMetricsF metrics = m_style.metrics(TextStyle::Small);
    const QString date = QLocale().toString(m_date.date(), QLocale::ShortFormat);
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const Page& page = pages[i];
        if (i > 0) {
            m_device.setPageOrientation(page.orientation);
            m_device.newPage();
        }
        const QSizeF size = page.orientation == QPageLayout::Landscape ? m_printable.transposed() : m_printable;
        painter.save();
        painter.setFont(font);
        painter.setPen(mutedColor());
        for (qsizetype line = 0; line < m_headerLines.size(); ++line)
            painter.drawText(QPointF(0, double(line) * metrics.lineSpacing() + metrics.ascent()), m_headerLines[line]);
        painter.drawText(QRectF(0, 0, size.width(), metrics.lineSpacing()), Qt::AlignRight | Qt::AlignTop,
                         page.section);
        painter.setPen(QPen(ruleColor(), m_style.pt(0.5)));
        const double rule = double(m_headerLines.size() - 1) * metrics.lineSpacing() + metrics.ascent()
                            + metrics.descent() + m_style.pt(4);
        painter.drawLine(QPointF(0, rule), QPointF(size.width(), rule));
        painter.setPen(mutedColor());
        const QRectF foot(0, size.height() - metrics.lineSpacing(), size.width(), metrics.lineSpacing());
        painter.drawText(foot, Qt::AlignLeft | Qt::AlignBottom, date);
        painter.drawText(foot, Qt::AlignRight | Qt::AlignBottom, tr("Page %1 of %2").arg(i + 1).arg(pages.size()));
        painter.restore();
        for (const Block& block : page.blocks) {
            painter.save();
            block.paint(painter, QPointF(0, m_bodyTop + block.y));
            painter.restore();
        }
        if (!pageDone())
            return false;
    }
    return true;
}

} // namespace editor::specification
