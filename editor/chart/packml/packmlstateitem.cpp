#include "editor/chart/packml/packmlstateitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/pixelsnap.h"
#include "editor/chart/segmentstroke.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

namespace editor {

PackmlStateItem::PackmlStateItem(const core::packml::ChartStateBox& layout, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_state(layout.state)
    , m_box(0, 0, layout.box.width, layout.box.height)
{
    const std::string_view name = core::packml::stateName(m_state);
    m_name = QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
    setPos(layout.box.x, layout.box.y);
    setFlag(ItemIsSelectable);
    setZValue(chartstyle::kStepZ);
}

core::packml::StateKind PackmlStateItem::kind() const
{
    return core::packml::stateInfo(m_state).kind;
}

void PackmlStateItem::setDisplayName(const QString& name)
{
    if (m_name == name)
        return;
    m_name = name;
    update();
}

void PackmlStateItem::setDisabledInMode(bool disabled)
{
    if (m_disabled == disabled)
        return;
    m_disabled = disabled;
    update();
}

void PackmlStateItem::setActiveInSimulation(bool active)
{
    if (m_active == active)
        return;
    m_active = active;
    update();
}

QColor PackmlStateItem::fillColor() const
{
    if (m_active)
        return chartstyle::activeFillColor();
    return m_disabled ? chartstyle::packmlDisabledFillColor() : chartstyle::packmlStateFillColor(kind());
}

QVariant PackmlStateItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemSelectedHasChanged)
        setZValue(value.toBool() ? chartstyle::kSelectedZ : chartstyle::kStepZ);
    return QGraphicsItem::itemChange(change, value);
}

QRectF PackmlStateItem::boundingRect() const
{
    const double margin = chartstyle::kHaloWidth + 1;
    return m_box.adjusted(-margin, -margin, margin, margin);
}

QPainterPath PackmlStateItem::shape() const
{
    QPainterPath path;
    path.addRect(m_box);
    return path;
}

void PackmlStateItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    if (option->state & QStyle::State_Selected) {
        painter->setPen(QPen(chartstyle::haloColor(), chartstyle::kHaloWidth));
        painter->setBrush(Qt::NoBrush);
        const double gap = chartstyle::kHaloWidth / 2;
        painter->drawRoundedRect(m_box.adjusted(-gap, -gap, gap, gap), gap, gap);
    }
    const QColor ink = m_disabled ? chartstyle::packmlGreyedInkColor() : chartstyle::inkColor();
    pixelsnap::fillRect(painter, m_box, fillColor());
    QPen pen(ink, chartstyle::kStrokeWidth, m_disabled ? Qt::DashLine : Qt::SolidLine);
    pen.setJoinStyle(Qt::MiterJoin);
    painter->setPen(pen);
    segmentstroke::drawRectOutline(painter, m_box);
    painter->setPen(ink);
    chartstyle::drawCentredText(painter, m_box, m_name);
}

} // namespace editor
