#include "editor/chart/gemma/stepitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/pixelsnap.h"
#include "editor/chart/segmentstroke.h"
#include "editor/document.h"
#include "editor/text/gemmastatenames.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>

namespace editor {

namespace {

// The ring around the GRAFCET mark while that GRAFCET runs: its gap to the mark and its pen.
constexpr double kRunningRingGap = 2.5;
constexpr double kRunningRingWidth = 1.5;

} // namespace

StepItem::StepItem(const Document& document, const core::StepLayout& layout, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_document(document)
    , m_id(QString::fromUtf8(layout.id.data(), static_cast<qsizetype>(layout.id.size())))
    , m_modelId(layout.id)
    , m_box(0, 0, layout.box.width, layout.box.height)
{
    setPos(layout.box.x, layout.box.y);
    setFlag(ItemIsSelectable);
    setZValue(chartstyle::kStepZ);
    setAcceptHoverEvents(false);
    m_nestedSteps = readNestedMark();
}

QVariant StepItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemSelectedHasChanged)
        setZValue(value.toBool() ? chartstyle::kSelectedZ : chartstyle::kStepZ);
    return QGraphicsItem::itemChange(change, value);
}

const core::Step* StepItem::step() const
{
    return m_document.model().step(m_modelId);
}

bool StepItem::isHiddenInModel() const
{
    const core::Step* s = step();
    return !s || s->hidden;
}

std::optional<int> StepItem::readNestedMark() const
{
    const core::Step* s = step();
    if (!s || s->type == core::StepType::Simple)
        return std::nullopt;
    const core::Grafcet* grafcet = m_document.model().grafcet(m_modelId);
    if (!grafcet || grafcet->steps().empty())
        return std::nullopt;
    return static_cast<int>(grafcet->steps().size());
}

void StepItem::refresh()
{
    m_nestedSteps = readNestedMark();
    update();
}

void StepItem::setProblemMark(bool problem)
{
    if (m_problem == problem)
        return;
    m_problem = problem;
    update();
}

void StepItem::setActive(bool active)
{
    if (m_active == active)
        return;
    m_active = active;
    update();
}

void StepItem::setCompleteMark(std::optional<bool> complete)
{
    if (m_complete == complete)
        return;
    m_complete = complete;
    update();
}

void StepItem::setNestedRunning(const std::optional<QString>& activeSteps)
{
    if (m_nestedRunning == activeSteps)
        return;
    m_nestedRunning = activeSteps;
    update();
}

QString StepItem::toolTipText() const
{
    const core::Step* found = step();
    if (!found)
        return {};
    const core::Step& step = *found;
    QString kind;
    switch (step.type) {
    case core::StepType::Simple: kind = tr("Simple step"); break;
    case core::StepType::Macro: kind = tr("Macro-step"); break;
    case core::StepType::Enclosing: kind = tr("Enclosing step"); break;
    }
    if (step.initial)
        kind = tr("%1, initial").arg(kind);
    if (step.hidden)
        kind = tr("%1, hidden").arg(kind);

    QString text = QStringLiteral("<b>%1</b> %2<br/><i>%3</i>")
                       .arg(m_id, officialStateName(m_id).toHtmlEscaped(), kind.toHtmlEscaped());
    const QString comment = QString::fromStdString(step.comment).trimmed();
    if (m_nestedSteps)
        text
            += QStringLiteral("<br/>") + tr("Has a nested GRAFCET (%n steps)", nullptr, *m_nestedSteps).toHtmlEscaped();
    if (const int problems = m_document.nestedProblemCount(m_id); problems > 0)
        // A singular text of its own: English has no "%n" form for one.
        text += QStringLiteral("<br/><span style=\"color:%1\">").arg(chartstyle::problemColor().name())
              + (problems == 1 ? tr("Its nested GRAFCET has 1 problem")
                               : tr("Its nested GRAFCET has %n problems", nullptr, problems))
                    .toHtmlEscaped()
              + QStringLiteral("</span>");
    if (m_nestedSteps && m_nestedRunning)
        //: simulation; %1: the active steps of the nested GRAFCET ("3, 5")
        text += QStringLiteral("<br/><b>")
              + tr("Its GRAFCET runs: steps %1 active").arg(*m_nestedRunning).toHtmlEscaped() + QStringLiteral("</b>");
    if (!comment.isEmpty())
        text += QStringLiteral("<br/>") + comment.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br/>"));
    return text;
}

QRectF StepItem::boundingRect() const
{
    const double margin = std::max({ chartstyle::kHaloWidth, chartstyle::kBadgeRadius,
                              chartstyle::kCompleteBadgeSize / 2,
                              chartstyle::kNestedMarkSize / 2 + kRunningRingGap + kRunningRingWidth / 2 })
        + 1;
    return m_box.adjusted(-margin, -margin, margin, margin);
}

QPainterPath StepItem::shape() const
{
    QPainterPath path;
    path.addRect(m_box);
    return path;
}

void StepItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    const core::Step* s = step();
    if (!s)
        return;
    painter->setRenderHint(QPainter::Antialiasing);
    if (option->state & QStyle::State_Selected) {
        painter->setPen(QPen(chartstyle::haloColor(), chartstyle::kHaloWidth));
        painter->setBrush(Qt::NoBrush);
        const double gap = chartstyle::kHaloWidth / 2;
        painter->drawRoundedRect(m_box.adjusted(-gap, -gap, gap, gap), gap, gap);
    }
    paintSymbol(painter, *s);
    if (m_nestedSteps)
        paintNestedMark(painter);
    if (m_problem)
        paintBadge(painter);
    if (m_complete)
        paintCompleteBadge(painter);
}

