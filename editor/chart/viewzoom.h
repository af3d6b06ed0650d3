#pragma once

// Zooming a view about a point, shared by the GEMMA chart and the GRAFCET
// tabs (Ctrl+wheel and pinch zoom about the point under the cursor or the
// fingers).

#include <QPointF>

class QGraphicsView;

namespace editor {

// Scales `view` to `target` (1.0 is actual size), keeping the scene point
// under `viewPoint` (viewport coordinates) where it is. False, and nothing
// changed, when the view is at that zoom already.
bool zoomViewAbout(QGraphicsView& view, double target, QPointF viewPoint);

} // namespace editor
