#pragma once

#include <QTransform>

#include <optional>

class QBrush;
class QPainter;
class QRectF;

namespace editor::pixelsnap {

// The chart's orthogonal lines and boxes aligned with the device's pixels
// when it is painted on screen or into an image.
//
// At a fitted zoom a 1.6-unit line is less than one pixel wide and falls
// across two pixel rows: antialiased, it comes out as two pale rows, and
// Qt's raster engine rasterizes every such fill edge by edge. Snapped, it
// is one dark row of whole pixels, as thick along the whole chart, and a
// plain memory fill. Vector output (SVG, PDF, print) and a rotated or
// sheared painter are drawn exactly as given.

// The painter's logical-to-device transform when it paints pixels under a
// transform that only scales and moves; nothing otherwise.
std::optional<QTransform> deviceTransform(const QPainter& painter);

// A half-open run of device pixels [begin, end) along one axis.
struct Span {
    int begin;
    int end;
};

// The pixels a stroke `width` device pixels wide centred on `centre` covers:
// as many as its width rounds to, at least one, the same count wherever it
// falls, so that every line of one pen is as thick as the others.
Span strokeSpan(double centre, double width);

// The pixels between two edges, each moved to the nearest pixel boundary;
// at least one. Two boxes sharing an edge share its boundary.
Span edgeSpan(double from, double to);

// While it lives, the painter fills whole device pixels, without
// antialiasing; its state is restored after.
class DevicePixels {
public:
    explicit DevicePixels(QPainter* painter);
    ~DevicePixels();
    DevicePixels(const DevicePixels&) = delete;
    DevicePixels& operator=(const DevicePixels&) = delete;

    void fill(Span x, Span y, const QBrush& brush);

private:
    QPainter* m_painter;
};

// `rect` filled as QPainter::fillRect does, its edges snapped where
// deviceTransform() allows.
void fillRect(QPainter* painter, const QRectF& rect, const QBrush& brush);

} // namespace editor::pixelsnap
