#include "editor/chart/packml/packmlframeitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/pixelsnap.h"
#include "editor/chart/segmentstroke.h"

#include <QPainter>

namespace editor {

PackmlFrameItem::PackmlFrameItem(const core::packml::ChartFrame& frame, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_command(frame.command)
    , m_rect(frame.rect.x, frame.rect.y, frame.rect.width, frame.rect.height)
    , m_titleRect(frame.titleRect.x, frame.titleRect.y, frame.titleRect.width, frame.titleRect.height)
{
    const std::string_view name = core::packml::commandName(m_command);
    m_title = QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
    setZValue(chartstyle::kFrameZ);
}

QRectF PackmlFrameItem::boundingRect() const
{
    const double margin = chartstyle::kStrokeWidth;
    return m_rect.adjusted(-margin, -margin, margin, margin);
}

void PackmlFrameItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    pixelsnap::fillRect(painter, m_rect, chartstyle::packmlFrameFillColor(m_command));
    painter->setPen(QPen(chartstyle::packmlFrameBorderColor(m_command), chartstyle::kStrokeWidth));
    segmentstroke::drawRectOutline(painter, m_rect);
    painter->setPen(chartstyle::packmlFrameBorderColor(m_command).darker(150));
    chartstyle::drawText(painter, m_titleRect, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine, m_title,
                         chartstyle::kTitleScale);
}

} // namespace editor
