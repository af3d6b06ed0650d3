#include "editor/chart/pinchzoom.h"

#include <QGestureEvent>
#include <QNativeGestureEvent>
#include <QPinchGesture>
#include <QWidget>

#include <algorithm>

namespace editor {

std::optional<PinchZoom> pinchZoom(QEvent* event, const QWidget& viewport)
{
    if (event->type() == QEvent::NativeGesture) {
        auto* gesture = static_cast<QNativeGestureEvent*>(event);
        if (gesture->gestureType() != Qt::ZoomNativeGesture)
            return std::nullopt;
        gesture->accept();
        // value() is the change of scale since the last event (0.1: 10 % larger).
        // A wild value cannot turn the drawing over or shrink it to nothing.
        return PinchZoom{std::max(1.0 + gesture->value(), 0.1), gesture->position()};
    }
    if (event->type() == QEvent::Gesture) {
        auto* gestures = static_cast<QGestureEvent*>(event);
        auto* pinch = static_cast<QPinchGesture*>(gestures->gesture(Qt::PinchGesture));
        if (!pinch)
            return std::nullopt;
        gestures->accept(pinch);
        if (!(pinch->changeFlags() & QPinchGesture::ScaleFactorChanged))
            return PinchZoom{1.0, viewport.mapFromGlobal(pinch->centerPoint())};
        return PinchZoom{pinch->scaleFactor(), viewport.mapFromGlobal(pinch->centerPoint())};
    }
    return std::nullopt;
}

} // namespace editor
