// The zoom follows the central tab in front: View > Fit (Ctrl+0), Actual
// Size (Ctrl+1), Zoom In and Out act on the nested GRAFCET in front or on
// the chart, the status bar shows that tab's zoom, and Ctrl+wheel and a
// pinch zoom either.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/window/statusindicators.h"

#include <QAction>
#include <QGestureEvent>
#include <QNativeGestureEvent>
#include <QPinchGesture>
#include <QPointingDevice>
#include <QScrollBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <cmath>
#include <memory>

using namespace editor;

namespace {

QString zoomText(double zoom)
{
    return QStringLiteral("Zoom: %1 %").arg(std::lround(zoom * 100));
}

void ctrlWheel(QAbstractScrollArea& view, int notches)
{
    const QPointF at = view.viewport()->rect().center();
    QWheelEvent event(at, view.viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                      Qt::ControlModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view.viewport(), &event);
}

// A touchpad's pinch (macOS, Wayland): `value` is the change of scale.
void nativePinch(QAbstractScrollArea& view, double value)
{
    const QPointF at = view.viewport()->rect().center();
    QNativeGestureEvent event(Qt::ZoomNativeGesture, QPointingDevice::primaryPointingDevice(), 2, at, at,
                              view.viewport()->mapToGlobal(at), value, QPointF());
    QCoreApplication::sendEvent(view.viewport(), &event);
}

// A touch screen's pinch, as the gesture recognizer reports it.
void touchPinch(QAbstractScrollArea& view, double scale)
{
    QPinchGesture pinch;
    pinch.setChangeFlags(QPinchGesture::ScaleFactorChanged);
    pinch.setScaleFactor(scale);
    pinch.setCenterPoint(view.viewport()->mapToGlobal(view.viewport()->rect().center()));
    QGestureEvent event({&pinch});
    QCoreApplication::sendEvent(view.viewport(), &event);
}

} // namespace

class TestZoom : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void menuEntriesActOnTheFrontTab();
    void wheelAndPinchZoomTheFrontTab();
    void middleButtonPansAGrafcet();

private:
    QTemporaryDir m_settingsDir;
    Translators m_translators;
    std::unique_ptr<MainWindow> m_window;
    GrafcetView* m_f1 = nullptr;
    ZoomIndicator* m_indicator = nullptr;
};

void TestZoom::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_zoom"));
    m_translators.setLanguage(QStringLiteral("en"));
}

void TestZoom::init()
{
    m_window = editortest::showMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    m_f1 = m_window->grafcetView(QStringLiteral("F1"));
    m_indicator = m_window->findChild<ZoomIndicator*>(QStringLiteral("zoomIndicator"));
    QVERIFY(m_f1 && m_indicator);
}

void TestZoom::cleanup()
{
    m_window.reset();
}

void TestZoom::menuEntriesActOnTheFrontTab()
{
    ChartView* chart = m_window->chartView();
    const double chartZoom = chart->zoom();
    QCOMPARE(m_f1->zoom(), 1.0);
    QCOMPARE(m_indicator->text(), zoomText(1.0)); // the GRAFCET's, not the fitted chart's

    m_f1->setFocus();
    QTest::keyClick(m_f1, Qt::Key_0, Qt::ControlModifier); // View > Fit
    QVERIFY(m_f1->zoom() < 1.0); // F1's nine steps are taller than the tab
    const QRectF shown = m_f1->mapToScene(m_f1->viewport()->rect()).boundingRect();
    QVERIFY(shown.contains(m_f1->scene()->sceneRect()));
    QCOMPARE(chart->zoom(), chartZoom);
    QCOMPARE(m_indicator->text(), zoomText(m_f1->zoom()));

    QTest::keyClick(m_f1, Qt::Key_1, Qt::ControlModifier); // Actual Size
    QCOMPARE(m_f1->zoom(), 1.0);
    QCOMPARE(m_indicator->text(), zoomText(1.0));
    m_window->findChild<QAction*>(QStringLiteral("zoomInAction"))->trigger();
    QCOMPARE(m_f1->zoom(), 1.25);
    QCOMPARE(m_indicator->text(), zoomText(1.25));
    QCOMPARE(chart->zoom(), chartZoom);

    // The chart in front: its zoom shown, and the entries act on it.
    m_window->centralTabs()->setCurrentIndex(0);
    QCOMPARE(m_indicator->text(), zoomText(chartZoom));
    m_window->findChild<QAction*>(QStringLiteral("actualSizeAction"))->trigger();
    QCOMPARE(chart->zoom(), 1.0);
    QCOMPARE(m_f1->zoom(), 1.25);
    QCOMPARE(m_indicator->text(), zoomText(1.0));
    m_window->findChild<QAction*>(QStringLiteral("fitAction"))->trigger();
    QCOMPARE(chart->zoom(), chartZoom);

    m_window->centralTabs()->setCurrentWidget(m_f1);
    QCOMPARE(m_indicator->text(), zoomText(1.25));
}

void TestZoom::wheelAndPinchZoomTheFrontTab()
{
    ctrlWheel(*m_f1, 1);
    const double wheeled = m_f1->zoom();
    QVERIFY(wheeled > 1.1);
    QCOMPARE(m_indicator->text(), zoomText(wheeled));

    nativePinch(*m_f1, 0.5);
    QVERIFY(std::abs(m_f1->zoom() - wheeled * 1.5) < 1e-9);
    QCOMPARE(m_indicator->text(), zoomText(m_f1->zoom()));
    touchPinch(*m_f1, 0.5);
    QVERIFY(std::abs(m_f1->zoom() - wheeled * 0.75) < 1e-9);
    QCOMPARE(m_indicator->text(), zoomText(m_f1->zoom()));

    ChartView* chart = m_window->chartView();
    m_window->centralTabs()->setCurrentIndex(0);
    const double fitted = chart->zoom();
    nativePinch(*chart, 0.5);
    QVERIFY(std::abs(chart->zoom() - fitted * 1.5) < 1e-9);
    QCOMPARE(m_indicator->text(), zoomText(chart->zoom()));
    touchPinch(*chart, 0.5);
    QVERIFY(std::abs(chart->zoom() - fitted * 0.75) < 1e-9);
    ctrlWheel(*chart, -1);
    QVERIFY(chart->zoom() < fitted * 0.75);
    QCOMPARE(m_indicator->text(), zoomText(chart->zoom()));
}

// The left button draws the rubber band on the paper: the middle one pans.
void TestZoom::middleButtonPansAGrafcet()
{
    m_f1->zoomIn();
    m_f1->zoomIn();
    QScrollBar* vertical = m_f1->verticalScrollBar();
    QScrollBar* horizontal = m_f1->horizontalScrollBar();
    QVERIFY(vertical->maximum() > 100 && horizontal->maximum() > 40);
    vertical->setValue(vertical->maximum());
    horizontal->setValue(horizontal->maximum());
    const int top = vertical->value();
    const int left = horizontal->value();
    const QPoint from = m_f1->viewport()->rect().center();
    QTest::mousePress(m_f1->viewport(), Qt::MiddleButton, {}, from);
    QTest::mouseMove(m_f1->viewport(), from + QPoint(20, 60));
    QTest::mouseRelease(m_f1->viewport(), Qt::MiddleButton, {}, from + QPoint(20, 60));
    QCOMPARE(vertical->value(), top - 60);
    QCOMPARE(horizontal->value(), left - 20);
    QVERIFY(m_f1->scene()->selectedItems().isEmpty());
}

QTEST_MAIN(TestZoom)
#include "test_zoom.moc"
