// The main window: what it opens on, opening and refusing files, the
// PLCopen export of the GUI, the dock layout, undo texts and the runtime
// language switch.

#include "editortestsupport.h"

#include "editor/app/autosave.h"
#include "editor/app/examplemodels.h"
#include "editor/app/languages.h"
#include "editor/app/recentfiles.h"
#include "editor/app/settings.h"
#include "editor/app/userguide.h"
#include "editor/chart/chartstyle.h"
#include "editor/chart/gemma/chartcontextmenu.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/chart/gemma/stepitem.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/docks/gemma/startguide.h"
#include "editor/docks/gemma/stepdock.h"
#include "editor/docks/problemsdock.h"
#include "editor/document.h"
#include "editor/export/chartexport.h"
#include "editor/export/exportactions.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"
#include "editor/style/windowbuttonstyle.h"
#include "editor/window/modelsettingsdialog.h"
#include "editor/window/statusindicators.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmltemplate.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCommonStyle>
#include <QContextMenuEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QMenu>
#include <QScreen>
#include <QToolBar>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QProcess>
#include <QPropertyAnimation>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyleFactory>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocumentFragment>
#include <QTextBlock>
#include <QTextBrowser>
#include <QUrl>
#include <QTimer>
#include <QTranslator>
#include <QUndoStack>

#include <algorithm>
#include <cctype>
#include <functional>
#include <memory>

#include <sys/stat.h>
#include <sys/sysmacros.h>

using namespace editor;
using editortest::countItems;

namespace {

// Wraps every text of GG Studio in brackets, to see which texts are
// retranslated without needing a finished translation. Qt's own texts
// (contexts "QShortcut", "QDialogButtonBox"...) are left alone.
class BracketTranslator : public QTranslator {
public:
    QString translate(const char* context, const char* sourceText, const char* disambiguation = nullptr,
                      int n = -1) const override
    {
        Q_UNUSED(disambiguation)
        Q_UNUSED(n)
        const QByteArray name(context);
        if (name.size() > 1 && name[0] == 'Q' && std::isupper(static_cast<unsigned char>(name[1])))
            return {};
        return QStringLiteral("[%1]").arg(QString::fromUtf8(sourceText));
    }
    bool isEmpty() const override { return false; }
};

// Closes the next modal message box once it appears (or clicks the button
// of the given text) and keeps its texts.
struct MessageBoxCatcher {
    QString text;
    QString informativeText;
    QString button; // to click; empty: close, which is Cancel or the escape button
    bool seen = false;

    void arm()
    {
        QTimer::singleShot(0, [this] { poll(); });
    }

private:
    void poll()
    {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) {
            QTimer::singleShot(10, [this] { poll(); });
            return;
        }
        seen = true;
        text = box->text();
        informativeText = box->informativeText();
        for (QAbstractButton* candidate : box->buttons()) {
            if (!button.isEmpty() && candidate->text() == button) {
                candidate->click();
                return;
            }
        }
        box->close();
    }
};

QByteArray localPath(const QString& path)
{
    return QFile::encodeName(path);
}

bool isFifo(const QString& path)
{
    struct stat status {};
    return ::lstat(localPath(path).constData(), &status) == 0 && S_ISFIFO(status.st_mode);
}

bool isCharacterDevice(const QString& path)
{
    struct stat status {};
    return ::stat(localPath(path).constData(), &status) == 0 && S_ISCHR(status.st_mode);
}

// A device a write may be aimed at without risk: a private node with
// /dev/null's numbers where allowed (root, who could replace /dev/null), else
// /dev/null itself (which others cannot replace).
QString harmlessCharacterDevice(const QTemporaryDir& dir)
{
    const QString node = dir.filePath(QStringLiteral("null-device"));
    if (::mknod(localPath(node).constData(), S_IFCHR | 0666, makedev(1, 3)) == 0)
        return node;
    return QStringLiteral("/dev/null");
}

// Whether `text` is language: it has letters and is not an element id, an
// IEC type name, a key name or a PackTags state or command name (which
// PackML never translates, spec packml.md §2.1).
bool isLanguage(const QString& text)
{
    static const QRegularExpression notLanguage(
        QStringLiteral(R"(^([A-Z][0-9](->[A-Z][0-9])?|F->D1|[A-Z]+|[A-Z]{2}[0-9]{3}|[-+]?[0-9.,]+ ?%?|Ctrl\+.*)$)"));
    const QString plain = QTextDocumentFragment::fromHtml(text).toPlainText().trimmed();
    const std::string name = plain.toStdString();
    if (core::packml::findState(name) || core::packml::findCommand(name) || plain == QLatin1String("Completed"))
        return false;
    const bool hasLetters = std::any_of(plain.begin(), plain.end(), [](QChar c) { return c.isLetter(); });
    return hasLetters && !notLanguage.match(plain).hasMatch();
}

using TextCheck = std::function<void(const QObject* owner, const QString& what, const QString& text)>;

// Passes each text `widget` shows to `check`.
void checkWidgetTexts(const QWidget& widget, const TextCheck& check)
{
    check(&widget, QStringLiteral("tooltip"), widget.toolTip());
    if (const auto* label = qobject_cast<const QLabel*>(&widget))
        check(label, QStringLiteral("text"), label->text());
    if (const auto* button = qobject_cast<const QAbstractButton*>(&widget))
        check(button, QStringLiteral("text"), button->text());
    if (const auto* edit = qobject_cast<const QLineEdit*>(&widget))
        check(edit, QStringLiteral("placeholder"), edit->placeholderText());
    if (const auto* box = qobject_cast<const QGroupBox*>(&widget))
        check(box, QStringLiteral("title"), box->title());
    if (const auto* tabs = qobject_cast<const QTabBar*>(&widget)) {
        for (int i = 0; i < tabs->count(); ++i)
            check(tabs, QStringLiteral("tab"), tabs->tabText(i));
    }
    if (const auto* view = qobject_cast<const QAbstractItemView*>(&widget); view && view->model()) {
        for (int column = 0; column < view->model()->columnCount(); ++column)
            check(view, QStringLiteral("header"), view->model()->headerData(column, Qt::Horizontal).toString());
    }
    if (const auto* combo = qobject_cast<const QComboBox*>(&widget)) {
        for (int i = 0; i < combo->count(); ++i)
            check(combo, QStringLiteral("item"), combo->itemText(i));
    }
}

// The texts of the window's docks and status bar that carry no bracket,
// each as "class name (what): text". The menus have a test of their own.
QStringList untranslatedWindowTexts(const QMainWindow& window)
{
    QStringList found;
    const TextCheck check = [&found](const QObject* owner, const QString& what, const QString& text) {
        if (isLanguage(text) && !text.contains(QLatin1Char('[')))
            found << QStringLiteral("%1 %2 (%3): %4")
                         .arg(QString::fromLatin1(owner->metaObject()->className()), owner->objectName(), what, text);
    };
    for (const QDockWidget* dock : window.findChildren<QDockWidget*>())
        check(dock, QStringLiteral("title"), dock->windowTitle());
    for (const QWidget* widget : window.findChildren<QWidget*>()) {
        if (!qobject_cast<const QMenu*>(widget) && !qobject_cast<const QMenuBar*>(widget))
            checkWidgetTexts(*widget, check);
    }
    return found;
}

core::Model namedModel(const std::string& name)
{
    core::Model model;
    model.setName(name);
    model.setStepHidden("A3", true);
    model.addVariable(core::Variable{"Start", core::IecType::Bool, "", "start button"});
    return model;
}

