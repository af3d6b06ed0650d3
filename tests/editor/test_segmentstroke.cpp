// The chart's outlines drawn segment by segment (editor/chart/segmentstroke)
// must look like the polylines and rectangles QPainter strokes itself when
// drawn as vectors (SVG, PDF, print), and be whole, evenly thick, closed
// runs of pixels when drawn on pixels (pixelsnap.h).

#include "editor/chart/pixelsnap.h"
#include "editor/chart/segmentstroke.h"

#include <QImage>
#include <QPainter>
#include <QPen>
#include <QPicture>
#include <QTest>
#include <QWidget>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <set>
#include <utility>

using namespace editor;

namespace {

constexpr QSize kCanvas(160, 120);
constexpr double kScale = 1.37; // fractional, as a fitted chart is drawn

using Drawing = std::function<void(QPainter&)>;

void prepare(QPainter& painter, const QPen& pen, double scale)
{
    painter.setRenderHint(QPainter::Antialiasing);
    painter.scale(scale, scale);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
}

QImage blankCanvas(double devicePixelRatio = 1)
{
    QImage image(kCanvas * devicePixelRatio, QImage::Format_RGB32);
    image.setDevicePixelRatio(devicePixelRatio);
    image.fill(Qt::white);
    return image;
}

// Black on white, drawn on the image's pixels.
QImage renderOnPixels(const QPen& pen, const Drawing& draw, double scale = kScale, double devicePixelRatio = 1)
{
    QImage image = blankCanvas(devicePixelRatio);
    QPainter painter(&image);
    prepare(painter, pen, scale);
    draw(painter);
    return image;
}

// The same drawn as vector output is: recorded (as into an SVG or a PDF),
// then played back onto the image.
QImage render(const QPen& pen, const Drawing& draw)
{
    QPicture picture;
    {
        QPainter recorder(&picture);
        prepare(recorder, pen, kScale);
        draw(recorder);
    }
    QImage image = blankCanvas();
    QPainter painter(&image);
    painter.drawPicture(0, 0, picture);
    return image;
}

bool isInk(const QImage& image, int x, int y)
{
    return qGray(image.pixel(x, y)) < 128;
}

// How many pixels of ink are in column `x` (or row `y`).
int inkInColumn(const QImage& image, int x)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        count += isInk(image, x, y);
    return count;
}

int inkInRow(const QImage& image, int y)
{
    int count = 0;
    for (int x = 0; x < image.width(); ++x)
        count += isInk(image, x, y);
    return count;
}

// Every pixel is paper or full ink: nothing in between.
bool isCrisp(const QImage& image)
{
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const int grey = qGray(image.pixel(x, y));
            if (grey != 0 && grey != 255)
                return false;
        }
    }
    return true;
}

// Whether all the ink is one piece, its pixels joined by their sides.
bool inkIsConnected(const QImage& image)
{
    std::set<std::pair<int, int>> ink;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (isInk(image, x, y))
                ink.insert({x, y});
    if (ink.empty())
        return false;
    std::set<std::pair<int, int>> reached{*ink.begin()};
    std::vector<std::pair<int, int>> todo{*ink.begin()};
    while (!todo.empty()) {
        const auto [x, y] = todo.back();
        todo.pop_back();
        for (const auto& next : {std::pair{x + 1, y}, std::pair{x - 1, y}, std::pair{x, y + 1}, std::pair{x, y - 1}}) {
            if (ink.count(next) && reached.insert(next).second)
                todo.push_back(next);
        }
    }
    return reached.size() == ink.size();
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

// Whether every pixel of ink touches two others by its sides, as in a closed
// ring: an open corner leaves two loose ends.
bool hasNoLooseEnds(const QImage& image)
{
    const auto inkAt = [&image](int x, int y) { return image.rect().contains(x, y) && isInk(image, x, y); };
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (inkAt(x, y) && inkAt(x + 1, y) + inkAt(x - 1, y) + inkAt(x, y + 1) + inkAt(x, y - 1) < 2)
                return false;
        }
    }
    return true;
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

    void orthogonalOutlinesAreWholePixels();
    void everyLineIsEquallyThick_data();
    void everyLineIsEquallyThick();
    void cornersAreClosedWhereverTheyFall();
    void ownEndsStopAtTheirPoint();
    void followsTheDevicePixelRatio();
    void followsTheWidgetsPlaceInItsWindow();
    void followsTheViewTransform();
    void fillMeetsItsOutline();
    void slantedOrRotatedIsDrawnExactly();
    void vectorOutputIsNotSnapped();
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

