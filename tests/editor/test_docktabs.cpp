// The property docks follow the tab in front (issue 33): at 1366 x 768 the
// dock column holds Step, Transition and Simulation, or Nested Step, Nested
// Transition and Simulation, with whole titles in every language; the five
// together did not fit ("Nested Transit…"). A dock the user closed stays
// closed, through tab switches and restarts; a renumbered nested step keeps
// its panel in its dock. On the shipped drilling cell.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"

#include "core/model/model.h"


#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QFontMetrics>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <memory>

using namespace editor;

class TestDockTabs : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void everyDockTabShowsItsWholeTitle_data();
    void everyDockTabShowsItsWholeTitle();
    void theFrontDockGivesPlaceToItsCounterpart();
    void aClosedDockStaysClosedAcrossTabs();
    void aClosedDockStaysClosedAfterARestart();
    void resetLayoutReopensClosedDocks();
    void renumberedStepStaysInItsDock();

private:
    void showWindow();
    void useDefaultLayout();
    void showChart();
    void showGrafcet();
    QStringList shownPropertyDocks() const;
    QDockWidget* dock(const char* name) const
    {
        return m_window->findChild<QDockWidget*>(QLatin1String(name), Qt::FindDirectChildrenOnly);
    }

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestDockTabs::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_docktabs"));
}

void TestDockTabs::init()
{
    QSettings().clear();
    m_translators = std::make_unique<Translators>();
    m_translators->setLanguage(QStringLiteral("en"));
    showWindow();
}

void TestDockTabs::cleanup()
{
    m_window.reset();
    m_translators.reset();
    QSettings().clear();
}

void TestDockTabs::showWindow()
{
    m_window = editortest::showMainWindow(*m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QString error;
    QVERIFY2(m_window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error),
             qPrintable(error));
}

// The window inside a 1366 x 768 screen (less the window manager's frame), in the default layout.
void TestDockTabs::useDefaultLayout()
{
    m_window->resize(1366 - 16, 768 - 48);
    m_window->findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
    QApplication::processEvents();
}

void TestDockTabs::showChart()
{
    m_window->findChild<QTabWidget*>(QStringLiteral("centralTabs"))->setCurrentIndex(0);
    QApplication::processEvents();
}

void TestDockTabs::showGrafcet()
{
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    QApplication::processEvents();
}

QStringList TestDockTabs::shownPropertyDocks() const
{
    QStringList shown;
    for (const char* name : {"stepDock", "transitionDock", "grafcetStepDock", "grafcetTransitionDock"}) {
        if (!dock(name)->isHidden())
            shown << QLatin1String(name);
    }
    return shown;
}

// Every dock tab bar of the window: whole titles, no scroll buttons, the
// last tab inside the bar.
static void verifyWholeTabTitles(const QMainWindow& window)
{
    for (QTabBar* bar : window.findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!bar->isVisible())
            continue;
        const QFontMetrics metrics(bar->font());
        for (int i = 0; i < bar->count(); ++i) {
            const QRect tab = bar->tabRect(i);
            QVERIFY2(metrics.horizontalAdvance(bar->tabText(i)) < tab.width(),
                     qPrintable(QStringLiteral("%1: %2 px of text in a %3 px tab")
                                    .arg(bar->tabText(i))
                                    .arg(metrics.horizontalAdvance(bar->tabText(i)))
                                    .arg(tab.width())));
            QVERIFY2(tab.left() >= 0 && tab.right() < bar->width(),
                     qPrintable(QStringLiteral("%1 at %2..%3 in a %4 px bar")
                                    .arg(bar->tabText(i))
                                    .arg(tab.left())
                                    .arg(tab.right())
                                    .arg(bar->width())));
        }
        for (const QToolButton* scroll : bar->findChildren<QToolButton*>())
            QVERIFY2(!scroll->isVisible(), "the tab bar scrolls");
    }
}

void TestDockTabs::everyDockTabShowsItsWholeTitle_data()
{
    QTest::addColumn<QString>("language");
    for (const char* language : {"en", "fr", "de", "es", "it"})
        QTest::newRow(language) << QString::fromLatin1(language);
}

void TestDockTabs::everyDockTabShowsItsWholeTitle()
{
    QFETCH(QString, language);
    QVERIFY(m_translators->setLanguage(language));
    useDefaultLayout();
    QCOMPARE(shownPropertyDocks(), (QStringList{"stepDock", "transitionDock"}));
    verifyWholeTabTitles(*m_window);
    showGrafcet();
    QCOMPARE(shownPropertyDocks(), (QStringList{"grafcetStepDock", "grafcetTransitionDock"}));
    verifyWholeTabTitles(*m_window);
    // The tab reads as the GEMMA dock it stands for; the View menu tells them apart.
    QCOMPARE(dock("grafcetStepDock")->windowTitle(), dock("stepDock")->windowTitle());
    QVERIFY(dock("grafcetStepDock")->toggleViewAction()->text() != dock("stepDock")->toggleViewAction()->text());
    QVERIFY(dock("grafcetTransitionDock")->toggleViewAction()->text()
            != dock("transitionDock")->toggleViewAction()->text());
    showChart();
    QCOMPARE(shownPropertyDocks(), (QStringList{"stepDock", "transitionDock"}));
    verifyWholeTabTitles(*m_window);
}

