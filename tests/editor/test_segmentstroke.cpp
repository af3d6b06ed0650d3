// The chart's outlines drawn segment by segment (editor/chart/segmentstroke)
// must look like the polylines and rectangles QPainter strokes itself.

#include "editor/chart/segmentstroke.h"

#include <QImage>
#include <QPainter>
#include <QPen>
#include <QTest>

#include <cstdlib>
#include <functional>

using namespace editor;

namespace {

constexpr QSize kCanvas(160, 120);

// Black on white under a fractional scale, as a fitted chart is drawn.
QImage render(const QPen& pen, const std::function<void(QPainter&)>& draw)
{
    QImage image(kCanvas, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.scale(1.37, 1.37);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    draw(painter);
    return image;
}

struct Difference {
    long inkA = 0;    // total darkness of each image, in grey levels
    long inkB = 0;
    int worstPixel = 0;  // the largest difference of one pixel
    int pixelsOver = 0;  // pixels that differ by more than a third of full ink
};

Difference compare(const QImage& a, const QImage& b)
{
    Difference difference;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const int greyA = qGray(a.pixel(x, y));
            const int greyB = qGray(b.pixel(x, y));
            difference.inkA += 255 - greyA;
            difference.inkB += 255 - greyB;
            const int delta = std::abs(greyA - greyB);
            difference.worstPixel = std::max(difference.worstPixel, delta);
            if (delta > 85)
                ++difference.pixelsOver;
        }
    }
    return difference;
}

QPen chartPen(double width)
{
    return QPen(Qt::black, width, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin);
}

} // namespace

class TestSegmentStroke : public QObject {
    Q_OBJECT

private slots:
    void orthogonalPolylineMatchesQtsStroke_data();
    void orthogonalPolylineMatchesQtsStroke();
    void rectOutlineMatchesQtsStroke();
    void slantedSegmentsKeepTheirWidth();
    void dashedPenIsDrawnByQt();
    void tooShortEndsAreDrawnByQt();
};

void TestSegmentStroke::orthogonalPolylineMatchesQtsStroke_data()
{
    QTest::addColumn<QPolygonF>("route");
    QTest::addColumn<double>("width");
    QTest::newRow("one segment") << QPolygonF({{10.3, 20.6}, {90.2, 20.6}}) << 1.3;
    QTest::newRow("L") << QPolygonF({{10.3, 10.6}, {10.3, 70.2}, {100.7, 70.2}}) << 1.3;
    QTest::newRow("Z, wide pen") << QPolygonF({{10, 10}, {60.5, 10}, {60.5, 70.25}, {105, 70.25}}) << 4.0;
    QTest::newRow("U turn") << QPolygonF({{20, 10}, {20, 60}, {80, 60}, {80, 15}}) << 1.6;
}

// The same ink, pixel for pixel but for the antialiased edge pixels of the
// corners, where two square caps overlap.
void TestSegmentStroke::orthogonalPolylineMatchesQtsStroke()
{
    QFETCH(QPolygonF, route);
    QFETCH(double, width);
    const QImage byQt = render(chartPen(width), [&](QPainter& p) { p.drawPolyline(route); });
    const QImage bySegments = render(chartPen(width), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); });

    const Difference difference = compare(byQt, bySegments);
    QVERIFY(difference.inkA > 0);
    QVERIFY2(std::abs(difference.inkA - difference.inkB) < difference.inkA / 50,
             qPrintable(QStringLiteral("ink %1 against %2").arg(difference.inkB).arg(difference.inkA)));
    QVERIFY2(difference.pixelsOver <= 2 * static_cast<int>(route.size() - 2),
             qPrintable(QStringLiteral("%1 pixels differ").arg(difference.pixelsOver)));
}

void TestSegmentStroke::rectOutlineMatchesQtsStroke()
{
    const QRectF box(12.4, 8.7, 60.3, 50.1);
    const QImage byQt = render(chartPen(1.6), [&](QPainter& p) { p.drawRect(box); });
    const QImage bySegments = render(chartPen(1.6), [&](QPainter& p) { segmentstroke::drawRectOutline(&p, box); });

    const Difference difference = compare(byQt, bySegments);
    QVERIFY(std::abs(difference.inkA - difference.inkB) < difference.inkA / 50);
    QVERIFY2(difference.pixelsOver <= 8, qPrintable(QStringLiteral("%1 pixels differ").arg(difference.pixelsOver)));
}

// A route that is not orthogonal is stroked by Qt, segment by segment.
void TestSegmentStroke::slantedSegmentsKeepTheirWidth()
{
    const QPolygonF route({{10, 10}, {90, 60}});
    const QImage byQt = render(chartPen(2), [&](QPainter& p) { p.drawPolyline(route); });
    const QImage bySegments = render(chartPen(2), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); });

    const Difference difference = compare(byQt, bySegments);
    QVERIFY(std::abs(difference.inkA - difference.inkB) < difference.inkA / 50);
    QVERIFY(difference.pixelsOver <= 4);
}

void TestSegmentStroke::dashedPenIsDrawnByQt()
{
    QPen dashed = chartPen(1.3);
    dashed.setStyle(Qt::DashLine);
    const QPolygonF route({{10, 10}, {10, 70}, {100, 70}});
    const QImage byQt = render(dashed, [&](QPainter& p) { p.drawPolyline(route); });
    const QImage bySegments = render(dashed, [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); });
    QCOMPARE(bySegments, byQt);

    const QRectF box(12, 8, 60, 50);
    QCOMPARE(render(dashed, [&](QPainter& p) { segmentstroke::drawRectOutline(&p, box); }),
             render(dashed, [&](QPainter& p) { p.drawRect(box); }));
}

// Ends shorter than half the pen's width cannot be pulled in.
void TestSegmentStroke::tooShortEndsAreDrawnByQt()
{
    const QPolygonF route({{10, 10}, {10, 10.5}, {100, 10.5}});
    const QImage byQt = render(chartPen(4), [&](QPainter& p) { p.drawPolyline(route); });
    QCOMPARE(render(chartPen(4), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); }), byQt);
}

QTEST_MAIN(TestSegmentStroke)
#include "test_segmentstroke.moc"
