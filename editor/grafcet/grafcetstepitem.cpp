#include "editor/grafcet/grafcetstepitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"
#include "editor/stdstring.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

namespace editor {

namespace {

} // namespace

GrafcetStepItem::GrafcetStepItem(const core::GrafcetStepLayout& layout, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_layout(layout)
{
    setFlag(ItemIsSelectable); // the docks and the GRAFCET tab's editing follow the selected steps
    setZValue(chartstyle::kStepZ);
    m_bounds = toQRectF(layout.box);
    for (const core::GrafcetActionLayout& action : layout.actions)
        m_bounds |= toQRectF(action.box) | toQRectF(action.conditionRect);
    m_bounds.adjust(-2, -2, 2, 2);
}

void GrafcetStepItem::setSimulationMark(SimulationMark mark)
{
    if (m_mark == mark)
        return;
    m_mark = mark;
    update();
}

void GrafcetStepItem::setLitActions(const QList<int>& actions)
{
    if (m_litActions == actions)
        return;
    m_litActions = actions;
    update();
}

void GrafcetStepItem::setProblemMarks(bool problem, const QList<int>& actions)
{
    if (m_problem == problem && m_problemActions == actions)
        return;
    m_problem = problem;
    m_problemActions = actions;
    update();
}

// Centred between the number's baseline and the box's (inner) bottom: a
// little smaller in the inner square of an initial step.
QRectF GrafcetStepItem::tokenRect() const
{
    const QRectF box = toQRectF(m_layout.box);
    const double inset = m_layout.initial ? chartstyle::kInitialInset : 0;
    const double r = chartstyle::kGrafcetTokenRadius - inset / 8;
    const double baseline = box.center().y() + chartstyle::kFontSize * 0.36;
    const QPointF centre(box.center().x(), (baseline + box.bottom() - inset) / 2);
    return QRectF(centre.x() - r, centre.y() - r, 2 * r, 2 * r);
}

QRectF GrafcetStepItem::boundingRect() const
{
    // The halo reaches beyond the drawing only while selected: pictures,
    // which unselect, keep the extents their page breaks are made from.
    const double halo = isSelected() ? chartstyle::kHaloWidth : 0;
    return m_bounds.adjusted(-halo, -halo, halo, halo);
}

QVariant GrafcetStepItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemSelectedChange)
        prepareGeometryChange();
    return QGraphicsItem::itemChange(change, value);
}

void GrafcetStepItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const QRectF box = toQRectF(m_layout.box);
    // The halo of the GEMMA chart's selection, around the step's square.
    if (option->state & QStyle::State_Selected) {
        painter->setPen(QPen(chartstyle::haloColor(), chartstyle::kHaloWidth));
        painter->setBrush(Qt::NoBrush);
        const double gap = chartstyle::kHaloWidth / 2;
        painter->drawRoundedRect(box.adjusted(-gap, -gap, gap, gap), gap, gap);
    }
    const QColor ink = m_problem ? chartstyle::problemColor() : chartstyle::inkColor();
    painter->setPen(QPen(ink, chartstyle::kStrokeWidth));
    painter->setBrush(m_mark == SimulationMark::Active   ? chartstyle::activeFillColor()
                      : m_mark == SimulationMark::Frozen ? chartstyle::frozenFillColor()
                                                         : chartstyle::stepFillColor());
    painter->drawRect(box);
    if (m_layout.initial) {
        const double inset = chartstyle::kInitialInset;
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(box.adjusted(inset, inset, -inset, -inset));
    }
    chartstyle::drawCentredText(painter, box, QString::number(m_layout.number));
    if (m_mark != SimulationMark::None) {
        painter->setPen(Qt::NoPen);
        painter->setBrush(m_mark == SimulationMark::Active ? chartstyle::tokenColor() : chartstyle::frozenTokenColor());
        painter->drawEllipse(tokenRect());
    }
    paintActions(painter);
}

void GrafcetStepItem::paintActions(QPainter* painter) const
{
    if (m_layout.actions.empty())
        return;
    painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kRouteWidth));
    QPolygonF link;
    for (const core::Point& point : m_layout.actionLink)
        link << toQPointF(point);
    painter->drawPolyline(link);
    for (const core::GrafcetActionLayout& action : m_layout.actions) {
        const bool lit = m_litActions.contains(action.index);
        if (lit) { // the box lit, its outline drawn over by the plain one's
            painter->setPen(QPen(chartstyle::litActionBorderColor(), 2 * chartstyle::kRouteWidth));
            painter->setBrush(chartstyle::litActionFillColor());
            painter->drawRect(toQRectF(action.box));
        }
        painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kRouteWidth));
        painter->setBrush(lit ? QBrush(Qt::NoBrush) : QBrush(chartstyle::stepFillColor()));
        painter->drawRect(toQRectF(action.box));
        if (m_problemActions.contains(action.index)) { // the outline drawn over, as the lit one
            painter->setPen(QPen(chartstyle::problemColor(), 2 * chartstyle::kRouteWidth));
            painter->setBrush(Qt::NoBrush);
            painter->drawRect(toQRectF(action.box));
            painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kRouteWidth));
        }
        if (!action.qualifier.empty()) {
            painter->drawRect(toQRectF(action.qualifierCell));
            chartstyle::drawCentredText(painter, toQRectF(action.qualifierCell), fromStd(action.qualifier));
        }
        chartstyle::drawCentredText(painter, toQRectF(action.textCell), fromStd(action.text));
        if (!action.condition.empty()) {
            painter->setPen(chartstyle::labelColor());
            chartstyle::drawCentredText(painter, toQRectF(action.conditionRect), fromStd(action.condition));
        }
    }
}

} // namespace editor
