#include "editor/grafcet/grafcettransitionitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"

#include <QPainter>
#include <QRegularExpression>
#include <QStyleOptionGraphicsItem>

namespace editor {

GrafcetTransitionItem::GrafcetTransitionItem(const core::GrafcetTransitionLayout& layout,
                                             const std::string& receptivity, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_layout(layout)
    , m_label(drawnReceptivity(QString::fromStdString(receptivity)))
{
    setFlag(ItemIsSelectable); // the docks and the GRAFCET tab's editing follow the selected transition
    setZValue(chartstyle::kTransitionZ);
    m_bounds = boundsOf(layout);
}

QRectF GrafcetTransitionItem::boundsOf(const core::GrafcetTransitionLayout& layout)
{
    const QPointF bar = toQPointF(layout.barCenter);
    const double half = core::kGrafcetBarLength / 2;
    return QRectF(bar.x() - half, bar.y() - chartstyle::kBarWidth, 2 * half, 2 * chartstyle::kBarWidth)
        .united(toQRectF(layout.labelRect))
        .adjusted(-2, -2, 2, 2);
}

void GrafcetTransitionItem::setReceptivity(const core::GrafcetTransitionLayout& layout, const std::string& receptivity)
{
    const QString label = drawnReceptivity(QString::fromStdString(receptivity));
    if (layout == m_layout && label == m_label)
        return;
    prepareGeometryChange();
    m_layout = layout;
    m_label = label;
    m_bounds = boundsOf(layout);
    update();
}

QString GrafcetTransitionItem::drawnReceptivity(const QString& receptivity)
{
    static const QRegularExpression rising(QStringLiteral(R"(\bRE\s+)"));
    static const QRegularExpression falling(QStringLiteral(R"(\bFE\s+)"));
    QString text = receptivity.simplified();
    text.replace(rising, QStringLiteral("↑"));
    text.replace(falling, QStringLiteral("↓"));
    return text;
}

void GrafcetTransitionItem::setFired(bool fired)
{
    if (m_fired == fired)
        return;
    m_fired = fired;
    update();
}

void GrafcetTransitionItem::setProblemMark(bool problem)
{
    if (m_problem == problem)
        return;
    m_problem = problem;
    update();
}

QRectF GrafcetTransitionItem::boundingRect() const
{
    // The halo reaches beyond the drawing only while selected: pictures,
    // which unselect, keep the extents their page breaks are made from.
    const double halo = isSelected() ? chartstyle::kHaloWidth : 0;
    return m_bounds.adjusted(-halo, -halo, halo, halo);
}

QVariant GrafcetTransitionItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemSelectedChange)
        prepareGeometryChange();
    return QGraphicsItem::itemChange(change, value);
}

void GrafcetTransitionItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const QPointF bar = toQPointF(m_layout.barCenter);
    const double half = core::kGrafcetBarLength / 2;
    // The halo of the GEMMA chart's selection, along the bar and around the receptivity.
    if (option->state & QStyle::State_Selected) {
        painter->setPen(QPen(chartstyle::haloColor(), chartstyle::kHaloWidth, Qt::SolidLine, Qt::RoundCap));
        painter->setBrush(Qt::NoBrush);
        painter->drawLine(QLineF(bar.x() - half, bar.y(), bar.x() + half, bar.y()));
        if (!m_label.isEmpty())
            painter->drawRoundedRect(toQRectF(m_layout.labelRect).adjusted(-2, -1, 2, 1), 3, 3);
    }
    const QColor ink = m_problem ? chartstyle::problemColor() : chartstyle::inkColor();
    painter->setPen(QPen(m_fired ? chartstyle::firedColor() : ink, chartstyle::kBarWidth, Qt::SolidLine, Qt::FlatCap));
    painter->drawLine(QLineF(bar.x() - half, bar.y(), bar.x() + half, bar.y()));
    painter->setPen(m_problem ? chartstyle::problemColor() : chartstyle::labelColor());
    chartstyle::drawText(painter, toQRectF(m_layout.labelRect), Qt::AlignLeft | Qt::AlignVCenter, m_label);
}

} // namespace editor