QString writeNativeFile(const QTemporaryDir& dir, const QString& fileName, const core::Model& model)
{
    const QString path = dir.filePath(fileName);
    const core::Status status = core::saveModelFile(model, QFile::encodeName(path).toStdString(),
                                                    core::ModelFormat::Native);
    return status ? path : QString();
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void opensOnTheTemplate();
    void docksAreAroundTheChart();
    void toolbarHoldsTheMainCommands();
    void userGuideOpensAtTheFocusedPanel();
    void rightClickOnAStepOffersItsCommands();
    void transitionMenuMovesPriorityAndEditsTheCondition();
    void sheetMenuOffersTheViewCommands();
    void enterEditsTheSelectionAndEscReturnsToTheChart();
    void ctrlClickSelectsSeveralAndDeleteHidesThemInOneStep();
    void initialStepIsNotHiddenFromTheChart();
    void rubberBandSelectsWhatItCovers();
    void resetLayoutPutsEveryPanelBack();
    void windowFitsTheScreen();
    void fittedChartLabelsReadOnALaptop();
    void simulationTakesTheColumnWhileItRuns();
    void exportNamesFollowTheModelFile();
    void opensANativeFile();
    void examplesOpenAsUntitledCopies();
    void startGuideShowsWhileNothingIsSelected();
    void nestedGrafcetOpensInATab();
    void grafcetTabsComeBackWithTheirFile();
    void brokenFileLeavesTheModelUntouched();
    void editsMarkTheTitleModified();
    void undoActionNamesTheCommand();
    void statusBarCountsProblems();
    void plcOpenExportValidates();
    void otherExportsWriteTheirFiles();
    void exportWithErrorsAsksFirst();
    void ggGeneratorExportSaysWhatItLeavesOut();
    void chartPicturesAreWritten();
    void saveOntoAFifoKeepsTheEditAndSaysWhy();
    void exportsNeverReplaceAFifoOrADevice();
    void autosaveNeverReplacesAFifo();
    void unsavedChangesAskBeforeOpening();
    void modelSettingsAreOneUndoStep();
    void modelSettingsOfferTheEvolutionRule();
    void layoutIsRestored();
    void deferredDocksFillInAfterTheFirstFrame();
    void deferredDocksKeepTheSavedLayout();
    void framesTabbedBehindNeedTheScreenAndKeepAFrame();
    void deferredDocksSaveTheirLayoutWhenClosedEarly();
    void deferredDocksAreBuiltWhenNeeded();
    void recoveryIsOffered();
    void translatorLoadsFrench();
    void languageChangeRetranslatesMenus();
    void languageChangeRetranslatesEveryWindowText_data();
    void languageChangeRetranslatesEveryWindowText();
    void languageChangeKeepsWhatTheDocksShow();
    void frenchMenuTitles();
    void windowButtonsAreDrawn();
    // Last: it replaces the application's style.
    void windowButtonStyleWrapsQtsOwnStyles();

private:
    static void discardRecoveries()
    {
        for (const RecoveryFile& file : Autosave::pendingRecoveries())
            Autosave::discard(file);
    }

    QTemporaryDir m_settingsDir;
    QTemporaryDir m_files;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestMainWindow::initTestCase()
{
    // Keep the user's settings and autosave folder out of the tests.
    QVERIFY(m_settingsDir.isValid());
    QVERIFY(m_files.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_mainwindow"));
    discardRecoveries(); // left by an interrupted run
}

void TestMainWindow::init()
{
    m_translators = std::make_unique<Translators>();
    m_translators->setLanguage(QStringLiteral("en"));
    m_window = editortest::showMainWindow(*m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestMainWindow::cleanup()
{
    m_window.reset();
    m_translators.reset();
}

void TestMainWindow::opensOnTheTemplate()
{
    const QGraphicsScene& scene = *m_window->chartScene();
    QCOMPARE(countItems<StepItem>(scene), 16);
    QCOMPARE(countItems<TransitionItem>(scene), 34);
    QVERIFY(m_window->document()->model().sameContent(core::Model()));
    QCOMPARE(m_window->windowTitle(), QStringLiteral("Untitled[*] — GG Studio"));
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::docksAreAroundTheChart()
{
    const auto dock = [this](const char* name) { return m_window->findChild<QDockWidget*>(QLatin1String(name)); };
    // One column on the right: Step and Transition above, Variables,
    // Problems and Structured Text below; nothing under the chart.
    for (const char* name : {"stepDock", "transitionDock", "variablesDock", "problemsDock", "stPreviewDock"}) {
        QVERIFY2(dock(name), name);
        QCOMPARE(m_window->dockWidgetArea(dock(name)), Qt::RightDockWidgetArea);
    }
    QVERIFY(dock("variablesDock")->geometry().top() >= dock("stepDock")->geometry().bottom());
    QCOMPARE(dock("variablesDock")->geometry().left(), dock("stepDock")->geometry().left());
    // Tabbed, not squeezed side by side.
    QVERIFY(m_window->tabifiedDockWidgets(dock("stepDock")).contains(dock("transitionDock")));
    QCOMPARE(m_window->tabifiedDockWidgets(dock("variablesDock")).size(), 3); // and the Machine panel, closed
    QVERIFY(dock("machineDock")->isHidden());
    // The chart keeps most of the window.
    const QSize chart = m_window->chartView()->size();
    QVERIFY2(chart.width() > m_window->width() / 2, qPrintable(QString::number(chart.width())));
    QVERIFY2(chart.height() > m_window->height() - 120, qPrintable(QString::number(chart.height())));
    QVERIFY2(chart.height() > m_window->height() / 2, qPrintable(QString::number(chart.height())));
    // Every dock can be shown again from the View menu.
    auto* viewMenu = m_window->findChild<QMenu*>(QStringLiteral("viewMenu"));
    QVERIFY(viewMenu);
    QVERIFY(viewMenu->actions().contains(dock("problemsDock")->toggleViewAction()));
}

void TestMainWindow::toolbarHoldsTheMainCommands()
{
    auto* toolbar = m_window->findChild<QToolBar*>(QStringLiteral("mainToolBar"));
    QVERIFY(toolbar);
    QVERIFY(toolbar->isVisible());
    QStringList names;
    for (QAction* action : toolbar->actions()) {
        if (!action->isSeparator()) {
            names << action->objectName();
            QVERIFY2(!action->icon().isNull() && !action->iconText().isEmpty(), qPrintable(action->objectName()));
        }
    }
    QCOMPARE(names, QStringList({"newAction", "openAction", "saveAction", "undoAction", "redoAction",
                                 "simulateAction", "verifyAction", "exportPlcOpenAction"}));
    // The standard shortcuts, Save As included.
    auto* saveAs = m_window->findChild<QAction*>(QStringLiteral("saveAsAction"));
    QVERIFY(saveAs->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)));
    auto* viewMenu = m_window->findChild<QMenu*>(QStringLiteral("viewMenu"));
    QVERIFY(viewMenu->actions().contains(toolbar->toggleViewAction()));
}

namespace {

// Opens the context menu the chart view shows at `viewPos` and hands it to
// `use` while it is open; closes it afterwards.
void withChartMenu(ChartView* view, const QPoint& viewPos, const std::function<void(QMenu*)>& use)
{
    bool seen = false;
    std::function<void()> poll;
    poll = [&] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (!menu) {
            QTimer::singleShot(10, poll);
            return;
        }
        seen = true;
        use(menu);
        menu->close();
    };
    QTimer::singleShot(0, poll);
    QContextMenuEvent event(QContextMenuEvent::Mouse, viewPos, view->viewport()->mapToGlobal(viewPos));
    QApplication::sendEvent(view->viewport(), &event);
    QVERIFY(seen);
}

QStringList actionNames(const QMenu* menu)
{
    QStringList names;
    for (const QAction* action : menu->actions()) {
        if (!action->isSeparator())
            names << (action->menu() ? action->menu()->objectName() : action->objectName());
    }
    return names;
}

} // namespace

void TestMainWindow::rightClickOnAStepOffersItsCommands()
{
    ChartView* view = m_window->chartView();
    const QPoint f1 = view->mapFromScene(m_window->chartScene()->stepItem(QStringLiteral("F1"))->sceneBoundingRect().center());
    QStringList names;
    withChartMenu(view, f1, [&](QMenu* menu) {
        names = actionNames(menu);
        menu->findChild<QAction*>(QStringLiteral("hideElementAction"))->trigger();
    });
    // F1, a macro-step of the template, has no GRAFCET yet: its tab opens on an empty drawing.
    QCOMPARE(names, QStringList({"openGrafcetAction", "hideElementAction", "stepTypeMenu", "makeInitialAction",
                                 "editCommentAction"}));
    // The right click selected F1, and Hide is one undoable command.
    QCOMPARE(m_window->selection()->current(), ElementRef::step(QStringLiteral("F1")));
    QVERIFY(m_window->document()->model().step("F1")->hidden);
    m_window->document()->undoStack()->undo();
    QVERIFY(!m_window->document()->model().step("F1")->hidden);

    // The type submenu checks the current type and changes it.
    withChartMenu(view, f1, [&](QMenu* menu) {
        auto* types = menu->findChild<QMenu*>(QStringLiteral("stepTypeMenu"));
        QVERIFY(types);
        QAction* macro = types->findChild<QAction*>(QStringLiteral("stepType_%1").arg(int(core::StepType::Macro)));
        QVERIFY(macro && macro->isChecked()); // F1 is a macro-step in the template
        types->findChild<QAction*>(QStringLiteral("stepType_%1").arg(int(core::StepType::Enclosing)))->trigger();
    });
    QCOMPARE(m_window->document()->model().step("F1")->type, core::StepType::Enclosing);
}

void TestMainWindow::transitionMenuMovesPriorityAndEditsTheCondition()
{
    auto* contextMenu = m_window->findChild<ChartContextMenu*>();
    QVERIFY(contextMenu);
    const core::Model& model = m_window->document()->model();
    const std::vector<const core::Transition*> outgoing = model.effectiveOutgoing("F1");
    QVERIFY(outgoing.size() > 2);
    const QString first = QString::fromStdString(outgoing[0]->id);
    const QString second = QString::fromStdString(outgoing[1]->id);
    {
        QMenu menu;
        contextMenu->populate(&menu, ElementRef::transition(first));
        QVERIFY(!menu.findChild<QAction*>(QStringLiteral("priorityUpAction"))->isEnabled());
        QAction* down = menu.findChild<QAction*>(QStringLiteral("priorityDownAction"));
        QVERIFY(down->isEnabled());
        down->trigger();
    }
    QCOMPARE(model.priority(first.toStdString()), 2);
    QCOMPARE(model.priority(second.toStdString()), 1);
    {
        QMenu menu;
        contextMenu->populate(&menu, ElementRef::transition(QStringLiteral("A1->F1")));
        QAction* negate = menu.findChild<QAction*>(QStringLiteral("negateAction"));
        QVERIFY(negate && !negate->isChecked());
        negate->trigger();
        QVERIFY(model.transition("A1->F1")->negated);
        menu.findChild<QAction*>(QStringLiteral("editConditionAction"))->trigger();
    }
    // Edit Condition selects the transition and puts the focus in its condition.
    QCOMPARE(m_window->selection()->current(), ElementRef::transition(QStringLiteral("A1->F1")));
    QVERIFY(QApplication::focusWidget());
    QCOMPARE(QApplication::focusWidget()->objectName(), QStringLiteral("conditionEdit"));
}

void TestMainWindow::sheetMenuOffersTheViewCommands()
{
    ChartView* view = m_window->chartView();
    const QPoint empty = view->mapFromScene(QPointF(40, 300));
    QStringList names;
    withChartMenu(view, empty, [&](QMenu* menu) { names = actionNames(menu); });
    QCOMPARE(names, QStringList({"showHiddenAction", "fitAction", "exportChartAction"}));
}

void TestMainWindow::enterEditsTheSelectionAndEscReturnsToTheChart()
{
    ChartView* view = m_window->chartView();
    m_window->selection()->select(ElementRef::transition(QStringLiteral("A1->F4")));
    view->setFocus();
    QTest::keyClick(view, Qt::Key_F2);
    QVERIFY(QApplication::focusWidget());
    QCOMPARE(QApplication::focusWidget()->objectName(), QStringLiteral("conditionEdit"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
    // A step: Enter goes to its type.
    m_window->selection()->select(ElementRef::step(QStringLiteral("F1")));
    QTest::keyClick(view, Qt::Key_Return);
    QVERIFY(QApplication::focusWidget());
    QCOMPARE(QApplication::focusWidget()->objectName(), QStringLiteral("typeCombo"));
}

void TestMainWindow::ctrlClickSelectsSeveralAndDeleteHidesThemInOneStep()
{
    ChartView* view = m_window->chartView();
    ChartScene* scene = m_window->chartScene();
    const auto centre = [&](QGraphicsItem* item) { return view->mapFromScene(item->sceneBoundingRect().center()); };
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, centre(scene->stepItem(QStringLiteral("F4"))));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::ControlModifier,
                      centre(scene->stepItem(QStringLiteral("F5"))));
    const QList<ElementRef> both{ElementRef::step(QStringLiteral("F4")), ElementRef::step(QStringLiteral("F5"))};
    QCOMPARE(m_window->selection()->elements().size(), 2);
    for (const ElementRef& element : both)
        QVERIFY(m_window->selection()->elements().contains(element));
    // The docks show the one added last.
    QCOMPARE(m_window->selection()->current(), ElementRef::step(QStringLiteral("F5")));
    QVERIFY(scene->stepItem(QStringLiteral("F4"))->isSelected() && scene->stepItem(QStringLiteral("F5"))->isSelected());

    // Right-click on one of them offers to hide both.
    QStringList names;
    withChartMenu(view, centre(scene->stepItem(QStringLiteral("F4"))), [&](QMenu* menu) { names = actionNames(menu); });
    QVERIFY2(names.mid(0, 2) == QStringList({"hideSelectionAction", "showSelectionAction"}),
             qPrintable(names.join(QLatin1Char(' '))));
    QCOMPARE(m_window->selection()->elements().size(), 2); // the right click kept both

    // Delete on the chart hides both, as one undoable step.
    const int before = m_window->document()->undoStack()->count();
    m_window->activateWindow(); // the menu took the activation
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    view->setFocus();
    QTest::keyClick(view, Qt::Key_Delete);
    const core::Model& model = m_window->document()->model();
    QVERIFY(model.step("F4")->hidden && model.step("F5")->hidden);
    QCOMPARE(m_window->document()->undoStack()->count(), before + 1);
    QCOMPARE(m_window->document()->undoStack()->undoText(), QStringLiteral("Hide 2 elements"));
    m_window->document()->undoStack()->undo();
    QVERIFY(!model.step("F4")->hidden && !model.step("F5")->hidden);

    // A plain click selects one again.
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, centre(scene->stepItem(QStringLiteral("F4"))));
    QCOMPARE(m_window->selection()->elements(), QList<ElementRef>{ElementRef::step(QStringLiteral("F4"))});
}

// The template's initial step A6 on the chart: its Hide entry is disabled
// with the reason, and Delete is refused with the reason in the status bar.
void TestMainWindow::initialStepIsNotHiddenFromTheChart()
{
    ChartView* view = m_window->chartView();
    ChartScene* scene = m_window->chartScene();
    const auto centre = [&](const QString& id) {
        return view->mapFromScene(scene->stepItem(id)->sceneBoundingRect().center());
    };
    const core::Model& model = m_window->document()->model();
    QVERIFY(model.step("A6")->initial);
    withChartMenu(view, centre(QStringLiteral("A6")), [&](QMenu* menu) {
        QAction* hide = menu->findChild<QAction*>(QStringLiteral("hideElementAction"));
        QVERIFY(hide);
        QVERIFY(!hide->isEnabled());
        QVERIFY(hide->toolTip().contains(QStringLiteral("A6 is the initial step")));
    });
    m_window->activateWindow(); // the menu took the activation
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, centre(QStringLiteral("A6")));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::ControlModifier, centre(QStringLiteral("F4")));
    withChartMenu(view, centre(QStringLiteral("F4")), [&](QMenu* menu) {
        QAction* hideAll = menu->findChild<QAction*>(QStringLiteral("hideSelectionAction"));
        QVERIFY(hideAll && !hideAll->isEnabled());
    });
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    view->setFocus();
    const int before = m_window->document()->undoStack()->count();
    QTest::keyClick(view, Qt::Key_Delete);
    QVERIFY(!model.step("A6")->hidden && !model.step("F4")->hidden);
    QCOMPARE(m_window->document()->undoStack()->count(), before);
    QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("A6 is the initial step")),
             qPrintable(m_window->statusBar()->currentMessage()));
    // A hidden step offers no Make Initial Step.
    QVERIFY(m_window->document()->push(new SetStepHiddenCommand(*m_window->document(), QStringLiteral("F4"), true)));
    m_window->findChild<QAction*>(QStringLiteral("showHiddenAction"))->setChecked(true);
    withChartMenu(view, centre(QStringLiteral("F4")), [&](QMenu* menu) {
        QAction* initial = menu->findChild<QAction*>(QStringLiteral("makeInitialAction"));
        QVERIFY(initial && !initial->isEnabled());
    });
}