// A route that is not orthogonal is stroked by Qt, segment by segment, on
// pixels too.
void TestSegmentStroke::slantedSegmentsKeepTheirWidth()
{
    const QPolygonF route({{10, 10}, {90, 60}});
    const QImage byQt = renderOnPixels(chartPen(2), [&](QPainter& p) { p.drawPolyline(route); });
    const QImage bySegments = renderOnPixels(chartPen(2), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); });

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

void TestSegmentStroke::orthogonalOutlinesAreWholePixels()
{
    const QPolygonF route({{10.3, 10.6}, {10.3, 70.2}, {100.7, 70.2}});
    QVERIFY(isCrisp(renderOnPixels(chartPen(1.3), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); })));
    const QRectF box(12.4, 8.7, 60.3, 50.1);
    QVERIFY(isCrisp(renderOnPixels(chartPen(1.6), [&](QPainter& p) { segmentstroke::drawRectOutline(&p, box); })));
}

void TestSegmentStroke::everyLineIsEquallyThick_data()
{
    QTest::addColumn<double>("width");
    QTest::addColumn<int>("pixels");
    QTest::newRow("under half a pixel") << 0.3 << 1;  // 0.41 px, still shown
    QTest::newRow("the chart's pen") << 1.6 << 2;       // 2.19 px
    QTest::newRow("wide") << 4.0 << 5;                   // 5.48 px
}

// The U turn's three lines fall differently across the pixels; each is as
// thick as the pen's width in pixels rounds to, and never vanishes.
void TestSegmentStroke::everyLineIsEquallyThick()
{
    QFETCH(double, width);
    QFETCH(int, pixels);
    const QPolygonF route({{20.15, 10.4}, {20.15, 60.7}, {80.55, 60.7}, {80.55, 15.2}});
    const QImage image = renderOnPixels(chartPen(width), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); });
    const int middleRow = qRound(35 * kScale);
    const int middleColumn = qRound(50 * kScale);
    // A row through both verticals, a column through the horizontal.
    QCOMPARE(inkInRow(image, middleRow), 2 * pixels);
    QCOMPARE(inkInColumn(image, middleColumn), pixels);
}

// Wherever a rectangle's corners fall within the pixels, its outline is one
// closed ring: no corner left open by the rounding of its two sides.
void TestSegmentStroke::cornersAreClosedWhereverTheyFall()
{
    for (double dx = 0; dx < 1; dx += 0.125) {
        for (double dy = 0; dy < 1; dy += 0.125) {
            const QRectF box(12 + dx, 8 + dy, 60.3, 50.1);
            const QImage image = renderOnPixels(chartPen(0.6), [&](QPainter& p) { segmentstroke::drawRectOutline(&p, box); });
            const QString where = QStringLiteral("at offset %1, %2").arg(dx).arg(dy);
            QVERIFY2(inkIsConnected(image), qPrintable(where));
            QVERIFY2(hasNoLooseEnds(image), qPrintable(QStringLiteral("open corner ") + where));
            // A one-pixel ring: two pixels in every row and column between
            // its top and bottom sides, and no more.
            const int inside = qRound((box.center().y()) * kScale);
            QCOMPARE(inkInRow(image, inside), 2);
        }
    }
}

void TestSegmentStroke::ownEndsStopAtTheirPoint()
{
    const QPolygonF route({{10.3, 20.6}, {90.2, 20.6}});
    const QImage image = renderOnPixels(chartPen(1.3), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); });
    const int row = qRound(20.6 * kScale - 0.5);
    QVERIFY(isInk(image, qRound(10.3 * kScale), row));
    QVERIFY(!isInk(image, qRound(10.3 * kScale) - 1, row));
    QVERIFY(isInk(image, qRound(90.2 * kScale) - 1, row));
    QVERIFY(!isInk(image, qRound(90.2 * kScale), row));
}

// On a high-density image the lines are whole device pixels, as thick as
// the width in device pixels rounds to.
void TestSegmentStroke::followsTheDevicePixelRatio()
{
    const QPolygonF route({{20.15, 10.4}, {20.15, 40.7}, {60.55, 40.7}});
    const QImage image = renderOnPixels(chartPen(1), [&](QPainter& p) { segmentstroke::drawPolyline(&p, route); },
                                        kScale, 2);
    QVERIFY(isCrisp(image));
    QCOMPARE(inkInRow(image, qRound(25 * kScale * 2)), 3);     // 2.74 device pixels
    QCOMPARE(inkInColumn(image, qRound(40 * kScale * 2)), 3);
    QVERIFY(inkIsConnected(image));
}

