#pragma once

// How the Simulation dock shows a BOOL value (an input's toggle, a step's
// Complete): TRUE and FALSE told apart by colour as well as by their text,
// at a glance and on a projector. Each pair keeps a text contrast of at
// least 4.5:1 (WCAG 2).

#include <QColor>
#include <QString>

namespace editor {

struct ValueColours {
    QColor text;
    QColor background;
    QColor border;
};

ValueColours valueColours(bool value);

// The style sheet of a widget of class `widgetClass` ("QToolButton",
// "QLabel") showing `value`.
QString valueStyleSheet(const char* widgetClass, bool value);

} // namespace editor
