#pragma once

#include <QPolygonF>
#include <QRectF>

class QPainter;

namespace editor::segmentstroke {

// Outlines drawn segment by segment in the painter's current pen, each
// segment as with a square cap; a horizontal or vertical one is filled as
// the rectangle it covers.
//
// Qt's raster engine fills a rectangle directly, while a stroked line or
// polyline goes through its line rasterizer or its general path stroker,
// several times the work for the long routes of the GEMMA chart: stroking
// them was most of the painting of the editor's first frame. Where two
// segments meet at a right angle, their square caps cover the corner as a
// mitre join does, so the chart's orthogonal outlines keep their shape.
// On screen and in images (pixelsnap.h) the rectangles of an outline whose
// segments are all horizontal or vertical are whole device pixels: each line
// as many pixels thick as its width rounds to, at least one, and closed at
// its corners. Any other pen (dashed, cosmetic) is drawn the ordinary way.

// An open polyline, as with Qt::FlatCap and Qt::MiterJoin.
void drawPolyline(QPainter* painter, const QPolygonF& points);

// A rectangle's outline (no fill), as with Qt::MiterJoin.
void drawRectOutline(QPainter* painter, const QRectF& rect);

} // namespace editor::segmentstroke
