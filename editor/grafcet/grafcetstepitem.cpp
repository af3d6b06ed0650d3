#include "editor/grafcet/grafcetstepitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

namespace editor {

namespace {

QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

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
    painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kStrokeWidth));
    painter->setBrush(chartstyle::stepFillColor());
    painter->drawRect(box);
    if (m_layout.initial) {
        const double inset = chartstyle::kInitialInset;
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(box.adjusted(inset, inset, -inset, -inset));
    }
    chartstyle::drawCentredText(painter, box, QString::number(m_layout.number));
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
        painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kRouteWidth));
        painter->setBrush(chartstyle::stepFillColor());
        painter->drawRect(toQRectF(action.box));
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
