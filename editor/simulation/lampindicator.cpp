#include "editor/simulation/lampindicator.h"

#include <QPainter>
#include <QRadialGradient>

#include <algorithm>

namespace editor {

LampIndicator::LampIndicator(QWidget* parent)
    : QWidget(parent)
{
    setFocusPolicy(Qt::NoFocus);
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

QColor LampIndicator::onColour()
{
    return QColor(0x2e, 0xc4, 0x5a);
}

QColor LampIndicator::offColour()
{
    return QColor(0x6b, 0x72, 0x7c);
}

void LampIndicator::setOn(bool on)
{
    if (m_on == on)
        return;
    m_on = on;
    update();
}

QSize LampIndicator::sizeHint() const
{
    const int side = fontMetrics().height();
    return {side, side};
}

QSize LampIndicator::minimumSizeHint() const
{
    return sizeHint();
}

void LampIndicator::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const double side = std::min(width(), height()) - 2.0;
    const QRectF lamp((width() - side) / 2, (height() - side) / 2, side, side);
    const QColor colour = m_on ? onColour() : offColour();
    // A lit lamp glows from its middle; an unlit one is flat.
    QRadialGradient glow(lamp.center() - QPointF(side / 6, side / 6), side / 2);
    glow.setColorAt(0, m_on ? colour.lighter(150) : colour);
    glow.setColorAt(1, colour);
    painter.setPen(QPen(colour.darker(150), 1));
    painter.setBrush(glow);
    painter.drawEllipse(lamp);
}

} // namespace editor
