#include "editor/chart/segmentstroke.h"

#include "editor/chart/pixelsnap.h"

#include <QLineF>
#include <QPainter>
#include <QPen>
#include <QVarLengthArray>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace editor::segmentstroke {

namespace {

using Segments = QVarLengthArray<QLineF, 8>;

bool drawnAsSegments(const QPen& pen)
{
    return pen.style() == Qt::SolidLine && !pen.isCosmetic() && pen.widthF() > 0;
}

bool isAxisAligned(const QLineF& line)
{
    return line.dx() == 0 || line.dy() == 0;
}

// Draws `segments` as the painter's pen would with square caps.
void drawSquareCapped(QPainter* painter, const Segments& segments)
{
    const QPen pen = painter->pen();
    const double halfWidth = pen.widthF() / 2;
    Segments slanted;
    for (const QLineF& segment : segments) {
        if (isAxisAligned(segment)) {
            const QRectF covered = QRectF(segment.p1(), segment.p2()).normalized();
            painter->fillRect(covered.adjusted(-halfWidth, -halfWidth, halfWidth, halfWidth), pen.brush());
        } else {
            slanted.append(segment);
        }
    }
    if (slanted.isEmpty())
        return;
    QPen squareCapped = pen;
    squareCapped.setCapStyle(Qt::SquareCap);
    painter->setPen(squareCapped);
    painter->drawLines(slanted.constData(), static_cast<int>(slanted.size()));
    painter->setPen(pen);
}

// The run of pixels from end `a` to end `b` of a segment along its axis. An
// end that joins another segment reaches across that segment's own stroke,
// as a square cap does, so that corners close; the outline's own ends stop
// at their point.
pixelsnap::Span lengthSpan(double a, bool aJoins, double b, bool bJoins, double width)
{
    if (a > b) {
        std::swap(a, b);
        std::swap(aJoins, bJoins);
    }
    const int begin = aJoins ? pixelsnap::strokeSpan(a, width).begin : static_cast<int>(std::lround(a));
    const int end = bJoins ? pixelsnap::strokeSpan(b, width).end : static_cast<int>(std::lround(b));
    return {begin, std::max(end, begin + 1)};
}

bool allAxisAligned(const Segments& segments)
{
    return std::all_of(segments.begin(), segments.end(), isAxisAligned);
}

// Orthogonal `segments`, each a piece of one outline that joins the next one
// (and the last the first when `closed`), in whole device pixels.
void drawSnapped(QPainter* painter, const QTransform& toDevice, const Segments& segments, bool closed)
{
    const QPen pen = painter->pen();
    const double widthX = pen.widthF() * toDevice.m11();
    const double widthY = pen.widthF() * toDevice.m22();
    const qsizetype last = segments.size() - 1;
    pixelsnap::DevicePixels pixels(painter);
    for (qsizetype i = 0; i <= last; ++i) {
        const QLineF& segment = segments[i];
        const bool startJoins = closed || i > 0;
        const bool endJoins = closed || i < last;
        const QPointF from = toDevice.map(segment.p1());
        const QPointF to = toDevice.map(segment.p2());
        if (segment.dy() == 0 && segment.dx() != 0) {
            pixels.fill(lengthSpan(from.x(), startJoins, to.x(), endJoins, widthX),
                        pixelsnap::strokeSpan(from.y(), widthY), pen.brush());
        } else {
            pixels.fill(pixelsnap::strokeSpan(from.x(), widthX),
                        lengthSpan(from.y(), startJoins, to.y(), endJoins, widthY), pen.brush());
        }
    }
}

// `line` with its ends moved towards each other by `atStart` and `atEnd`.
QLineF pulledIn(const QLineF& line, double atStart, double atEnd)
{
    const double length = line.length();
    return QLineF(line.pointAt(atStart / length), line.pointAt(1 - atEnd / length));
}

} // namespace

void drawPolyline(QPainter* painter, const QPolygonF& points)
{
    const QPen pen = painter->pen();
    if (points.size() < 2 || !drawnAsSegments(pen)) {
        painter->drawPolyline(points);
        return;
    }
    Segments segments;
    for (qsizetype i = 1; i < points.size(); ++i)
        segments.append(QLineF(points[i - 1], points[i]));
    const std::optional<QTransform> toDevice = pixelsnap::deviceTransform(*painter);
    if (toDevice && allAxisAligned(segments)) {
        drawSnapped(painter, *toDevice, segments, false);
        return;
    }
    // The polyline's own ends stay flat: square caps would stick out by half
    // the width there, so those ends are pulled in by as much.
    const double halfWidth = pen.widthF() / 2;
    const qsizetype lastIndex = segments.size() - 1;
    const double lastPull = lastIndex == 0 ? 2 * halfWidth : halfWidth;
    if (segments.front().length() <= halfWidth || segments.back().length() <= lastPull) {
        painter->drawPolyline(points); // too short to pull in
        return;
    }
    segments.front() = pulledIn(segments.front(), halfWidth, 0);
    segments[lastIndex] = pulledIn(segments[lastIndex], 0, halfWidth);
    drawSquareCapped(painter, segments);
}

void drawRectOutline(QPainter* painter, const QRectF& rect)
{
    if (!drawnAsSegments(painter->pen())) {
        painter->save();
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(rect);
        painter->restore();
        return;
    }
    const Segments sides = {
        QLineF(rect.topLeft(), rect.topRight()),
        QLineF(rect.topRight(), rect.bottomRight()),
        QLineF(rect.bottomRight(), rect.bottomLeft()),
        QLineF(rect.bottomLeft(), rect.topLeft()),
    };
    if (const std::optional<QTransform> toDevice = pixelsnap::deviceTransform(*painter)) {
        drawSnapped(painter, *toDevice, sides, true);
        return;
    }
    drawSquareCapped(painter, sides);
}

} // namespace editor::segmentstroke
