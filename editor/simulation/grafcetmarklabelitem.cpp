#include "editor/simulation/grafcetmarklabelitem.h"

#include "editor/chart/chartstyle.h"

#include <QPainter>

namespace editor {

namespace {

constexpr double kPadding = 4;
constexpr double kTimerHeight = 14;
constexpr double kCaptionHeight = 20;
// Above the steps, transitions and wiring of the drawing.
constexpr double kLabelZ = 10;

struct ToneColours {
    QColor text;
    QColor background;
    QColor border;
};

// Each pair keeps a text contrast of at least 4.5:1.
ToneColours coloursOf(GrafcetMarkLabelItem::Tone tone)
{
    using Tone = GrafcetMarkLabelItem::Tone;
    switch (tone) {
    case Tone::Neutral: return {QColor(0x4a, 0x52, 0x5c), QColor(0xf1, 0xf3, 0xf5), QColor(0xc9, 0xcd, 0xd3)};
    case Tone::Running: return {QColor(0x14, 0x63, 0x2b), QColor(0xe8, 0xf6, 0xec), chartstyle::firedColor()};
    case Tone::Elapsed: return {QColor(0x14, 0x63, 0x2b), chartstyle::litActionFillColor(), chartstyle::firedColor()};
    case Tone::Warning: return {QColor(0xff, 0xff, 0xff), chartstyle::problemColor(), chartstyle::problemColor()};
    }
    return {};
}

} // namespace

GrafcetMarkLabelItem::GrafcetMarkLabelItem(Kind kind, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_kind(kind)
{
    setZValue(kLabelZ);
    setAcceptedMouseButtons(Qt::NoButton); // a click goes to the step or transition under it
}

double GrafcetMarkLabelItem::scale() const
{
    return m_kind == Kind::Timer ? chartstyle::kBadgeScale : 1.0;
}

void GrafcetMarkLabelItem::setText(const QString& text, Tone tone)
{
    if (text == m_text && tone == m_tone)
        return;
    const double height = m_kind == Kind::Timer ? kTimerHeight : kCaptionHeight;
    const QRectF box(0, 0, chartstyle::advance(text) * scale() + 2 * kPadding, height);
    if (box != m_box) {
        prepareGeometryChange();
        m_box = box;
    }
    m_text = text;
    m_tone = tone;
    update();
}

QRectF GrafcetMarkLabelItem::boundingRect() const
{
    return m_box.adjusted(-1, -1, 1, 1);
}

void GrafcetMarkLabelItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    const ToneColours colours = coloursOf(m_tone);
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(colours.border, 1));
    painter->setBrush(colours.background);
    painter->drawRoundedRect(m_box, 3, 3);
    painter->setPen(colours.text);
    chartstyle::drawCentredText(painter, m_box, m_text, scale());
}

} // namespace editor