void TestMainWindow::rubberBandSelectsWhatItCovers()
{
    ChartView* view = m_window->chartView();
    ChartScene* scene = m_window->chartScene();
    // A band around A5 and A6 (left column of the A frame), from empty sheet.
    const QRectF a5 = scene->stepItem(QStringLiteral("A5"))->sceneBoundingRect();
    const QRectF a6 = scene->stepItem(QStringLiteral("A6"))->sceneBoundingRect();
    const QRectF band = a5.united(a6).adjusted(-6, -6, 6, 6);
    const QPoint from = view->mapFromScene(band.topLeft());
    const QPoint to = view->mapFromScene(band.bottomRight());
    QWidget* viewport = view->viewport();
    const auto send = [&](QEvent::Type type, const QPoint& pos, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent event(type, pos, viewport->mapToGlobal(pos), button, buttons, Qt::ShiftModifier);
        QApplication::sendEvent(viewport, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseMove, (from + to) / 2, Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    QList<ElementRef> selected = m_window->selection()->elements();
    QVERIFY2(selected.contains(ElementRef::step(QStringLiteral("A5"))) && selected.contains(ElementRef::step(QStringLiteral("A6"))),
             qPrintable(QString::number(selected.size())));
    // Dragging without a modifier still pans: the drag mode is back.
    QCOMPARE(view->dragMode(), QGraphicsView::ScrollHandDrag);
}

void TestMainWindow::userGuideOpensAtTheFocusedPanel()
{
    auto* help = m_window->findChild<QAction*>(QStringLiteral("userGuideAction"));
    QVERIFY(help);
    QVERIFY(help->shortcuts().contains(QKeySequence(Qt::Key_F1)));
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));

    // Every topic is a heading of the guide, so renaming one in docs/ fails here.
    UserGuide guide;
    for (int i = 0; i < UserGuide::kTopicCount; ++i) {
        const auto topic = static_cast<UserGuide::Topic>(i);
        guide.showTopic(topic);
        QCOMPARE(guide.currentHeading(), UserGuide::heading(topic));
        QCOMPARE(guide.browser()->textCursor().block().text(), UserGuide::heading(topic));
    }
    // The guide shows its picture, and its links open the reference pages offline.
    QVERIFY(guide.browser()->toHtml().contains(QStringLiteral("main-window-template.png")));
    // Every picture the guide shows is embedded with it.
    QFile page(QStringLiteral(":/docs/user-guide.md"));
    QVERIFY(page.open(QIODevice::ReadOnly));
    const QString markdown = QString::fromUtf8(page.readAll());
    QRegularExpressionMatchIterator pictures =
        QRegularExpression(QStringLiteral(R"(!\[[^\]]*\]\((images/[^)]+)\))")).globalMatch(markdown);
    int pictureCount = 0;
    while (pictures.hasNext()) {
        const QString path = QStringLiteral(":/docs/") + pictures.next().captured(1);
        QVERIFY2(QImage(path).width() > 0, qPrintable(path));
        ++pictureCount;
    }
    QVERIFY(pictureCount >= 5);
    guide.browser()->setSource(QUrl(QStringLiteral("diagnostics.md")));
    QVERIFY2(guide.browser()->toPlainText().contains(QStringLiteral("GG202")),
             qPrintable(guide.browser()->source().toString()));
    guide.close();

    // F1 in the Variables panel, then on the chart.
    auto* table = m_window->findChild<QDockWidget*>(QStringLiteral("variablesDock"))->findChild<QTableView*>();
    QVERIFY(table);
    table->setFocus();
    help->trigger();
    auto* shown = m_window->findChild<UserGuide*>();
    QVERIFY(shown && shown->isVisible());
    QCOMPARE(shown->currentHeading(), QStringLiteral("The Variables panel"));
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    m_window->chartView()->setFocus();
    help->trigger();
    QCOMPARE(shown->currentHeading(), QStringLiteral("The chart"));
}

void TestMainWindow::resetLayoutPutsEveryPanelBack()
{
    const auto dock = [this](const char* name) { return m_window->findChild<QDockWidget*>(QLatin1String(name)); };
    auto* toolbar = m_window->findChild<QToolBar*>(QStringLiteral("mainToolBar"));
    dock("stepDock")->setFloating(true);
    dock("problemsDock")->hide();
    m_window->addDockWidget(Qt::LeftDockWidgetArea, dock("variablesDock"));
    toolbar->hide();
    auto* reset = m_window->findChild<QAction*>(QStringLiteral("resetLayoutAction"));
    QVERIFY(reset);
    reset->trigger();
    for (const char* name : {"stepDock", "transitionDock", "simulationDock"}) {
        QVERIFY2(!dock(name)->isFloating() && !dock(name)->isHidden(), name);
        QCOMPARE(m_window->dockWidgetArea(dock(name)), Qt::RightDockWidgetArea);
    }
    for (const char* name : {"variablesDock", "problemsDock", "stPreviewDock"}) {
        QVERIFY2(!dock(name)->isHidden(), name);
        QCOMPARE(m_window->dockWidgetArea(dock(name)), Qt::RightDockWidgetArea);
    }
    QVERIFY(dock("variablesDock")->geometry().top() >= dock("stepDock")->geometry().bottom());
    QVERIFY(m_window->tabifiedDockWidgets(dock("variablesDock")).contains(dock("problemsDock")));
    QVERIFY(!toolbar->isHidden());
}

// The window the first start opens on a 1366 x 768 screen (its available
// area less the title bar and frame allowance) and on 1920 x 1080, in the
// default layout: the fitted sheet draws the transition labels and
// priorities at least 8 px high.
void TestMainWindow::fittedChartLabelsReadOnALaptop()
{
    for (const QSize& size : {QSize(1366 - 16, 768 - 48), QSize(1920 - 16, 1080 - 48)}) {
        // As at a first start: the default layout applied before the window
        // is shown and laid out.
        QSettings().clear();
        MainWindow window(*m_translators);
        window.resize(size);
        window.findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QApplication::processEvents();
        QCOMPARE(window.size(), size); // Reset Layout never makes the window taller than the screen
        // Whatever the docks show, the window fits a laptop screen.
        QVERIFY(window.minimumSizeHint().height() <= 768 - 48);
        window.chartView()->zoomToFit();
        const double labelPixels = chartstyle::kFontSize * window.chartView()->zoom();
        QVERIFY2(labelPixels >= 8.0, qPrintable(QStringLiteral("%1 px at %2 x %3 (zoom %4)")
                                                    .arg(labelPixels)
                                                    .arg(size.width())
                                                    .arg(size.height())
                                                    .arg(window.chartView()->zoom())));
        // The column takes what the height-fitted sheet leaves: little is wasted beside the sheet.
        const QRect sheet = window.chartView()->mapFromScene(window.chartScene()->sceneRect()).boundingRect();
        QVERIFY2(window.chartView()->viewport()->width() - sheet.width() < 80,
                 qPrintable(QStringLiteral("%1 px around a %2 px sheet")
                                .arg(window.chartView()->viewport()->width() - sheet.width())
                                .arg(sheet.width())));
        QVERIFY(window.close());
    }
    QSettings().clear();
}

