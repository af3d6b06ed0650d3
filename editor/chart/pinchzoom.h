#pragma once

// Pinch zoom for the chart and the GRAFCET tabs: a touchpad's zoom gesture
// (QNativeGestureEvent, macOS and Wayland) or a touch screen's pinch
// (QPinchGesture, once the viewport grabs Qt::PinchGesture).

#include <QPointF>

#include <optional>

class QEvent;
class QWidget;

namespace editor {

struct PinchZoom {
    double factor = 1.0; // the scale to apply now, relative to the current one
    QPointF at;          // in the viewport's coordinates
};

// The zoom a pinch event asks for, accepting it; nullopt for any other event.
std::optional<PinchZoom> pinchZoom(QEvent* event, const QWidget& viewport);

} // namespace editor