void StepItem::paintSymbol(QPainter* painter, const core::Step& step) const
{
    QPen pen(m_problem ? chartstyle::problemColor() : chartstyle::inkColor(), chartstyle::kStrokeWidth);
    pen.setJoinStyle(Qt::MiterJoin);
    if (step.hidden)
        pen.setStyle(Qt::DashLine);
    painter->setPen(pen);
    pixelsnap::fillRect(painter, m_box, m_active ? chartstyle::activeFillColor() : chartstyle::stepFillColor());
    segmentstroke::drawRectOutline(painter, m_box);

    // The type marks go inside the inner square of an initial step.
    QRectF symbol = m_box;
    if (step.initial) {
        const double inset = chartstyle::kInitialInset;
        symbol.adjust(inset, inset, -inset, -inset);
        segmentstroke::drawRectOutline(painter, symbol);
    }
    if (step.type == core::StepType::Macro) {
        const double y1 = symbol.top() + chartstyle::kMacroInset;
        const double y2 = symbol.bottom() - chartstyle::kMacroInset;
        segmentstroke::drawPolyline(painter, QPolygonF({{symbol.left(), y1}, {symbol.right(), y1}}));
        segmentstroke::drawPolyline(painter, QPolygonF({{symbol.left(), y2}, {symbol.right(), y2}}));
    } else if (step.type == core::StepType::Enclosing) {
        const double k = chartstyle::kEnclosingMark;
        const QLineF marks[] = {
            {symbol.left(), symbol.top() + k, symbol.left() + k, symbol.top()},
            {symbol.right() - k, symbol.top(), symbol.right(), symbol.top() + k},
            {symbol.left(), symbol.bottom() - k, symbol.left() + k, symbol.bottom()},
            {symbol.right() - k, symbol.bottom(), symbol.right(), symbol.bottom() - k},
        };
        painter->drawLines(marks, 4);
    }

    painter->setPen(m_problem ? chartstyle::problemColor() : chartstyle::inkColor());
    chartstyle::drawCentredText(painter, m_box, m_id, chartstyle::stepIdScale(m_box.width()));
}

void StepItem::paintBadge(QPainter* painter) const
{
    const double r = chartstyle::kBadgeRadius;
    const QRectF badge(m_box.right() - r, m_box.top() - r, 2 * r, 2 * r);
    painter->setPen(QPen(Qt::white, 1));
    painter->setBrush(chartstyle::problemColor());
    painter->drawEllipse(badge);
    chartstyle::drawCentredText(painter, badge, QStringLiteral("!"), chartstyle::kBadgeScale);
}

// On the bottom-right corner, clear of the problem badge (top right).
void StepItem::paintCompleteBadge(QPainter* painter) const
{
    const double size = chartstyle::kCompleteBadgeSize;
    const QRectF badge(m_box.right() - size / 2, m_box.bottom() - size / 2, size, size);
    painter->setPen(QPen(Qt::white, 1));
    painter->setBrush(*m_complete ? chartstyle::trueMarkColor() : chartstyle::falseMarkColor());
    painter->drawRoundedRect(badge, 3, 3);
    chartstyle::drawCentredText(painter, badge, QStringLiteral("C"), chartstyle::kBadgeScale);
}

// On the top-left corner, clear of the problem badge (top right) and the
// Complete badge (bottom right): a tab with a tiny GRAFCET, a step above a
// transition bar with its links.
void StepItem::paintNestedMark(QPainter* painter) const
{
    const double size = chartstyle::kNestedMarkSize;
    const QRectF tab(m_box.left() - size / 2, m_box.top() - size / 2, size, size);
    if (m_nestedRunning) { // a ring around the tab, within the item's margin
        painter->setPen(QPen(chartstyle::nestedRunningColor(), kRunningRingWidth));
        painter->setBrush(Qt::NoBrush);
        const double gap = kRunningRingGap;
        painter->drawRoundedRect(tab.adjusted(-gap, -gap, gap, gap), 3 + gap, 3 + gap);
    }
    painter->setPen(QPen(Qt::white, 1));
    painter->setBrush(m_nestedRunning ? chartstyle::nestedRunningColor() : chartstyle::nestedMarkColor());
    painter->drawRoundedRect(tab, 3, 3);

    const double unit = size / 15;
    const QPointF centre = tab.center();
    QPen glyph(Qt::white, 1.4 * unit);
    glyph.setCapStyle(Qt::FlatCap);
    glyph.setJoinStyle(Qt::MiterJoin);
    painter->setPen(glyph);
    painter->setBrush(Qt::NoBrush);
    const QRectF square(centre.x() - 3 * unit, tab.top() + 2.5 * unit, 6 * unit, 5 * unit);
    painter->drawRect(square);
    const double barY = square.bottom() + 3 * unit;
    painter->drawLine(QPointF(centre.x(), square.bottom()), QPointF(centre.x(), tab.bottom() - 1.5 * unit));
    painter->setPen(QPen(Qt::white, 2 * unit, Qt::SolidLine, Qt::FlatCap));
    painter->drawLine(QPointF(centre.x() - 3 * unit, barY), QPointF(centre.x() + 3 * unit, barY));
}

} // namespace editor
