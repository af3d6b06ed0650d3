#include "editor/chart/gemma/frameitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"
#include "editor/chart/pixelsnap.h"
#include "editor/chart/segmentstroke.h"
#include "editor/text/gemmastatenames.h"

#include <QFontMetrics>
#include <QPainter>
#include <QtMath>

namespace editor {

FrameItem::FrameItem(const core::FrameLayout& layout, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_family(layout.family)
    , m_rect(toQRectF(layout.rect))
    , m_titleRect(toQRectF(layout.titleRect))
{
    setZValue(chartstyle::kFrameZ);
}

QString FrameItem::title() const
{
    //: Title of a GEMMA family frame: %1 is the letter (A, F, D), %2 the family name
    return tr("%1 — %2").arg(QString::fromUtf8(core::familyName(m_family)), officialFamilyName(m_family));
}

void FrameItem::retranslate()
{
    m_shownTitle = QString();
    update();
}

QRectF FrameItem::boundingRect() const
{
    const double margin = chartstyle::kStrokeWidth;
    return m_rect.adjusted(-margin, -margin, margin, margin);
}

void FrameItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    pixelsnap::fillRect(painter, m_rect, chartstyle::frameFillColor(m_family));
    painter->setPen(QPen(chartstyle::frameBorderColor(m_family), chartstyle::kStrokeWidth));
    segmentstroke::drawRectOutline(painter, m_rect);

    painter->setPen(chartstyle::frameBorderColor(m_family).darker(150));
    // Elided rather than cut mid-letter, should a translation be longer still;
    // once, not at every paint.
    const double scale = chartstyle::kTitleScale;
    if (m_shownTitle.isNull()) {
        m_shownTitle = QFontMetrics(chartstyle::font())
                           .elidedText(title(), Qt::ElideRight, qFloor(m_titleRect.width() / scale));
    }
    chartstyle::drawText(painter, m_titleRect, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine, m_shownTitle,
                         scale);
}

} // namespace editor