// Simulating, the Simulation dock gets most of the dock column (the docks
// below are locked then); ending gives the column back as it was.
void TestMainWindow::simulationTakesTheColumnWhileItRuns()
{
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->resize(1366 - 16, 768 - 48);
    m_window->findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
    QApplication::processEvents();
    auto* simulation = m_window->findChild<QDockWidget*>(QStringLiteral("simulationDock"));
    auto* variables = m_window->findChild<QDockWidget*>(QStringLiteral("variablesDock"));
    const int lowerBefore = variables->height();
    auto* simulate = m_window->findChild<QAction*>(QStringLiteral("simulateAction"));
    simulate->setChecked(true);
    QApplication::processEvents();
    QVERIFY(simulation->isVisible());
    QVERIFY2(simulation->height() >= 2 * variables->height(),
             qPrintable(QStringLiteral("%1 over %2").arg(simulation->height()).arg(variables->height())));
    simulate->setChecked(false);
    QApplication::processEvents();
    // Within a few pixels: the group above also holds the other template's
    // (hidden) docks, and Qt's resizeDocks rounds the split by up to 3 px then.
    QVERIFY2(qAbs(variables->height() - lowerBefore) <= 4,
             qPrintable(QStringLiteral("%1, was %2").arg(variables->height()).arg(lowerBefore)));
}

void TestMainWindow::windowFitsTheScreen()
{
    // The first start (no saved geometry): inside the screen's available
    // area, with room left for the title bar the window manager adds.
    m_window.reset();
    QSettings().clear();
    MainWindow window(*m_translators);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QRect available = window.screen()->availableGeometry();
    QVERIFY2(window.width() + 16 <= available.width() && window.height() + 48 <= available.height(),
             qPrintable(QStringLiteral("%1 x %2 in %3 x %4")
                            .arg(window.width())
                            .arg(window.height())
                            .arg(available.width())
                            .arg(available.height())));
}

void TestMainWindow::exportNamesFollowTheModelFile()
{
    core::Model model;
    QVERIFY(model.setName("Press_Line"));
    QCOMPARE(ExportActions::suggestedBaseName(QStringLiteral("/work/press.json"), model), QStringLiteral("press"));
    QCOMPARE(ExportActions::suggestedBaseName(QStringLiteral("/work/cell.ggstudio.json"), model),
             QStringLiteral("cell"));
    // Untitled: the model's name, which is also its PLC program's.
    QCOMPARE(ExportActions::suggestedBaseName(QString(), model), QStringLiteral("Press_Line"));
}

void TestMainWindow::opensANativeFile()
{
    const QString path = writeNativeFile(m_files, QStringLiteral("bottling.json"), namedModel("Bottling"));
    QVERIFY(!path.isEmpty());
    QVERIFY(m_window->openFile(path));
    QCOMPARE(m_window->windowTitle(), QStringLiteral("bottling.json[*] — GG Studio"));
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(m_window->document()->model().sameContent(namedModel("Bottling")));
    QCOMPARE(m_window->document()->filePath(), path);
    auto* recent = m_window->findChild<QMenu*>(QStringLiteral("recentFilesMenu"));
    QVERIFY(recent);
    QVERIFY(recent->actions().first()->text().contains(QStringLiteral("bottling.json")));
}

void TestMainWindow::examplesOpenAsUntitledCopies()
{
    auto* menu = m_window->findChild<QMenu*>(QStringLiteral("examplesMenu"));
    QVERIFY(menu);
    const std::vector<ExampleModel> examples = exampleModels();
    QCOMPARE(menu->actions().size(), qsizetype(examples.size()));
    for (size_t i = 0; i < examples.size(); ++i) {
        QAction* action = menu->actions()[qsizetype(i)];
        QCOMPARE(action->text(), examples[i].title);
        action->trigger();
        // The shipped file, as an untitled copy: Save asks for a new name.
        const core::LoadedModel shipped = core::loadModelFile(
            std::string(GGSTUDIO_EXAMPLES_DIR "/") + examples[i].fileName.toStdString());
        QVERIFY2(shipped.ok(), shipped.error.toString().c_str());
        QVERIFY(m_window->document()->model().sameContent(*shipped.model));
        QVERIFY(m_window->document()->filePath().isEmpty());
        QVERIFY(!m_window->document()->isModified());
    }
    // The drilling cell opens with its nested GRAFCETs and nothing to report.
    menu->actions().first()->trigger();
    QVERIFY(m_window->document()->model().grafcet("F1"));
    QVERIFY(m_window->document()->diagnostics().empty());
}

// The first start explains itself in the dock column: the start guide while
// nothing is selected, the element's properties once something is; its
// buttons open the first example and the user guide.
void TestMainWindow::startGuideShowsWhileNothingIsSelected()
{
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    auto* guide = m_window->findChild<StartGuide*>(QStringLiteral("startGuide"));
    QVERIFY(guide);
    QVERIFY(guide->isVisible());
    QVERIFY(guide->findChild<QLabel*>(QStringLiteral("startGuideText"))->text().contains(QStringLiteral("Delete")));

    Selection* selection = m_window->selection();
    selection->select(ElementRef::step(QStringLiteral("A1")));
    QVERIFY(!guide->isVisible());
    auto* stepDock = m_window->findChild<StepDock*>(QStringLiteral("stepDock"));
    QCOMPARE(stepDock->stepId(), QStringLiteral("A1"));
    // A transition selected: the Step dock says what it is for, no guide.
    selection->select(ElementRef::transition(QStringLiteral("A1->F1")));
    QVERIFY(!guide->isVisibleTo(stepDock));
    selection->clear();
    QVERIFY(guide->isVisibleTo(stepDock));

    guide->exampleButton()->click();
    QVERIFY(m_window->document()->model().grafcet("F1")); // the drilling cell
    QVERIFY(m_window->document()->filePath().isEmpty());
    guide->userGuideButton()->click();
    auto* shown = m_window->findChild<UserGuide*>();
    QVERIFY(shown && shown->isVisible());
    shown->close();
}

// A step's nested GRAFCET opens in a tab beside the GEMMA chart, drawn from
// its computed layout, from the Step dock, the chart's context menu or a
// double-click; one tab per GRAFCET; the chart's tab stays; a new model
// closes the tabs of GRAFCETs it does not have.
void TestMainWindow::nestedGrafcetOpensInATab()
{
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell
    // Without its machine: the Machine tab (test_machineview.cpp) would come first.
    QVERIFY(m_window->document()->modelForCommands().setMachine({}).ok);
    const core::Grafcet* f1 = m_window->document()->model().grafcet("F1");
    QVERIFY(f1);
    QTabWidget* tabs = m_window->centralTabs();
    QCOMPARE(tabs->count(), 1);
    QVERIFY(!tabs->tabBar()->isVisible()); // the chart alone: no tab bar

    // From the Step dock: its button shows for a step that has or may have a GRAFCET.
    m_window->selection()->select(ElementRef::step(QStringLiteral("A1")));
    auto* button = m_window->findChild<QPushButton*>(QStringLiteral("openGrafcetButton"));
    QVERIFY(button);
    QVERIFY(!button->isVisibleTo(button->window()));
    m_window->selection()->select(ElementRef::step(QStringLiteral("A7"))); // a macro-step without one yet
    QVERIFY(button->isVisibleTo(button->window()));
    m_window->selection()->select(ElementRef::step(QStringLiteral("F1")));
    QVERIFY(button->isVisibleTo(button->window()));
    button->click();
    QCOMPARE(tabs->count(), 2);
    QVERIFY(tabs->tabBar()->isVisible());
    QCOMPARE(tabs->tabText(1), QStringLiteral("F1 Normal production"));
    GrafcetView* view = m_window->grafcetView(QStringLiteral("F1"));
    QVERIFY(view);
    QCOMPARE(tabs->currentWidget(), static_cast<QWidget*>(view));
    GrafcetScene* scene = view->grafcetScene();
    for (const core::GrafcetStep& step : f1->steps())
        QVERIFY2(scene->stepItem(step.number), qPrintable(QString::number(step.number)));
    bool edgeDrawn = false;
    for (const core::GrafcetTransition& transition : f1->transitions()) {
        GrafcetTransitionItem* item = scene->transitionItem(transition.number);
        QVERIFY(item);
        edgeDrawn = edgeDrawn || item->labelText().contains(QStringLiteral("↓"));
    }
    QVERIFY(edgeDrawn); // F1's FE PartPresent is drawn ↓PartPresent
    QVERIFY(view->zoom() == 1.0); // readable at the chart's label size

    // Export Chart writes the picture in front: this GRAFCET, then the GEMMA sheet.
    QTemporaryDir pictures;
    QString error;
    const QString grafcetSvg = pictures.filePath(QStringLiteral("f1.svg"));
    QVERIFY2(m_window->exportActions()->writeChart(grafcetSvg, ChartExport::Format::Svg, &error), qPrintable(error));
    QFile grafcetFile(grafcetSvg);
    QVERIFY(grafcetFile.open(QIODevice::ReadOnly));
    const QByteArray grafcetPicture = grafcetFile.readAll();
    QVERIFY(grafcetPicture.contains("DrillLow") && !grafcetPicture.contains("Stop procedures"));
    tabs->setCurrentIndex(0);
    const QString chartSvg = pictures.filePath(QStringLiteral("chart.svg"));
    QVERIFY2(m_window->exportActions()->writeChart(chartSvg, ChartExport::Format::Svg, &error), qPrintable(error));
    QFile chartFile(chartSvg);
    QVERIFY(chartFile.open(QIODevice::ReadOnly));
    QVERIFY(chartFile.readAll().contains("Stop procedures"));
    tabs->setCurrentWidget(view);

    // Again from the chart: the same tab, not a second one.
    tabs->setCurrentIndex(0);
    const QPoint f1OnChart =
        m_window->chartView()->mapFromScene(m_window->chartScene()->stepItem(QStringLiteral("F1"))->sceneBoundingRect().center());
    QTest::mouseDClick(m_window->chartView()->viewport(), Qt::LeftButton, {}, f1OnChart);
    QCOMPARE(tabs->count(), 2);
    QCOMPARE(tabs->currentWidget(), static_cast<QWidget*>(view));
    QVERIFY(!m_window->openNestedGrafcet(QStringLiteral("A1"))); // A1 has none
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F2")));
    QCOMPARE(tabs->count(), 3);

    // Closing: a GRAFCET's tab closes, the chart's does not.
    emit tabs->tabCloseRequested(0);
    QCOMPARE(tabs->widget(0), static_cast<QWidget*>(m_window->chartView()));
    emit tabs->tabCloseRequested(tabs->indexOf(m_window->grafcetView(QStringLiteral("F2"))));
    QCOMPARE(tabs->count(), 2);

    // A new model: F1 keeps its GRAFCET (the tab redraws it), F2 loses it.
    core::Model changed = m_window->document()->model();
    core::Grafcet grown = *f1;
    core::GrafcetStep extra;
    extra.number = 99;
    QVERIFY(grown.addStep(extra).ok);
    QVERIFY(changed.setGrafcet("F1", grown).ok);
    m_window->document()->replaceModel(changed, QString(), core::ModelFormat::Native);
    QVERIFY(m_window->grafcetView(QStringLiteral("F1")));
    QVERIFY(m_window->grafcetView(QStringLiteral("F1"))->grafcetScene()->stepItem(99));
    m_window->document()->replaceModel(core::Model(), QString(), core::ModelFormat::Native);
    QCOMPARE(tabs->count(), 1);
}

