#include "editor/chart/chartstyle.h"

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
const QFont& stepFont(double boxSize)
{
    static const QFont normal = makeFont(15, true);
    static const QFont big = makeFont(22, true);
    return boxSize >= 60 ? big : normal;
}

const QFont& labelFont()
{
    static const QFont font = makeFont(12);
    return font;
}

const QFont& titleFont()
{
    static const QFont font = makeFont(15, true);
    return font;
}

const QFont& badgeFont()
{
    static const QFont font = makeFont(11, true);
    return font;
}

} // namespace editor::chartstyle
