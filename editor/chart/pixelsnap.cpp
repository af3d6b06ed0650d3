#include "editor/chart/pixelsnap.h"

#include <QBrush>
#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainter>
#include <QRectF>

#include <algorithm>
#include <cmath>

namespace editor::pixelsnap {

std::optional<QTransform> deviceTransform(const QPainter& painter)
{
    const QPaintEngine* engine = painter.paintEngine();
    if (!engine || engine->type() != QPaintEngine::Raster)
        return std::nullopt;
    const QTransform toDevice = painter.deviceTransform();
    if (toDevice.type() > QTransform::TxScale || toDevice.m11() <= 0 || toDevice.m22() <= 0)
        return std::nullopt;
    return toDevice;
}

Span strokeSpan(double centre, double width)
{
    const int pixels = std::max(1, static_cast<int>(std::lround(width)));
    const int begin = static_cast<int>(std::lround(centre - pixels / 2.0));
    return {begin, begin + pixels};
}

Span edgeSpan(double from, double to)
{
    const int begin = static_cast<int>(std::lround(std::min(from, to)));
    const int end = static_cast<int>(std::lround(std::max(from, to)));
    return {begin, std::max(end, begin + 1)};
}

DevicePixels::DevicePixels(QPainter* painter)
    : m_painter(painter)
{
    painter->save();
    // Beyond its world and view transforms the painter moves to where the
    // widget is in its window and scales by the device's pixel ratio; a world
    // transform undoing that leaves device pixels.
    painter->resetTransform();
    painter->setViewTransformEnabled(false);
    painter->setWorldTransform(painter->deviceTransform().inverted());
    painter->setRenderHint(QPainter::Antialiasing, false);
}

DevicePixels::~DevicePixels()
{
    m_painter->restore();
}

void DevicePixels::fill(Span x, Span y, const QBrush& brush)
{
    m_painter->fillRect(QRectF(x.begin, y.begin, x.end - x.begin, y.end - y.begin), brush);
}

void fillRect(QPainter* painter, const QRectF& rect, const QBrush& brush)
{
    const std::optional<QTransform> toDevice = deviceTransform(*painter);
    if (!toDevice) {
        painter->fillRect(rect, brush);
        return;
    }
    const QRectF device = toDevice->mapRect(rect);
    DevicePixels pixels(painter);
    pixels.fill(edgeSpan(device.left(), device.right()), edgeSpan(device.top(), device.bottom()), brush);
}

} // namespace editor::pixelsnap