namespace {

// Paints one drawing, as the chart view paints its items.
class Canvas : public QWidget {
public:
    Canvas(const QPen& pen, Drawing draw, QWidget* parent)
        : QWidget(parent)
        , m_pen(pen)
        , m_draw(std::move(draw))
    {
    }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter painter(this);
        painter.fillRect(rect(), Qt::white);
        prepare(painter, m_pen, kScale);
        m_draw(painter);
    }

private:
    QPen m_pen;
    Drawing m_draw;
};

} // namespace

// A widget paints into its window's buffer, offset to where it sits: the
// pixels its lines snap to are its own.
void TestSegmentStroke::followsTheWidgetsPlaceInItsWindow()
{
    const Drawing draw = [](QPainter& p) {
        segmentstroke::drawRectOutline(&p, QRectF(12.4, 8.7, 60.3, 50.1));
        segmentstroke::drawPolyline(&p, QPolygonF({{20.15, 70.4}, {20.15, 80.7}, {90.55, 80.7}}));
    };
    QWidget window;
    window.resize(kCanvas + QSize(40, 40));
    Canvas canvas(chartPen(1.6), draw, &window);
    canvas.setGeometry(QRect(QPoint(13, 17), kCanvas));
    const QImage inWindow = window.grab().toImage().convertToFormat(QImage::Format_RGB32).copy(canvas.geometry());
    QCOMPARE(inWindow, renderOnPixels(chartPen(1.6), draw));
}

// A window and viewport set on the painter count as part of its transform.
void TestSegmentStroke::followsTheViewTransform()
{
    const QRectF box(12.4, 8.7, 60.3, 50.1);
    const QImage byWorld = renderOnPixels(chartPen(1.6), [&](QPainter& p) { segmentstroke::drawRectOutline(&p, box); },
                                          2 * kScale);
    const QImage byView = renderOnPixels(chartPen(1.6), [&](QPainter& p) {
        p.setWindow(0, 0, kCanvas.width(), kCanvas.height());
        p.setViewport(0, 0, 2 * kCanvas.width(), 2 * kCanvas.height());
        segmentstroke::drawRectOutline(&p, box);
    });
    QVERIFY(isCrisp(byView));
    QCOMPARE(byView, byWorld);
}

// A box filled with pixelsnap::fillRect and outlined leaves no paper
// between its fill and its outline.
void TestSegmentStroke::fillMeetsItsOutline()
{
    for (double offset = 0; offset < 1; offset += 0.125) {
        const QRectF box(12 + offset, 8 + offset, 60.3, 50.1);
        const QImage image = renderOnPixels(chartPen(0.6), [&](QPainter& p) {
            pixelsnap::fillRect(&p, box, Qt::gray);
            segmentstroke::drawRectOutline(&p, box);
        });
        const int row = qRound(box.center().y() * kScale);
        int left = 0;
        while (!isInk(image, left, row))
            ++left;
        int right = image.width() - 1;
        while (!isInk(image, right, row))
            --right;
        for (int x = left; x <= right; ++x)
            QVERIFY2(image.pixel(x, row) != qRgb(255, 255, 255), qPrintable(QStringLiteral("paper at %1").arg(x)));
    }
}

void TestSegmentStroke::slantedOrRotatedIsDrawnExactly()
{
    // Under a rotation there is no pixel row to follow: drawn as Qt strokes it.
    const QRectF box(40, 10, 50, 40);
    const QImage byQt = renderOnPixels(chartPen(1.6), [&](QPainter& p) {
        p.rotate(20);
        p.drawRect(box);
    });
    const QImage bySegments = renderOnPixels(chartPen(1.6), [&](QPainter& p) {
        p.rotate(20);
        segmentstroke::drawRectOutline(&p, box);
    });
    const Difference difference = compare(byQt, bySegments);
    QVERIFY(!isCrisp(bySegments));
    QVERIFY(std::abs(difference.inkA - difference.inkB) < difference.inkA / 50);
    QVERIFY2(difference.pixelsOver <= 8, qPrintable(QStringLiteral("%1 pixels differ").arg(difference.pixelsOver)));
}

void TestSegmentStroke::vectorOutputIsNotSnapped()
{
    const QRectF box(12.4, 8.7, 60.3, 50.1);
    QVERIFY(!isCrisp(render(chartPen(1.6), [&](QPainter& p) { segmentstroke::drawRectOutline(&p, box); })));
    QPicture picture;
    QPainter recorder(&picture);
    QVERIFY(!pixelsnap::deviceTransform(recorder));
    recorder.end();
    QImage image = blankCanvas();
    QPainter painter(&image);
    QVERIFY(pixelsnap::deviceTransform(painter));
    painter.rotate(1);
    QVERIFY(!pixelsnap::deviceTransform(painter));
}

QTEST_MAIN(TestSegmentStroke)
#include "test_segmentstroke.moc"
