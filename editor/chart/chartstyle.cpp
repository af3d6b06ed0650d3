#include "editor/chart/chartstyle.h"

#include <QFontMetricsF>
#include <QHash>
#include <QPainter>

namespace editor::chartstyle {

namespace {

QFont makeFont(int pixelSize)
{
    QFont font;
    font.setPixelSize(pixelSize);
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

QColor packmlStateFillColor(core::packml::StateKind kind)
{
    switch (kind) {
    case core::packml::StateKind::Wait: return QColor(0xb8, 0xec, 0xf4);
    case core::packml::StateKind::Acting: return QColor(0xbf, 0xe8, 0xb4);
    case core::packml::StateKind::Dual: return QColor(0xff, 0xff, 0xff);
    }
    return Qt::white;
}

QColor packmlFrameFillColor(core::packml::Command command)
{
    return command == core::packml::Command::Abort ? QColor(0xfc, 0xee, 0xeb) : QColor(0xfd, 0xf7, 0xe4);
}

QColor packmlFrameBorderColor(core::packml::Command command)
{
    return command == core::packml::Command::Abort ? QColor(0xc0, 0x5a, 0x48) : QColor(0xb8, 0x8a, 0x2c);
}

// Built once, at the first use (a QApplication exists by then).
const QFont& font()
{
    static const QFont font = makeFont(kFontSize);
    return font;
}

double advance(const QString& text)
{
    // Priorities and their separator; a few dozen at most.
    constexpr qsizetype kRememberedLength = 4;
    if (text.size() > kRememberedLength)
        return QFontMetricsF(font()).horizontalAdvance(text);
    static QHash<QString, double> remembered;
    const auto found = remembered.constFind(text);
    if (found != remembered.constEnd())
        return *found;
    return *remembered.insert(text, QFontMetricsF(font()).horizontalAdvance(text));
}

double stepIdScale(double boxSize)
{
    return (boxSize >= 60 ? 22.0 : 15.0) / kFontSize;
}

void drawText(QPainter* painter, const QRectF& rect, int flags, const QString& text, double scale)
{
    painter->setFont(font());
    if (scale == 1.0) {
        painter->drawText(rect, flags, text);
        return;
    }
    // Scaled about the rectangle's centre: the text keeps its place in it.
    painter->save();
    painter->translate(rect.center());
    painter->scale(scale, scale);
    const QSizeF size = rect.size() / scale;
    painter->drawText(QRectF(QPointF(-size.width() / 2, -size.height() / 2), size), flags, text);
    painter->restore();
}

void drawCentredText(QPainter* painter, const QRectF& rect, const QString& text, double scale)
{
    drawText(painter, rect, Qt::AlignCenter, text, scale);
}

} // namespace editor::chartstyle