void TestMainWindow::grafcetTabsComeBackWithTheirFile()
{
    m_window->findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell
    // Without its machine: the Machine tab (test_machineview.cpp) would come first.
    QVERIFY(m_window->document()->modelForCommands().setMachine({}).ok);
    const QString cell = m_files.filePath(QStringLiteral("tabs-cell.json"));
    QVERIFY(m_window->saveFile(cell));
    QTabWidget* tabs = m_window->centralTabs();
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F2")));
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    tabs->setCurrentWidget(m_window->grafcetView(QStringLiteral("F2")));

    // Another file: its own tabs (none), not the cell's.
    editortest::answerNewModel("templateGemma");
    m_window->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    QCOMPARE(tabs->count(), 1);
    const QString other = m_files.filePath(QStringLiteral("tabs-other.json"));
    QVERIFY(m_window->saveFile(other));
    QVERIFY(m_window->openFile(cell));
    QCOMPARE(tabs->count(), 3);
    QCOMPARE(tabs->widget(1), static_cast<QWidget*>(m_window->grafcetView(QStringLiteral("F2"))));
    QCOMPARE(tabs->widget(2), static_cast<QWidget*>(m_window->grafcetView(QStringLiteral("F1"))));
    QCOMPARE(tabs->currentWidget(), static_cast<QWidget*>(m_window->grafcetView(QStringLiteral("F2"))));
    QVERIFY(m_window->openFile(other));
    QCOMPARE(tabs->count(), 1);

    // Closing a tab and choosing the chart are remembered too, through a new window.
    QVERIFY(m_window->openFile(cell));
    emit tabs->tabCloseRequested(tabs->indexOf(m_window->grafcetView(QStringLiteral("F2"))));
    tabs->setCurrentIndex(0);
    m_window->close();
    m_window = editortest::showMainWindow(*m_translators);
    QVERIFY(m_window->openFile(cell));
    tabs = m_window->centralTabs();
    QCOMPARE(tabs->count(), 2);
    QVERIFY(m_window->grafcetView(QStringLiteral("F1")));
    QCOMPARE(tabs->currentIndex(), 0);
}

