#include "editor/grafcet/grafcettransitionitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"

#include <QPainter>
#include <QRegularExpression>

namespace editor {

GrafcetTransitionItem::GrafcetTransitionItem(const core::GrafcetTransitionLayout& layout,
                                             const std::string& receptivity, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_layout(layout)
    , m_label(drawnReceptivity(QString::fromStdString(receptivity)))
{
    setZValue(chartstyle::kTransitionZ);
    setFlag(ItemIsSelectable); // the GRAFCET tab's editing acts on the selected transition
    const QPointF bar = toQPointF(layout.barCenter);
    const double half = core::kGrafcetBarLength / 2;
    const double margin = chartstyle::kHaloWidth;
    m_bounds = QRectF(bar.x() - half, bar.y() - chartstyle::kBarWidth, 2 * half, 2 * chartstyle::kBarWidth)
                   .united(toQRectF(layout.labelRect))
                   .adjusted(-margin, -margin, margin, margin);
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

QRectF GrafcetTransitionItem::boundingRect() const
{
    return m_bounds;
}

void GrafcetTransitionItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const QPointF bar = toQPointF(m_layout.barCenter);
    const double half = core::kGrafcetBarLength / 2;
    if (isSelected()) {
        painter->setPen(QPen(chartstyle::haloColor(), chartstyle::kBarWidth + chartstyle::kHaloWidth, Qt::SolidLine,
                             Qt::RoundCap));
        painter->drawLine(QLineF(bar.x() - half, bar.y(), bar.x() + half, bar.y()));
    }
    painter->setPen(QPen(m_fired ? chartstyle::firedColor() : chartstyle::inkColor(), chartstyle::kBarWidth,
                         Qt::SolidLine, Qt::FlatCap));
    painter->drawLine(QLineF(bar.x() - half, bar.y(), bar.x() + half, bar.y()));
    painter->setPen(chartstyle::labelColor());
    chartstyle::drawText(painter, toQRectF(m_layout.labelRect), Qt::AlignLeft | Qt::AlignVCenter, m_label);
}

} // namespace editor