// The Step dock in front on the chart: Nested Step is in front in a GRAFCET
// tab, and the other way; a nested element selected brings its dock.
void TestDockTabs::theFrontDockGivesPlaceToItsCounterpart()
{
    useDefaultLayout();
    dock("stepDock")->raise();
    QApplication::processEvents();
    showGrafcet();
    QVERIFY(!dock("grafcetStepDock")->visibleRegion().isEmpty());
    dock("grafcetTransitionDock")->raise();
    QApplication::processEvents();
    showChart();
    QVERIFY(!dock("transitionDock")->visibleRegion().isEmpty());
    m_window->selection()->select(ElementRef::grafcetStep(QStringLiteral("F1"), 1));
    QApplication::processEvents();
    QCOMPARE(shownPropertyDocks(), (QStringList{"grafcetStepDock", "grafcetTransitionDock"}));
    QVERIFY(!dock("grafcetStepDock")->visibleRegion().isEmpty());
    // A GEMMA step selected from a dock while the GRAFCET tab is in front: the chart and the Step dock come.
    m_window->selection()->select(ElementRef::step(QStringLiteral("F1")));
    QApplication::processEvents();
    QCOMPARE(m_window->findChild<QTabWidget*>(QStringLiteral("centralTabs"))->currentIndex(), 0);
    QCOMPARE(shownPropertyDocks(), (QStringList{"stepDock", "transitionDock"}));
    QVERIFY(!dock("stepDock")->visibleRegion().isEmpty());
}

void TestDockTabs::aClosedDockStaysClosedAcrossTabs()
{
    useDefaultLayout();
    showGrafcet();
    QVERIFY(dock("grafcetTransitionDock")->close()); // its title bar's close button
    showChart();
    showGrafcet();
    QCOMPARE(shownPropertyDocks(), QStringList{"grafcetStepDock"});
    QAction* toggle = dock("grafcetTransitionDock")->toggleViewAction();
    QVERIFY(!toggle->isChecked());
    toggle->trigger(); // View > Nested Transition
    QApplication::processEvents();
    QCOMPARE(shownPropertyDocks(), (QStringList{"grafcetStepDock", "grafcetTransitionDock"}));
    dock("stepDock")->toggleViewAction()->trigger(); // View > Step, unchecked
    showChart();
    QCOMPARE(shownPropertyDocks(), (QStringList{"stepDock", "transitionDock"}));
    QVERIFY(dock("stepDock")->close());
    showGrafcet();
    showChart();
    QCOMPARE(shownPropertyDocks(), QStringList{"transitionDock"});
}

// The saved window state has the other context's docks hidden: only those
// the user closed stay closed at the next start.
void TestDockTabs::aClosedDockStaysClosedAfterARestart()
{
    useDefaultLayout();
    showGrafcet();
    QVERIFY(dock("grafcetTransitionDock")->close());
    QVERIFY(m_window->close());
    m_window.reset();
    showWindow();
    QCOMPARE(shownPropertyDocks(), (QStringList{"stepDock", "transitionDock"}));
    QVERIFY(m_window->tabifiedDockWidgets(dock("stepDock")).contains(dock("transitionDock")));
    showGrafcet();
    QCOMPARE(shownPropertyDocks(), QStringList{"grafcetStepDock"});
    QVERIFY(m_window->tabifiedDockWidgets(dock("grafcetStepDock")).contains(dock("simulationDock")));
}

void TestDockTabs::resetLayoutReopensClosedDocks()
{
    useDefaultLayout();
    QVERIFY(dock("transitionDock")->close());
    showGrafcet();
    QVERIFY(dock("grafcetStepDock")->close());
    useDefaultLayout();
    QCOMPARE(shownPropertyDocks(), (QStringList{"grafcetStepDock", "grafcetTransitionDock"}));
    showChart();
    QCOMPARE(shownPropertyDocks(), (QStringList{"stepDock", "transitionDock"}));
}

// A nested step renumbered in the Nested Step panel: the panel shows the
// step through the change, never its placeholder page in between (that
// switch back and forth left the form painted over the column's tab bar
// under X11), and its form stays inside the dock, below the tab bar.
void TestDockTabs::renumberedStepStaysInItsDock()
{
    useDefaultLayout();
    showGrafcet();
    m_window->selection()->select(ElementRef::grafcetStep(QStringLiteral("F1"), 1));
    QApplication::processEvents();
    QDockWidget* nestedStep = dock("grafcetStepDock");
    auto* pages = qobject_cast<QStackedWidget*>(nestedStep->widget());
    QVERIFY(pages);
    QSignalSpy pageChanges(pages, &QStackedWidget::currentChanged);
    auto* spin = nestedStep->findChild<QSpinBox*>(QStringLiteral("numberSpin"));
    QVERIFY(spin);
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("50"));
    QTest::keyClick(spin, Qt::Key_Return);
    QApplication::processEvents();
    QVERIFY(m_window->document()->model().grafcet("F1")->step(50));
    QCOMPARE(pageChanges.count(), 0);
    QCOMPARE(m_window->focusWidget(), spin); // not moved off a hidden page
    QCOMPARE(spin->value(), 50);
    const QRect content = pages->geometry().translated(nestedStep->pos());
    QVERIFY(pages->isVisible());
    QVERIFY2(nestedStep->geometry().contains(content), "the form is outside its dock");
    for (QTabBar* bar : m_window->findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (bar->isVisible())
            QVERIFY2(!bar->geometry().intersects(content), "the form covers a tab bar");
    }
}

QTEST_MAIN(TestDockTabs)
#include "test_docktabs.moc"