void TestMainWindow::brokenFileLeavesTheModelUntouched()
{
    const QString good = writeNativeFile(m_files, QStringLiteral("good.json"), namedModel("Good"));
    QVERIFY(m_window->openFile(good));
    const QString title = m_window->windowTitle();

    const QString broken = m_files.filePath(QStringLiteral("broken.json"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"format\": \"ggstudio-model\", \"version\": ");
    file.close();

    MessageBoxCatcher catcher;
    catcher.arm();
    QVERIFY(!m_window->openFile(broken));
    QVERIFY(catcher.seen);
    QVERIFY2(catcher.text.contains(QStringLiteral("broken.json")), qPrintable(catcher.text));
    // "FILE: LOCATION: MESSAGE" from the loader.
    QVERIFY2(catcher.informativeText.startsWith(broken + QStringLiteral(": ")), qPrintable(catcher.informativeText));
    QVERIFY(m_window->document()->model().sameContent(namedModel("Good")));
    QCOMPARE(m_window->document()->filePath(), good);
    QCOMPARE(m_window->windowTitle(), title);
}

void TestMainWindow::editsMarkTheTitleModified()
{
    Document& document = *m_window->document();
    QVERIFY(document.push(new SetStepHiddenCommand(document, QStringLiteral("A2"), true)));
    QVERIFY(m_window->isWindowModified());
    document.undoStack()->undo();
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::undoActionNamesTheCommand()
{
    auto* undo = m_window->findChild<QAction*>(QStringLiteral("undoAction"));
    auto* redo = m_window->findChild<QAction*>(QStringLiteral("redoAction"));
    QVERIFY(undo && redo);
    QVERIFY(!undo->isEnabled());
    QCOMPARE(undo->shortcut(), QKeySequence(QKeySequence::Undo));

    Document& document = *m_window->document();
    auto* command = new SetStepHiddenCommand(document, QStringLiteral("A2"), true);
    const QString text = command->text();
    QVERIFY(document.push(command));
    QVERIFY(undo->isEnabled());
    QCOMPARE(undo->text(), QStringLiteral("&Undo %1").arg(text));
    // The toolbar's button keeps its width: the command is in its tooltip.
    QCOMPARE(undo->iconText(), QStringLiteral("Undo"));
    QCOMPARE(undo->toolTip(), QStringLiteral("Undo %1").arg(text));
    undo->trigger();
    QVERIFY(!document.model().step("A2")->hidden);
    QCOMPARE(redo->text(), QStringLiteral("&Redo %1").arg(text));
    QCOMPARE(redo->iconText(), QStringLiteral("Redo"));
    QCOMPARE(redo->toolTip(), QStringLiteral("Redo %1").arg(text));
    QCOMPARE(undo->toolTip(), QStringLiteral("Undo"));
    redo->trigger();
    QVERIFY(document.model().step("A2")->hidden);
}

void TestMainWindow::statusBarCountsProblems()
{
    auto* counter = m_window->findChild<ProblemCounter*>();
    QVERIFY(counter);
    int errors = 0;
    for (const core::Diagnostic& diagnostic : m_window->document()->diagnostics())
        errors += diagnostic.severity == core::Severity::Error ? 1 : 0;
    QVERIFY(errors > 0); // the template's conditions are empty
    QCOMPARE(counter->errorCount(), errors);

    Document& document = *m_window->document();
    QVERIFY(document.push(new SetStepHiddenCommand(document, QStringLiteral("F1"), true)));
    QVERIFY(counter->errorCount() < errors); // F1's nine transitions no longer count
}

void TestMainWindow::plcOpenExportValidates()
{
    const QString path = m_files.filePath(QStringLiteral("gemma.xml"));
    QVERIFY(m_window->exportPlcOpen(path, core::Dialect::Iec));
    QVERIFY(QFile::exists(path));

    QProcess xmllint;
    xmllint.start(QStringLiteral("xmllint"),
                  {QStringLiteral("--noout"), QStringLiteral("--schema"),
                   QStringLiteral(GGSTUDIO_REFERENCE_DIR "/plcopen/tc6_xml_v201.xsd"), path});
    if (!xmllint.waitForStarted())
        QFAIL("xmllint is not installed (package libxml2-utils)");
    QVERIFY(xmllint.waitForFinished(60000));
    QVERIFY2(xmllint.exitStatus() == QProcess::NormalExit && xmllint.exitCode() == 0,
             xmllint.readAllStandardError().constData());

    // The exported file opens again as the same model.
    QVERIFY(m_window->openFile(path));
    QVERIFY(m_window->document()->model().sameContent(core::Model()));
    QCOMPARE(m_window->document()->fileFormat(), core::ModelFormat::PlcOpen);
}

void TestMainWindow::otherExportsWriteTheirFiles()
{
    const ExportActions& exports = *m_window->exportActions();
    QString error;

    const QString folder = m_files.filePath(QStringLiteral("st"));
    QVERIFY2(exports.writeStFolder(folder, core::Dialect::Iec, &error), qPrintable(error));
    QVERIFY(QFile::exists(folder + QStringLiteral("/GEMMA.st")));

    const QString single = m_files.filePath(QStringLiteral("gemma.st"));
    QVERIFY2(exports.writeStSingleFile(single, &error), qPrintable(error));
    QFile st(single);
    QVERIFY(st.open(QIODevice::ReadOnly));
    QVERIFY(st.readAll().contains("PROGRAM GEMMA"));

    const QString gg = m_files.filePath(QStringLiteral("gemma.gg.json"));
    QVERIFY2(exports.writeGGGenerator(gg, &error), qPrintable(error));
    const core::LoadedModel loaded = core::loadModelFile(QFile::encodeName(gg).toStdString());
    QVERIFY(loaded.ok());
    QCOMPARE(loaded.format, core::ModelFormat::GGGenerator);

    // A folder that cannot be created: refused with a reason.
    QVERIFY(!exports.writeStSingleFile(m_files.filePath(QStringLiteral("gemma.st/inside.st")), &error));
    QVERIFY(!error.isEmpty());
}

void TestMainWindow::exportWithErrorsAsksFirst()
{
    // The template's empty conditions are errors: the user is asked, and
    // closing the question cancels.
    const std::vector<core::Diagnostic>& diagnostics = m_window->document()->diagnostics();
    const auto errors = std::count_if(diagnostics.begin(), diagnostics.end(),
                                      [](const core::Diagnostic& d) { return d.severity == core::Severity::Error; });
    QVERIFY(errors > 6);
    MessageBoxCatcher catcher;
    catcher.arm();
    QVERIFY(!ExportActions::confirmErrors(m_window.get(), diagnostics));
    QVERIFY(catcher.seen);
    QVERIFY2(catcher.text.contains(QStringLiteral("has %1 errors").arg(errors)), qPrintable(catcher.text));
    // The first five, then how many more.
    QCOMPARE(catcher.informativeText.count(QChar(0x2022)), 5);
    QVERIFY2(catcher.informativeText.contains(QStringLiteral("and %1 more").arg(errors - 5)),
             qPrintable(catcher.informativeText));

    // No errors, no question.
    std::vector<core::Diagnostic> warningsOnly(1);
    warningsOnly[0].severity = core::Severity::Warning;
    QVERIFY(ExportActions::confirmErrors(m_window.get(), warningsOnly));
}

void TestMainWindow::ggGeneratorExportSaysWhatItLeavesOut()
{
    // The template loses nothing: no question.
    core::Model model;
    QVERIFY(ExportActions::ggGeneratorLossTexts(model).isEmpty());
    QVERIFY(ExportActions::confirmGGGeneratorLosses(m_window.get(), model));

    QVERIFY(model.addGrafcetStep("F1", {1, true, "", {}}));
    model.setEvolutionRule(core::EvolutionRule::UntilStable);
    const QStringList losses = ExportActions::ggGeneratorLossTexts(model);
    QCOMPARE(losses.size(), 2);
    QVERIFY2(losses[0].contains(QStringLiteral("nested GRAFCETs of F1")), qPrintable(losses[0]));
    QVERIFY2(losses[1].contains(QStringLiteral("until-stable")), qPrintable(losses[1]));

    // Closing the question cancels; Export Anyway goes on.
    MessageBoxCatcher cancel;
    cancel.arm();
    QVERIFY(!ExportActions::confirmGGGeneratorLosses(m_window.get(), model));
    QVERIFY(cancel.seen);
    QCOMPARE(cancel.informativeText.count(QChar(0x2022)), 2);
    MessageBoxCatcher goOn;
    goOn.button = QStringLiteral("&Export Anyway");
    goOn.arm();
    QVERIFY(ExportActions::confirmGGGeneratorLosses(m_window.get(), model));
    QVERIFY(goOn.seen);
}

void TestMainWindow::chartPicturesAreWritten()
{
    m_window->selection()->select(ElementRef::step(QStringLiteral("F1")));
    ChartExport chart(*m_window->chartScene());
    const struct {
        const char* name;
        QByteArray magic;
    } files[] = {{"chart.svg", "<?xml"}, {"chart.png", "\x89PNG"}, {"chart.pdf", "%PDF"}};
    for (const auto& file : files) {
        const QString path = m_files.filePath(QLatin1String(file.name));
        ChartExport::Format format;
        QVERIFY(ChartExport::formatForPath(path, &format));
        QString error;
        QVERIFY2(chart.write(path, format, &error), qPrintable(error));
        QFile written(path);
        QVERIFY(written.open(QIODevice::ReadOnly));
        QVERIFY2(written.read(8).startsWith(file.magic), file.name);
    }
    QImage png(m_files.filePath(QStringLiteral("chart.png")));
    QVERIFY(png.width() > 1000 && png.height() > 500);
    // The selection is left as it was.
    QCOMPARE(m_window->selection()->current(), ElementRef::step(QStringLiteral("F1")));
    QVERIFY(m_window->chartScene()->stepItem(QStringLiteral("F1"))->isSelected());

    ChartExport::Format format;
    QVERIFY(!ChartExport::formatForPath(QStringLiteral("chart.gif"), &format));
}

void TestMainWindow::saveOntoAFifoKeepsTheEditAndSaysWhy()
{
    const QString path = writeNativeFile(m_files, QStringLiteral("became-fifo.json"), namedModel("Fifo"));
    QVERIFY(m_window->openFile(path));
    Document& document = *m_window->document();
    QVERIFY(document.push(new SetStepHiddenCommand(document, QStringLiteral("A2"), true)));
    QVERIFY(QFile::remove(path));
    QCOMPARE(::mkfifo(localPath(path).constData(), 0644), 0);

    MessageBoxCatcher catcher;
    catcher.arm();
    m_window->findChild<QAction*>(QStringLiteral("saveAction"))->trigger();
    QVERIFY(catcher.seen);
    QVERIFY2(catcher.text.contains(QDir::toNativeSeparators(path)), qPrintable(catcher.text));
    QVERIFY2(catcher.text.contains(QStringLiteral("it is a named pipe (FIFO), not a regular file")),
             qPrintable(catcher.text));
    QVERIFY(isFifo(path));
    QVERIFY(document.isModified());
    QVERIFY(m_window->isWindowModified());
    QVERIFY(document.model().step("A2")->hidden);
    QCOMPARE(document.filePath(), path);
}

void TestMainWindow::exportsNeverReplaceAFifoOrADevice()
{
    const QString fifo = m_files.filePath(QStringLiteral("pipe"));
    QCOMPARE(::mkfifo(localPath(fifo).constData(), 0644), 0);
    const QString device = harmlessCharacterDevice(m_files);
    const QString deviceLink = m_files.filePath(QStringLiteral("device-link.xml"));
    QVERIFY(QFile::link(device, deviceLink));
    const ExportActions& exports = *m_window->exportActions();
    ChartExport chart(*m_window->chartScene());
    const std::vector<std::pair<const char*, std::function<bool(const QString&, QString*)>>> writers{
        {"PLCopen", [&](const QString& p, QString* e) { return exports.writePlcOpen(p, core::Dialect::Iec, e); }},
        {"ST file", [&](const QString& p, QString* e) { return exports.writeStSingleFile(p, e); }},
        {"ST folder", [&](const QString& p, QString* e) { return exports.writeStFolder(p, core::Dialect::Iec, e); }},
        {"GG-Generator", [&](const QString& p, QString* e) { return exports.writeGGGenerator(p, e); }},
        {"SVG", [&](const QString& p, QString* e) { return chart.write(p, ChartExport::Format::Svg, e); }},
        {"PNG", [&](const QString& p, QString* e) { return chart.write(p, ChartExport::Format::Png, e); }},
        {"PDF", [&](const QString& p, QString* e) { return chart.write(p, ChartExport::Format::Pdf, e); }},
    };
    for (const auto& [name, write] : writers) {
        QString error;
        QVERIFY2(!write(fifo, &error), name);
        QVERIFY2(error.contains(QStringLiteral("a named pipe (FIFO), not a")), qPrintable(name + (": " + error)));
        QVERIFY2(isFifo(fifo), name);
        QVERIFY2(!write(deviceLink, &error), name);
        QVERIFY2(error.contains(QStringLiteral("a character device, not a")), qPrintable(name + (": " + error)));
        QVERIFY2(isCharacterDevice(device), name);
    }
}

void TestMainWindow::autosaveNeverReplacesAFifo()
{
    discardRecoveries();
    Document document;
    Autosave autosave(document);
    QVERIFY(document.push(new SetStepHiddenCommand(document, QStringLiteral("A3"), true)));
    QVERIFY(autosave.writeNow()); // the session's copy and sidecar, locked
    const QString copy = autosave.recoveryPath();
    const QString sidecar = copy.chopped(int(QStringLiteral(".json").size())) + QStringLiteral(".info");
    const QStringList fifos{sidecar, copy};
    const QStringList steps{QStringLiteral("A4"), QStringLiteral("A5")};
    for (int i = 0; i < fifos.size(); ++i) {
        QVERIFY(QFile::remove(fifos[i]));
        QCOMPARE(::mkfifo(localPath(fifos[i]).constData(), 0644), 0);
        QVERIFY(document.push(new SetStepHiddenCommand(document, steps[i], true)));
        QVERIFY2(!autosave.writeNow(), qPrintable(fifos[i]));
        QVERIFY2(autosave.lastError().contains(QStringLiteral("it is a named pipe (FIFO), not a regular file")),
                 qPrintable(autosave.lastError()));
        QVERIFY(isFifo(fifos[i]));
        QVERIFY(QFile::remove(fifos[i]));
        QVERIFY(autosave.writeNow());
    }
    autosave.discard();
}

void TestMainWindow::unsavedChangesAskBeforeOpening()
{
    const QString other = writeNativeFile(m_files, QStringLiteral("other.json"), namedModel("Other"));
    Document& document = *m_window->document();
    QVERIFY(document.push(new SetStepHiddenCommand(document, QStringLiteral("A2"), true)));

    MessageBoxCatcher catcher; // closing the question is Cancel
    catcher.arm();
    QVERIFY(!m_window->openFile(other));
    QVERIFY(catcher.seen);
    QVERIFY(document.isModified());
    QVERIFY(document.model().step("A2")->hidden);
    QVERIFY(document.filePath().isEmpty());
}

void TestMainWindow::modelSettingsAreOneUndoStep()
{
    Document& document = *m_window->document();
    Settings settings;
    ModelSettingsDialog dialog(document, settings, m_window.get());
    dialog.findChild<QLineEdit*>(QStringLiteral("nameEdit"))->setText(QStringLiteral("Capper"));
    dialog.findChild<QSpinBox*>(QStringLiteral("cycleTimeSpin"))->setValue(10);
    auto* dialect = dialog.findChild<QComboBox*>(QStringLiteral("dialectCombo"));
    dialect->setCurrentIndex(dialect->findData(static_cast<int>(core::Dialect::Codesys)));
    dialog.accept();

    QCOMPARE(document.model().settings().name, std::string("Capper"));
    QCOMPARE(document.model().settings().cycleTimeMs, 10);
    QCOMPARE(document.model().settings().dialect, core::Dialect::Codesys);
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QVERIFY(document.model().sameContent(core::Model()));
    // Defaults for new models change only when asked.
    QCOMPARE(settings.defaultCycleTimeMs(), core::Model().settings().cycleTimeMs);
}

void TestMainWindow::modelSettingsOfferTheEvolutionRule()
{
    Document& document = *m_window->document();
    Settings settings;
    ModelSettingsDialog dialog(document, settings, m_window.get());
    auto* rule = dialog.findChild<QComboBox*>(QStringLiteral("evolutionCombo"));
    auto* description = dialog.findChild<QLabel*>(QStringLiteral("evolutionDescription"));
    QVERIFY(rule && description);
    QCOMPARE(rule->currentData().toInt(), static_cast<int>(core::EvolutionRule::OneEvolutionPerScan));
    QCOMPARE(description->text(),
        ModelSettingsDialog::evolutionRuleDescription(core::EvolutionRule::OneEvolutionPerScan));
    // The sentence follows the choice before anything is applied.
    rule->setCurrentIndex(rule->findData(static_cast<int>(core::EvolutionRule::UntilStable)));
    QCOMPARE(description->text(), ModelSettingsDialog::evolutionRuleDescription(core::EvolutionRule::UntilStable));
    QCOMPARE(document.model().settings().evolution, core::EvolutionRule::OneEvolutionPerScan);
    dialog.accept();

    QCOMPARE(document.model().settings().evolution, core::EvolutionRule::UntilStable);
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Set evolution rule to until stable"));
    document.undoStack()->undo();
    QCOMPARE(document.model().settings().evolution, core::EvolutionRule::OneEvolutionPerScan);

    // A dialog opened on the new rule starts on it.
    document.undoStack()->redo();
    ModelSettingsDialog again(document, settings, m_window.get());
    QCOMPARE(again.findChild<QComboBox*>(QStringLiteral("evolutionCombo"))->currentData().toInt(),
        static_cast<int>(core::EvolutionRule::UntilStable));
}

void TestMainWindow::layoutIsRestored()
{
    auto* problems = m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    m_window->addDockWidget(Qt::BottomDockWidgetArea, problems);
    m_window->resize(1000, 700);
    QVERIFY(m_window->close()); // unmodified: closes without asking, saves the layout

    MainWindow again(*m_translators);
    problems = again.findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    QCOMPARE(again.dockWidgetArea(problems), Qt::BottomDockWidgetArea);
    QCOMPARE(again.size(), QSize(1000, 700));
    QSettings().clear(); // the other tests start from the default layout
}

namespace {

QStringList tabsShownIn(const QWidget* window)
{
    QStringList tabs;
    // QMainWindow's tab bars of docks are its own children; one it does not
    // need it moves out of the window rather than hiding it.
    for (const QTabBar* bar : window->findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!bar->isVisible() || !window->rect().intersects(bar->geometry()))
            continue;
        for (int i = 0; i < bar->count(); ++i)
            tabs << bar->tabText(i);
    }
    tabs.sort();
    return tabs;
}

// The geometry of a widget when it is first painted, and the tabs its
// window shows then.
class FirstPaintGeometry : public QObject {
public:
    explicit FirstPaintGeometry(QWidget* widget)
        : m_widget(widget)
    {
        widget->installEventFilter(this);
    }
    QRect geometry;
    QStringList visibleTabs;
    QStringList visibleDocks;

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::Paint && geometry.isNull()) {
            geometry = m_widget->geometry();
            visibleTabs = tabsShownIn(m_widget->window());
            for (const QDockWidget* dock :
                 m_widget->window()->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
                if (dock->isVisible())
                    visibleDocks << dock->windowTitle();
            }
            visibleDocks.sort();
        }
        return false;
    }

private:
    QWidget* m_widget;
};

} // namespace

