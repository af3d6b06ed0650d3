#include "editor/chart/chartstyle.h"

#include <QPainter>

namespace editor::chartstyle {

namespace {

QFont makeFont(int pixelSize, bool bold = false)
{
    QFont font;
    font.setPixelSize(pixelSize);
    font.setBold(bold);
    return font;
}

} // namespace

QColor frameFillColor(core::Family family)
{
    switch (family) {
    case core::Family::A: return QColor(0xe3, 0xee, 0xfb);
    case core::Family::F: return QColor(0xe4, 0xf4, 0xe2);
    case core::Family::D: return QColor(0xfc, 0xe8, 0xdf);
    }
    return Qt::white;
}

QColor frameBorderColor(core::Family family)
{
    switch (family) {
    case core::Family::A: return QColor(0x5b, 0x86, 0xc0);
    case core::Family::F: return QColor(0x5a, 0x9a, 0x58);
    case core::Family::D: return QColor(0xc8, 0x6a, 0x4a);
    }
    return Qt::gray;
}

// Static fonts: built once, on the first paint (a QApplication exists by then).
const QFont& labelFont()
{
    static const QFont font = makeFont(12);
    return font;
}

const QFont& boldFont()
{
    static const QFont font = makeFont(15, true);
    return font;
}

double stepIdScale(double boxSize)
{
    return boxSize >= 60 ? 22.0 / 15.0 : 1.0;
}

void drawCentredText(QPainter* painter, const QRectF& rect, const QString& text, const QFont& font, double scale)
{
    painter->setFont(font);
    if (scale == 1.0) {
        painter->drawText(rect, Qt::AlignCenter, text);
        return;
    }
    painter->save();
    painter->translate(rect.center());
    painter->scale(scale, scale);
    const QSizeF size = rect.size() / scale;
    painter->drawText(QRectF(QPointF(-size.width() / 2, -size.height() / 2), size), Qt::AlignCenter, text);
    painter->restore();
}

} // namespace editor::chartstyle
