#include "editor/chart/packml/packmlarrowitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/segmentstroke.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPathStroker>
#include <QStyleOptionGraphicsItem>

#include <algorithm>

namespace editor {

namespace {

QPointF toPoint(core::Point point)
{
    return {point.x, point.y};
}

QRectF toRect(const core::Rect& rect)
{
    return {rect.x, rect.y, rect.width, rect.height};
}

// The label keeps to its bar's side, as on the GEMMA chart.
Qt::Alignment alignmentTowards(const QRectF& label, QPointF bar)
{
    if (label.right() <= bar.x() + 0.5)
        return Qt::AlignRight;
    if (label.left() >= bar.x() - 0.5)
        return Qt::AlignLeft;
    return Qt::AlignHCenter;
}

constexpr double kPickWidth = 8; // how far from the route a click still hits it

} // namespace

PackmlArrowItem::PackmlArrowItem(const core::packml::ChartArrow& arrow, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_barCenter(toPoint(arrow.barCenter))
    , m_barHorizontal(arrow.barHorizontal)
    , m_labelRect(toRect(arrow.labelRect))
{
    setFlag(ItemIsSelectable);
    setZValue(chartstyle::kTransitionZ);
    for (const core::Point& point : arrow.route)
        m_line << toPoint(point);
    if (m_line.size() >= 2) {
        const QPointF tip = m_line.last();
        const QLineF last(m_line[m_line.size() - 2], tip);
        const QPointF direction = last.length() > 0 ? (tip - last.p1()) / last.length() : QPointF(1, 0);
        const QPointF normal(-direction.y(), direction.x());
        const QPointF base = tip - direction * chartstyle::kArrowLength;
        m_arrow = QPolygonF({tip, base + normal * chartstyle::kArrowHalfWidth, base - normal * chartstyle::kArrowHalfWidth});
        m_line.last() = base;
    }
    m_labelAlignment = alignmentTowards(m_labelRect, m_barCenter);
    const double margin = chartstyle::kHaloWidth + chartstyle::kBarWidth;
    m_bounds = (m_line.boundingRect() | m_arrow.boundingRect() | m_labelRect).adjusted(-margin, -margin, margin, margin);

    QPainterPath route;
    route.addPolygon(m_line);
    QPainterPathStroker stroker;
    stroker.setWidth(kPickWidth);
    m_shape = stroker.createStroke(route);
    m_shape.addPolygon(m_arrow);
    const QLineF bar = barLine();
    m_shape.addRect(QRectF(bar.p1(), bar.p2()).adjusted(-4, -4, 4, 4));
    m_shape.setFillRule(Qt::WindingFill);
}

QVariant PackmlArrowItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemSelectedHasChanged)
        setZValue(value.toBool() ? chartstyle::kSelectedZ : chartstyle::kTransitionZ);
    return QGraphicsItem::itemChange(change, value);
}

void PackmlArrowItem::setLabelCandidates(const QStringList& candidates)
{
    if (m_candidates == candidates)
        return;
    m_candidates = candidates;
    const QFontMetricsF metrics(chartstyle::font());
    m_shown.clear();
    m_scale = 1;
    const double room = m_labelRect.width();
    for (const QString& candidate : candidates) {
        const double width = metrics.horizontalAdvance(candidate);
        if (width * kMinLabelScale <= room) {
            m_shown = candidate;
            m_scale = std::min(1.0, room / width);
            break;
        }
    }
    if (m_shown.isEmpty() && !candidates.isEmpty()) {
        m_scale = kMinLabelScale; // as much of the text as can be read
        m_shown = metrics.elidedText(candidates.last(), Qt::ElideRight, room / m_scale);
    }
    m_shownWidth = metrics.horizontalAdvance(m_shown) * m_scale;
    update();
}

void PackmlArrowItem::setDashed(bool dashed)
{
    if (m_dashed == dashed)
        return;
    m_dashed = dashed;
    update();
}

void PackmlArrowItem::setGreyed(bool greyed)
{
    if (m_greyed == greyed)
        return;
    m_greyed = greyed;
    update();
}

void PackmlArrowItem::setFired(bool fired)
{
    if (m_fired == fired)
        return;
    m_fired = fired;
    update();
}

QColor PackmlArrowItem::inkColor() const
{
    if (m_fired)
        return chartstyle::firedColor();
    return m_greyed ? chartstyle::packmlGreyedInkColor() : chartstyle::inkColor();
}

QLineF PackmlArrowItem::barLine() const
{
    const double half = core::packml::kChartBarLength / 2;
    if (m_barHorizontal)
        return {m_barCenter.x() - half, m_barCenter.y(), m_barCenter.x() + half, m_barCenter.y()};
    return {m_barCenter.x(), m_barCenter.y() - half, m_barCenter.x(), m_barCenter.y() + half};
}

QRectF PackmlArrowItem::shownLabelRect() const
{
    const double width = std::min(m_labelRect.width(), m_shownWidth);
    double x = m_labelRect.left();
    if (m_labelAlignment == Qt::AlignRight)
        x = m_labelRect.right() - width;
    else if (m_labelAlignment == Qt::AlignHCenter)
        x = m_labelRect.center().x() - width / 2;
    return {x, m_labelRect.top(), width, m_labelRect.height()};
}

QRectF PackmlArrowItem::boundingRect() const
{
    return m_bounds;
}

QPainterPath PackmlArrowItem::shape() const
{
    QPainterPath shape = m_shape;
    if (!m_shown.isEmpty())
        shape.addRect(shownLabelRect());
    return shape;
}

void PackmlArrowItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const QLineF bar = barLine();
    if (option->state & QStyle::State_Selected) {
        painter->setPen(QPen(chartstyle::haloColor(), chartstyle::kHaloWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter->setBrush(Qt::NoBrush);
        painter->drawPolyline(m_line);
        painter->drawPolygon(m_arrow);
        painter->drawLine(bar);
        if (!m_shown.isEmpty())
            painter->drawRoundedRect(shownLabelRect().adjusted(-2, -1, 2, 1), 3, 3);
    }
    const QColor ink = inkColor();
    const double routeWidth = m_fired ? chartstyle::kFiredWidth : chartstyle::kRouteWidth;
    painter->setPen(QPen(ink, routeWidth, m_dashed ? Qt::DashLine : Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin));
    painter->setBrush(Qt::NoBrush);
    segmentstroke::drawPolyline(painter, m_line);
    painter->setPen(QPen(ink, chartstyle::kRouteWidth));
    painter->setBrush(ink);
    painter->drawPolygon(m_arrow);
    painter->setPen(QPen(ink, chartstyle::kBarWidth, Qt::SolidLine, Qt::FlatCap));
    painter->drawLine(bar);
    if (!m_shown.isEmpty()) {
        painter->setPen(m_greyed ? ink : chartstyle::labelColor());
        chartstyle::drawText(painter, shownLabelRect(), Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine, m_shown,
                             m_scale);
    }
}

} // namespace editor