void TestMainWindow::deferredDocksFillInAfterTheFirstFrame()
{
    MainWindow window(*m_translators, MainWindow::DockContents::AfterFirstFrame);
    window.resize(1366, 768);
    QVERIFY(!window.docksReady());
    // The frames stand where the docks go, with their titles.
    auto* stepFrame = window.findChild<QDockWidget*>(QStringLiteral("stepDock"));
    QVERIFY(stepFrame);
    QCOMPARE(stepFrame->windowTitle(), QStringLiteral("Step"));
    QVERIFY(!window.findChild<StepDock*>());
    QSignalSpy shown(&window, &MainWindow::firstFrameShown);
    QSignalSpy ready(&window, &MainWindow::docksBecameReady);
    FirstPaintGeometry firstFrame(window.chartView()->viewport());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(ready.count() == 1 || ready.wait(5000));
    QCOMPARE(shown.count(), 1);
    QCOMPARE(ready.count(), 1);
    QVERIFY(window.docksReady());
    // The chart stays where the first frame drew it, which is where a start
    // with the docks built at once puts it.
    QApplication::processEvents();
    QVERIFY(!firstFrame.geometry.isNull());
    QCOMPARE(window.chartView()->viewport()->geometry(), firstFrame.geometry);
    QCOMPARE(window.chartView()->geometry(), m_window->chartView()->geometry());
    // The default layout's tab bars come with the docks: the first frame
    // showed the front frame of each group alone.
    QCOMPARE(firstFrame.visibleDocks, (QStringList{"Step", "Variables"}));
    QCOMPARE(firstFrame.visibleTabs, QStringList());
    // The nested docks wait for a GRAFCET tab in front (DockContext).
    QCOMPARE(tabsShownIn(&window),
             (QStringList{"Problems", "Simulation", "Step", "Structured Text", "Transition", "Variables"}));
    // The real docks, one of each, where the frames were, working.
    QCOMPARE(window.findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly).size(), 13);
    auto* stepDock = window.findChild<StepDock*>(QStringLiteral("stepDock"));
    QVERIFY(stepDock);
    QCOMPARE(window.dockWidgetArea(stepDock), Qt::RightDockWidgetArea);
    QCOMPARE(window.tabifiedDockWidgets(stepDock).size(), 8); // with the nested and the PackML docks
    window.selection()->select(ElementRef::step(QStringLiteral("F1")));
    auto* idLabel = stepDock->findChild<QLabel*>(QStringLiteral("idLabel"));
    QVERIFY(idLabel);
    QCOMPARE(idLabel->text(), QStringLiteral("F1"));
    // The View menu lists the real docks' actions, and only them.
    auto* viewMenu = window.findChild<QMenu*>(QStringLiteral("viewMenu"));
    QVERIFY(viewMenu->actions().contains(stepDock->toggleViewAction()));
    QCOMPARE(std::count_if(viewMenu->actions().cbegin(), viewMenu->actions().cend(),
                           [](QAction* action) { return action->text() == QStringLiteral("Step"); }),
             1);
}

// The frames take the saved layout, and the docks keep it: the chart does
// not move when they fill in.
void TestMainWindow::deferredDocksKeepTheSavedLayout()
{
    auto* problems = m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    m_window->addDockWidget(Qt::RightDockWidgetArea, problems);
    m_window->findChild<QDockWidget*>(QStringLiteral("stPreviewDock"))->raise();
    QVERIFY(m_window->close());

    MainWindow again(*m_translators, MainWindow::DockContents::AfterFirstFrame);
    QCOMPARE(again.dockWidgetArea(again.findChild<QDockWidget*>(QStringLiteral("problemsDock"))),
             Qt::RightDockWidgetArea);
    QSignalSpy ready(&again, &MainWindow::docksBecameReady);
    FirstPaintGeometry firstFrame(again.chartView()->viewport());
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QVERIFY(ready.count() == 1 || ready.wait(5000));
    QApplication::processEvents();
    QCOMPARE(again.dockWidgetArea(again.findChild<ProblemsDock*>(QStringLiteral("problemsDock"))),
             Qt::RightDockWidgetArea);
    QVERIFY(!firstFrame.geometry.isNull());
    QCOMPARE(again.chartView()->viewport()->geometry(), firstFrame.geometry);
    // The first frame showed the front frame of each group, as saved, and
    // no tab bar; the docks have them.
    QCOMPARE(firstFrame.visibleDocks, (QStringList{"Problems", "Step", "Structured Text"}));
    QCOMPARE(firstFrame.visibleTabs, QStringList());
    QCOMPARE(tabsShownIn(&again), (QStringList{"Simulation", "Step", "Structured Text", "Transition", "Variables"}));
    QVERIFY(!again.findChild<QDockWidget*>(QStringLiteral("stPreviewDock"))->visibleRegion().isEmpty());
    QVERIFY(again.findChild<QDockWidget*>(QStringLiteral("variablesDock"))->visibleRegion().isEmpty());
    QSettings().clear(); // the other tests start from the default layout
}

// Which docks were behind a tab is read from the screen: a window never
// shown records none, and a list that names a whole group (stale, or
// edited) still leaves the group a frame.
void TestMainWindow::framesTabbedBehindNeedTheScreenAndKeepAFrame()
{
    {
        MainWindow unseen(*m_translators);
        QVERIFY(unseen.close());
    }
    QVERIFY(QSettings().value(QStringLiteral("window/tabbedBehind")).toStringList().isEmpty());
    QSettings().setValue(QStringLiteral("window/tabbedBehind"),
                         QStringList{"stepDock", "transitionDock", "grafcetStepDock", "grafcetTransitionDock",
                                     "simulationDock", "variablesDock"});
    MainWindow window(*m_translators, MainWindow::DockContents::AfterFirstFrame);
    QStringList shown;
    for (const QDockWidget* frame : window.findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!frame->isHidden())
            shown << frame->objectName();
    }
    shown.sort();
    // The nested frames are hidden as the GEMMA chart is in front (DockContext).
    QCOMPARE(shown, (QStringList{"problemsDock", "simulationDock", "stPreviewDock", "stepDock", "transitionDock"}));
    QSettings().clear(); // the other tests start from the default layout
}

// Closed before its docks are built, the window saves their layout, not
// the frames'.
void TestMainWindow::deferredDocksSaveTheirLayoutWhenClosedEarly()
{
    {
        MainWindow early(*m_translators, MainWindow::DockContents::AfterFirstFrame);
        QVERIFY(!early.docksReady());
        QVERIFY(early.close());
    }
    MainWindow again(*m_translators);
    auto* problems = again.findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    QCOMPARE(again.dockWidgetArea(problems), Qt::RightDockWidgetArea);
    QCOMPARE(again.tabifiedDockWidgets(problems).size(), 3); // Variables, Structured Text, the closed Machine panel
    QCOMPARE(again.tabifiedDockWidgets(again.findChild<QDockWidget*>(QStringLiteral("stepDock"))).size(), 8);
    QSettings().clear(); // the other tests start from the default layout
}

// Whatever needs a dock before the first frame builds them at once.
void TestMainWindow::deferredDocksAreBuiltWhenNeeded()
{
    MainWindow window(*m_translators, MainWindow::DockContents::AfterFirstFrame);
    QVERIFY(!window.docksReady());
    window.simulationSession()->setActive(true);
    QVERIFY(window.docksReady());
    auto* simulation = window.findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(simulation);
    QVERIFY(!simulation->isHidden());
    // The editing lock holds for docks built while the simulation runs.
    QVERIFY(!window.findChild<StepDock*>(QStringLiteral("stepDock"))->widget()->isEnabled());
    window.simulationSession()->setActive(false);
    QVERIFY(window.findChild<StepDock*>(QStringLiteral("stepDock"))->widget()->isEnabled());
}

void TestMainWindow::recoveryIsOffered()
{
    discardRecoveries();
    const QString original = writeNativeFile(m_files, QStringLiteral("lost.json"), core::Model());
    {
        // A session that ends without saving its edit.
        Document document;
        QVERIFY(document.load(original, nullptr));
        Autosave autosave(document);
        QVERIFY(document.push(new SetStepHiddenCommand(document, QStringLiteral("A3"), true)));
        QVERIFY(autosave.writeNow());
    }
    QString lostCopy;
    {
        // Listing holds the copies until the list goes (another prompt would skip them).
        const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
        QCOMPARE(pending.size(), std::size_t(1));
        lostCopy = pending.front().recoveryPath;
    }

    MessageBoxCatcher catcher;
    catcher.button = QStringLiteral("&Recover");
    catcher.arm();
    m_window->offerRecovery();
    QVERIFY(catcher.seen);
    QVERIFY2(catcher.text.contains(QStringLiteral("lost.json")), qPrintable(catcher.text));
    const Document& document = *m_window->document();
    QVERIFY(document.model().step("A3")->hidden);
    QCOMPARE(document.filePath(), original);
    QVERIFY(m_window->isWindowModified()); // the user still has to save
    QCOMPARE(m_window->windowTitle(), QStringLiteral("lost.json[*] — GG Studio"));
    // The window's own autosave keeps the edit now, and nobody offers it while the window lives.
    QVERIFY(!QFile::exists(lostCopy));
    const QStringList copies = QDir(Autosave::recoveryDirectory()).entryList({QStringLiteral("*.json")}, QDir::Files);
    QCOMPARE(copies.size(), 1);
    QVERIFY(Autosave::pendingRecoveries().empty());

    m_window->document()->undoStack()->setClean(); // as if saved: the copy goes
    QVERIFY(QDir(Autosave::recoveryDirectory()).isEmpty());
}

