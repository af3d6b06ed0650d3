#include "editor/export/chartexport.h"

#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/frameitem.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/export/conditionnotes.h"
#include "editor/export/exportfile.h"
#include "editor/export/hiddenselection.h"

#include <QFileInfo>
#include <QGraphicsItem>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QPrinter>

#include <optional>

#include <utility>

namespace editor {

namespace {

// White margin around the sheet, in scene units.
constexpr double kMargin = 12;

// Numbers the conditions the labels cut short for the time of a rendering
// (TransitionItem::setNoteNumber), and gives the labels back their
// on-screen text afterwards.
class ExportNotes {
public:
    explicit ExportNotes(ChartScene& scene)
        : m_scene(scene)
        , m_notes(conditionNotes(scene))
    {
        for (const ConditionNote& note : std::as_const(m_notes)) {
            if (TransitionItem* item = m_scene.transitionItem(note.transitionId))
                item->setNoteNumber(note.number);
        }
    }
    ~ExportNotes()
    {
        for (const ConditionNote& note : std::as_const(m_notes)) {
            if (TransitionItem* item = m_scene.transitionItem(note.transitionId))
                item->setNoteNumber(0);
        }
    }
    ExportNotes(const ExportNotes&) = delete;
    ExportNotes& operator=(const ExportNotes&) = delete;

    const QList<ConditionNote>& notes() const { return m_notes; }

private:
    ChartScene& m_scene;
    QList<ConditionNote> m_notes;
};

QRectF paperRect(const ChartScene& scene)
{
    return scene.sceneRect().adjusted(-kMargin, -kMargin, kMargin, kMargin);
}

void render(ChartScene& scene, QPainter& painter, const QRectF& target)
{
    HiddenSelection hidden(scene);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    painter.fillRect(target, Qt::white);
    scene.render(&painter, target, paperRect(scene), Qt::KeepAspectRatio);
}

// Where the list under the sheet stands, in the picture's units from its
// left: under the family frames, as wide as they are together.
struct ListColumn {
    double left = kMargin;
    double width = 0;
};

ListColumn listColumn(const ChartScene& scene)
{
    const QRectF paper = paperRect(scene);
    QRectF frames;
    for (const FrameItem* frame : scene.frames())
        frames |= frame->sceneBoundingRect();
    if (frames.isEmpty())
        return {kMargin, paper.width() - 2 * kMargin};
    return {frames.left() - paper.left(), frames.width()};
}

ConditionList listUnder(const ChartScene& scene, const QList<ConditionNote>& notes)
{
    return ConditionList(notes, listColumn(scene).width);
}

// The sheet with its list under it, at `scale` device units per scene unit,
// the top left at the painter's origin.
void renderPicture(ChartScene& scene, QPainter& painter, const ConditionList& list, double scale)
{
    const QRectF paper = paperRect(scene);
    painter.fillRect(QRectF(0, 0, paper.width() * scale, (paper.height() + list.height()) * scale), Qt::white);
    render(scene, painter, QRectF(0, 0, paper.width() * scale, paper.height() * scale));
    if (list.isEmpty())
        return;
    painter.save();
    painter.scale(scale, scale);
    list.paint(painter, QPointF(listColumn(scene).left, paper.height() + ConditionList::kTopGap), 0, list.lineCount());
    painter.restore();
}

// PDF and print: every page of ChartExport::Pages.
void renderPages(ChartScene& scene, QPainter& painter, QPagedPaintDevice& device, const QSizeF& page)
{
    const ChartExport::Pages pages(scene, page);
    for (qsizetype i = 0; i < pages.count(); ++i) {
        if (i > 0)
            device.newPage();
        pages.paint(painter, i);
    }
}

} // namespace

ChartExport::ChartExport(ChartScene& scene)
    : m_scene(scene)
{
}

// The chart fitted to the page, and its list under it, or on the following
// pages when sharing the page would shrink the chart too much (planPages).
// The list is drawn at the chart's scale, so it reads as the labels do.
struct ChartExport::Pages::Plan {
    Plan(ChartScene& chart, const QSizeF& size)
        : scene(chart)
        , page(size)
        , notes(chart)
    {
    }

