#pragma once

#include <QIcon>

class QWidget;

namespace editor {

enum class ToolIcon { Add, Remove, Duplicate, MoveUp, MoveDown, SortByName };

// The icon theme's icon when there is one, else a simple drawing in the
// widget's text colour, so tool buttons stay small and recognisable on
// systems without an icon theme (and without depending on a font's glyphs).
QIcon toolIcon(ToolIcon icon, const QWidget* widget);

} // namespace editor