void TestMainWindow::translatorLoadsFrench()
{
    for (const UiLanguage& language : availableLanguages()) {
        QTranslator translator;
        QVERIFY2(translator.load(QLocale(language.code), QStringLiteral("ggstudio"), QStringLiteral("_"),
                                 QStringLiteral(":/i18n")),
                 qPrintable(language.code));
    }
    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    QCOMPARE(m_translators->language(), QStringLiteral("fr"));
    QCoreApplication::processEvents();
    auto* french = m_window->findChild<QAction*>(QStringLiteral("language_fr"));
    QVERIFY(french);
    QVERIFY(french->isChecked());
    QVERIFY(!m_translators->setLanguage(QStringLiteral("xx")));
    QCOMPARE(m_translators->language(), QStringLiteral("en"));
}

void TestMainWindow::languageChangeRetranslatesMenus()
{
    auto* fileMenu = m_window->findChild<QMenu*>(QStringLiteral("fileMenu"));
    auto* openAction = m_window->findChild<QAction*>(QStringLiteral("openAction"));
    QVERIFY(fileMenu && openAction);
    QCOMPARE(fileMenu->title(), QStringLiteral("&File"));

    // The user moved the Problems dock to the left.
    auto* problems = m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    QVERIFY(problems);
    m_window->addDockWidget(Qt::LeftDockWidgetArea, problems);

    BracketTranslator translator;
    QCoreApplication::installTranslator(&translator);
    QCoreApplication::processEvents(); // LanguageChange is posted
    QCOMPARE(fileMenu->title(), QStringLiteral("[&File]"));
    QCOMPARE(openAction->text(), QStringLiteral("[&Open…]"));
    QCOMPARE(m_window->windowTitle(), QStringLiteral("[[Untitled][*] — GG Studio]"));
    // The docks follow, in the place the user left them.
    QTRY_COMPARE(m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"))->windowTitle(),
                 QStringLiteral("[Problems]"));
    problems = m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    QCOMPARE(m_window->dockWidgetArea(problems), Qt::LeftDockWidgetArea);
    auto* viewMenu = m_window->findChild<QMenu*>(QStringLiteral("viewMenu"));
    QVERIFY(viewMenu->actions().contains(problems->toggleViewAction()));
    QCOMPARE(m_window->findChildren<QDockWidget*>().size(), 13); // with the Simulation, nested GRAFCET, PackML and Machine docks

    QCoreApplication::removeTranslator(&translator);
    QCoreApplication::processEvents();
    QCOMPARE(fileMenu->title(), QStringLiteral("&File"));
    QTRY_COMPARE(m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"))->windowTitle(),
                 QStringLiteral("Problems"));
}

// Every text the docks and the status bar show, on every tab and page,
// follows a change of language: after the switch each one carries the bracket translator's
// brackets, unless it is not language at all (an element id, a type name, a
// number).
void TestMainWindow::languageChangeRetranslatesEveryWindowText_data()
{
    QTest::addColumn<ElementRef>("selected");
    QTest::addColumn<bool>("simulating");
    QTest::newRow("step") << ElementRef::step(QStringLiteral("F1")) << false;
    QTest::newRow("transition with a problem") << ElementRef::transition(QStringLiteral("F1->A2")) << false;
    QTest::newRow("simulating") << ElementRef::step(QStringLiteral("A6")) << true;
}

void TestMainWindow::languageChangeRetranslatesEveryWindowText()
{
    QFETCH(ElementRef, selected);
    QFETCH(bool, simulating);
    m_window->selection()->select(selected);
    if (simulating) {
        // The user's texts are shown as they are: a variable named like an
        // element, without a comment.
        core::Model model;
        model.addVariable(core::Variable{"S1", core::IecType::Bool, "", ""});
        m_window->document()->replaceModel(model, QString(), core::ModelFormat::Native);
        m_window->simulationSession()->setActive(true);
        m_window->simulationSession()->stepOnce();
    }
    BracketTranslator translator;
    QCoreApplication::installTranslator(&translator);
    QCoreApplication::processEvents();
    QTRY_COMPARE(m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"))->windowTitle(),
                 QStringLiteral("[Problems]"));

    const QStringList untranslated = untranslatedWindowTexts(*m_window);
    QCoreApplication::removeTranslator(&translator);
    m_window->simulationSession()->setActive(false);
    QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join(QLatin1Char('\n'))));
}

// The docks are reworded in place: what the user set in them stays.
void TestMainWindow::languageChangeKeepsWhatTheDocksShow()
{
    auto* filter = m_window->findChild<QLineEdit*>(QStringLiteral("filterEdit"));
    auto* table = m_window->findChild<QTableView*>(QStringLiteral("variablesView"));
    QVERIFY(filter && table);
    filter->setText(QStringLiteral("motor"));
    table->horizontalHeader()->resizeSection(0, 211);
    const QPointer<QLineEdit> sameFilter(filter);

    BracketTranslator translator;
    QCoreApplication::installTranslator(&translator);
    QCoreApplication::processEvents();
    QCOMPARE(m_window->findChild<QDockWidget*>(QStringLiteral("variablesDock"))->windowTitle(),
             QStringLiteral("[Variables]"));
    QVERIFY(sameFilter);
    QCOMPARE(filter->text(), QStringLiteral("motor"));
    QCOMPARE(filter->placeholderText(), QStringLiteral("[Filter]"));
    QCOMPARE(table->horizontalHeader()->sectionSize(0), 211);
    QCOMPARE(table->model()->headerData(0, Qt::Horizontal).toString(), QStringLiteral("[Name]"));
    QCoreApplication::removeTranslator(&translator);
    QCoreApplication::processEvents();
    QCOMPARE(filter->placeholderText(), QStringLiteral("Filter"));
}

void TestMainWindow::frenchMenuTitles()
{
    QTranslator french;
    QVERIFY(french.load(QLocale(QStringLiteral("fr")), QStringLiteral("ggstudio"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")));
    const QString expected = french.translate("editor::MainWindow", "&File");
    if (expected.isEmpty())
        QSKIP("The French translation of the menus is not written yet (translations/ggstudio_fr.ts)");

    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    QCoreApplication::processEvents();
    auto* fileMenu = m_window->findChild<QMenu*>(QStringLiteral("fileMenu"));
    QVERIFY(fileMenu);
    QCOMPARE(fileMenu->title(), expected);
}

namespace {

// A style that counts the standard icons asked of it.
class CountingStyle : public QCommonStyle {
public:
    QIcon standardIcon(StandardPixmap standardIcon, const QStyleOption* option,
                       const QWidget* widget) const override
    {
        ++calls;
        return QCommonStyle::standardIcon(standardIcon, option, widget);
    }

    mutable int calls = 0;
};

} // namespace

void TestMainWindow::windowButtonsAreDrawn()
{
    auto* counting = new CountingStyle;
    const WindowButtonStyle style(counting); // owns `counting`
    for (const QStyle::StandardPixmap glyph :
         {QStyle::SP_TitleBarCloseButton, QStyle::SP_DockWidgetCloseButton, QStyle::SP_TitleBarNormalButton,
          QStyle::SP_ToolBarHorizontalExtensionButton, QStyle::SP_ToolBarVerticalExtensionButton,
          QStyle::SP_LineEditClearButton, QStyle::SP_MediaPlay, QStyle::SP_MediaPause, QStyle::SP_MediaSkipForward,
          QStyle::SP_MediaSkipBackward, QStyle::SP_MediaStop}) {
        const QImage image = style.standardIcon(glyph).pixmap(QSize(32, 32)).toImage();
        QCOMPARE(image.size(), QSize(32, 32));
        QCOMPARE(qAlpha(image.pixel(0, 0)), 0); // drawn on transparency
        int inked = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x)
                inked += qAlpha(image.pixel(x, y)) > 128 ? 1 : 0;
        }
        QVERIFY2(inked > 20, qPrintable(QString::number(glyph)));
    }
    QCOMPARE(counting->calls, 0); // none of them asked of the base style

    style.standardIcon(QStyle::SP_MessageBoxWarning);
    QCOMPARE(counting->calls, 1); // everything else is the base style's
}

void TestMainWindow::windowButtonStyleWrapsQtsOwnStyles()
{
    QVERIFY(WindowButtonStyle::appliesTo(QStringLiteral("fusion")));
    QVERIFY(WindowButtonStyle::appliesTo(QStringLiteral("Windows")));
    QVERIFY(!WindowButtonStyle::appliesTo(QStringLiteral("breeze")));

    m_window.reset();
    const QString chosen = QApplication::style()->name();
    QVERIFY(WindowButtonStyle::appliesTo(chosen)); // offscreen runs Fusion
    WindowButtonStyle::install();
    auto* installed = qobject_cast<WindowButtonStyle*>(QApplication::style());
    QVERIFY(installed);
    QCOMPARE(installed->baseStyle()->name(), chosen);

    // A window built under it: its docks' title buttons show the drawn glyphs.
    m_window = std::make_unique<MainWindow>(*m_translators);
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("stepDock"));
    QVERIFY(dock);
    auto* close = dock->findChild<QAbstractButton*>(QStringLiteral("qt_dockwidget_closebutton"));
    QVERIFY(close);
    const QImage shown = close->icon().pixmap(QSize(16, 16)).toImage();
    const QImage drawn = installed->standardIcon(QStyle::SP_TitleBarCloseButton).pixmap(QSize(16, 16)).toImage();
    QCOMPARE(shown, drawn);

    // Laid out while hidden, the docks were placed at once: no geometry
    // animation was made for them. On screen, moved docks animate.
    QCOMPARE(m_window->findChildren<QPropertyAnimation*>().size(), 0);
    QCOMPARE(installed->styleHint(QStyle::SH_Widget_Animation_Duration, nullptr, dock), 0);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    const int baseDuration = installed->baseStyle()->styleHint(QStyle::SH_Widget_Animation_Duration, nullptr, dock);
    QVERIFY(baseDuration > 0);
    QCOMPARE(installed->styleHint(QStyle::SH_Widget_Animation_Duration, nullptr, dock), baseDuration);
}

QTEST_MAIN(TestMainWindow)
#include "test_mainwindow.moc"