    ChartScene& scene;
    QSizeF page;
    ExportNotes notes;
    double scale = 1;
    std::optional<ConditionList> below; // under the chart on its page
    std::optional<ConditionList> after; // on the following pages
    QList<int> starts;                  // of the following pages, in `after`'s lines
};

ChartExport::Pages::Pages(ChartScene& scene, const QSizeF& page)
    : m_plan(std::make_unique<Plan>(scene, page))
{
    Plan& plan = *m_plan;
    const QList<ConditionNote>& notes = plan.notes.notes();
    if (notes.isEmpty())
        return;
    const ConditionList below = listUnder(scene, notes);
    const PagePlan pagePlan = planPages(paperRect(scene).size(), below.height(), page);
    plan.scale = pagePlan.scale;
    if (pagePlan.listBelowChart) {
        plan.below = below;
        return;
    }
    const QSizeF room = page / plan.scale; // a page in scene units
    plan.after.emplace(notes, room.width() - 2 * kMargin);
    plan.starts = pageBreaks(plan.after->lineHeights(), room.height() - 2 * kMargin);
}

ChartExport::Pages::~Pages() = default;

qsizetype ChartExport::Pages::count() const
{
    return 1 + m_plan->starts.size();
}

void ChartExport::Pages::paint(QPainter& painter, qsizetype index) const
{
    const Plan& plan = *m_plan;
    if (index == 0) {
        if (plan.notes.notes().isEmpty()) {
            render(plan.scene, painter, QRectF(QPointF(0, 0), plan.page));
            return;
        }
        const QRectF paper = paperRect(plan.scene);
        painter.save();
        painter.translate((plan.page.width() - paper.width() * plan.scale) / 2, 0);
        if (plan.below)
            renderPicture(plan.scene, painter, *plan.below, plan.scale);
        else
            render(plan.scene, painter, QRectF(0, 0, paper.width() * plan.scale, paper.height() * plan.scale));
        painter.restore();
        return;
    }
    const qsizetype i = index - 1;
    if (!plan.after || i >= plan.starts.size())
        return;
    painter.save();
    painter.scale(plan.scale, plan.scale);
    plan.after->paint(painter, QPointF(kMargin, kMargin), plan.starts[i],
                      i + 1 < plan.starts.size() ? plan.starts[i + 1] : plan.after->lineCount());
    painter.restore();
}

bool ChartExport::formatForPath(const QString& path, Format* format)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("svg"))
        *format = Format::Svg;
    else if (suffix == QLatin1String("png"))
        *format = Format::Png;
    else if (suffix == QLatin1String("pdf"))
        *format = Format::Pdf;
    else
        return false;
    return true;
}

bool ChartExport::write(const QString& path, Format format, QString* errorMessage) const
{
    switch (format) {
    case Format::Svg:
        return writeSvg(path, errorMessage);
    case Format::Png:
        return writePng(path, errorMessage);
    case Format::Pdf:
        return writePdf(path, errorMessage);
    }
    return false;
}

bool ChartExport::writeSvg(const QString& path, QString* errorMessage) const
{
    const ExportNotes notes(m_scene);
    const QRectF paper = paperRect(m_scene);
    const ConditionList list = listUnder(m_scene, notes.notes());
    return PictureFile::writeSvg(
        path, QSizeF(paper.width(), paper.height() + list.height()), m_title,
        tr("GEMMA-GRAFCET chart drawn by GG Studio"),
        [&](QPainter& painter) { renderPicture(m_scene, painter, list, 1.0); }, errorMessage);
}

bool ChartExport::writePng(const QString& path, QString* errorMessage, double scale) const
{
    const ExportNotes notes(m_scene);
    const QRectF sheet = paperRect(m_scene);
    const ConditionList list = listUnder(m_scene, notes.notes());
    return PictureFile::writePng(
        path, QSizeF(sheet.width(), sheet.height() + list.height()) * scale,
        [&](QPainter& painter) { renderPicture(m_scene, painter, list, scale); }, errorMessage);
}

bool ChartExport::writePdf(const QString& path, QString* errorMessage) const
{
    return PictureFile::writePdf(
        path, m_title, QPageLayout::Landscape,
        [this](QPainter& painter, QPagedPaintDevice& device, const QSizeF& page, double) {
            renderPages(m_scene, painter, device, page);
        },
        errorMessage);
}

bool ChartExport::print(QPrinter& printer) const
{
    printer.setDocName(m_title);
    QPainter painter;
    if (!painter.begin(&printer))
        return false;
    // The painter's origin is the top left of the printable area.
    renderPages(m_scene, painter, printer, QSizeF(printer.width(), printer.height()));
    return true;
}

} // namespace editor
