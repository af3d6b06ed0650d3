#include "editor/chart/segmentstroke.h"

#include <QLineF>
#include <QPainter>
#include <QPen>
#include <QVarLengthArray>

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
    drawSquareCapped(painter, {
        QLineF(rect.topLeft(), rect.topRight()),
        QLineF(rect.topRight(), rect.bottomRight()),
        QLineF(rect.bottomRight(), rect.bottomLeft()),
        QLineF(rect.bottomLeft(), rect.topLeft()),
    });
}

} // namespace editor::segmentstroke
