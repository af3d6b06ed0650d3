#include "editor/simulation/valuecolours.h"

namespace editor {

ValueColours valueColours(bool value)
{
    // TRUE: white on a deep green (5.2:1); FALSE: near black on light grey (13:1).
    if (value)
        return {QColor(0xff, 0xff, 0xff), QColor(0x1a, 0x7f, 0x37), QColor(0x14, 0x63, 0x2b)};
    return {QColor(0x20, 0x24, 0x2a), QColor(0xe4, 0xe7, 0xeb), QColor(0x9a, 0xa1, 0xab)};
}

QString valueStyleSheet(const char* widgetClass, bool value)
{
    const ValueColours colours = valueColours(value);
    return QStringLiteral("%1 { color: %2; background: %3; border: 1px solid %4; border-radius: 3px; "
                          "font-weight: bold; padding: 1px 6px; }")
        .arg(QLatin1String(widgetClass), colours.text.name(), colours.background.name(), colours.border.name());
}

} // namespace editor
