#include "editor/mainwindow.h"

#include "editor/app/autosave.h"
#include "editor/app/examplemodels.h"
#include "editor/app/languages.h"
#include "editor/app/recentfiles.h"
#include "editor/app/recoveryprompt.h"
#include "editor/app/settings.h"
#include "editor/app/userguide.h"
#include "editor/chart/gemma/chartcontextmenu.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/chart/packml/packmlchartbinding.h"
#include "editor/chart/packml/packmlchartcontextmenu.h"
#include "editor/chart/packml/packmlsheetview.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/commands/resetmodelcommand.h"
#include "editor/commands/setelementshiddencommand.h"
#include "editor/commands/undohistorywording.h"
#include "editor/docks/gemma/startguide.h"
#include "editor/docks/gemma/stepdock.h"
#include "editor/docks/gemma/transitiondock.h"
#include "editor/docks/grafcetstepdock.h"
#include "editor/docks/packml/packmlcommandsdock.h"
#include "editor/docks/packml/packmlmodesdock.h"
#include "editor/docks/packml/packmlstatedock.h"
#include "editor/docks/grafcettransitiondock.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/stpreviewdock.h"
#include "editor/docks/variablesdock.h"
#include "editor/docks/verificationpanel.h"
#include "editor/document.h"
#include "editor/export/exportactions.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetkeyboard.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetselectionsync.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/nestedgrafcetavailable.h"
#include "editor/selection.h"
#include "editor/simulation/grafcetsimulationmarks.h"
#include "editor/simulation/packml/packmlgrafcetmarks.h"
#include "editor/simulation/packml/packmlsimulationdock.h"
#include "editor/simulation/packml/packmlsimulationmarks.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/modbusconnectdialog.h"
#include "editor/simulation/modbusconnection.h"
#include "editor/simulation/simulationchartmarks.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"
#include "editor/text/gemmastatenames.h"
#include "editor/verificationrunner.h"
#include "editor/window/dockcontext.h"
#include "editor/window/frontzoom.h"
#include "editor/window/grafcettabs.h"
#include "editor/machine/machinetab.h"
#include "editor/docks/machinedock.h"
#include "editor/window/modelsettingsdialog.h"
#include "editor/window/newmodeldialog.h"
#include "editor/window/statusindicators.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QShortcut>
#include <QStyle>
#include <QChildEvent>
#include <QTabBar>
#include <QTabWidget>
#include <QToolBar>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QUndoStack>

#include <algorithm>
#include <map>
#include <utility>

namespace editor {

namespace {

constexpr int kStatusMessageMs = 6000;
// How long closing the window waits for a cancelled verification to end.
constexpr int kQuitWaitMs = 2000;

// What the window starts on: the GEMMA template with the user's default settings.
core::Model newTemplate(const Settings& settings)
{
    return NewModelDialog::newModel(NewModelDialog::Choice::Gemma, settings);
}

// The window's first size: most of the screen, but no wider than a chart
// and its docks need. The size is the window's inside: the title bar and
// frame the window manager adds (unknown before the window is shown) must
// fit too, so some room is left for them (kFrameAllowance, enough for the
// title bars of GNOME, KDE and Xfce).
constexpr QSize kFrameAllowance(16, 48);

QSize defaultWindowSize(const QWidget* window)
{
    const QScreen* screen = window->screen() ? window->screen() : QGuiApplication::primaryScreen();
    const QSize available = (screen ? screen->availableSize() : QSize(1366, 768)) - kFrameAllowance;
    return QSize(std::min(available.width(), 1600), std::min(available.height(), 1000));
}

} // namespace

MainWindow::MainWindow(Translators& translators, DockContents contents, QWidget* parent)
    : QMainWindow(parent)
    , m_translators(translators)
    , m_settings(std::make_unique<Settings>())
    , m_document(new Document(newTemplate(*m_settings), this))
    , m_selection(new Selection(this))
    , m_autosave(new Autosave(*m_document, m_document))
    , m_scene(new ChartScene(m_document, m_selection, this))
    , m_view(new ChartView(m_scene, this))
    , m_centralTabs(new QTabWidget(this))
    , m_packmlScene(new PackmlChartScene(&m_document->model(), m_selection, this))
    , m_packmlView(new PackmlChartView(m_packmlScene, this))
    , m_packmlBinding(new PackmlChartBinding(m_document, m_packmlView, this))
    , m_grafcetTabs(new GrafcetTabs(m_centralTabs, m_document, m_selection, m_settings.get(), this))
{
    setObjectName("mainWindow");
    // The window icon is the application's: editor::runApplication sets it
    // once, after the first frame.
    m_view->setObjectName("chartView");
    // The tab bar shows once a nested GRAFCET is open: until then the chart
    // has the whole area.
    m_centralTabs->setObjectName("centralTabs");
    m_centralTabs->setDocumentMode(true);
    m_centralTabs->setTabBarAutoHide(true);
    m_centralTabs->setTabsClosable(true);
    m_packmlView->setObjectName("packmlChartView");
    m_packmlView->hide();
    installChartTab(m_view);
    connect(m_centralTabs, &QTabWidget::tabCloseRequested, m_grafcetTabs, &GrafcetTabs::close);
    connect(m_centralTabs, &QTabWidget::currentChanged, m_grafcetTabs, &GrafcetTabs::remember);
    connect(m_packmlBinding, &PackmlChartBinding::openGrafcetRequested, this, &MainWindow::openNestedGrafcet);
    connect(m_grafcetTabs, &GrafcetTabs::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
    connect(m_grafcetTabs, &GrafcetTabs::viewOpened, this, [this](GrafcetView* view) {
        if (!isPackml())
            new GrafcetSimulationMarks(m_session, view->grafcetScene(), view->grafcetScene());
        else
            addPackmlGrafcetMarks(m_packmlSession, view->grafcetScene(), view->grafcetScene());
    });
    connect(m_centralTabs, &QTabWidget::currentChanged, this, &MainWindow::onCentralTabChanged);
    connect(m_centralTabs, &QTabWidget::currentChanged, this, &MainWindow::followTabInFront);
    connect(m_selection, &Selection::changed, this, &MainWindow::onSelectionChanged);
    setCentralWidget(m_centralTabs);

    // The right column runs the full height: the property docks are tall forms.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
    m_session = new SimulationSession(m_document, this);
    m_modbus = new ModbusConnection(m_session, this);
    m_chartMarks = new SimulationChartMarks(m_session, m_scene, this);
    m_machineTab = new MachineTab(m_centralTabs, m_document, m_session, this);
    m_packmlSession = new PackmlSimulationSession(m_document, this);
    m_packmlChartMarks = new PackmlSimulationMarks(m_packmlSession, m_packmlScene, this);
    m_verification = new VerificationRunner(m_document, m_session, this);
    m_dockContext = new DockContext(this);
    m_dockContext->setClosedDocks(m_settings->closedDocks());
    if (contents == DockContents::Immediate) {
        createDocks();
    } else {
        createDockFrames();
        m_firstFrameWatched = m_view->viewport();
        m_firstFrameWatched->installEventFilter(this);
    }
    createActions();
    createToolBar();
    createMenus();
    createStatusBar();
    retranslate();
    onSimulationActiveChanged(m_session->isActive());

    connect(m_document, &Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document, &Document::filePathChanged, m_grafcetTabs, &GrafcetTabs::remember); // Save As
    connect(m_document, &Document::modelReplaced, this, &MainWindow::applyTemplate);
    connect(m_document, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &Document::editFailed, this, &MainWindow::showEditFailure);
    connect(m_session, &SimulationSession::activeChanged, this, &MainWindow::onSimulationActiveChanged);
    connect(m_packmlSession, &PackmlSimulationSession::activeChanged, this, &MainWindow::onSimulationActiveChanged);
    connect(m_session, &SimulationSession::replayChanged, this, &MainWindow::onReplayChanged);
    connect(m_verification, &VerificationRunner::started, this, &MainWindow::showVerificationStatus);
    connect(m_verification, &VerificationRunner::finished, this, &MainWindow::showVerificationStatus);
    connect(m_verification, &VerificationRunner::cancelled, this, &MainWindow::showVerificationStatus);
    connect(m_autosave, &Autosave::writeFailed, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Autosave failed: %1").arg(message), kStatusMessageMs);
    });

    // The document already holds the template newModel() would load.
    updateTitle();
    m_showHiddenAction->setChecked(m_settings->showHidden());
    restoreLayout();
}

MainWindow::~MainWindow()
{
    // Everything that shows the document goes before it, and the window
    // hears none of the signals the document sends as it goes, nor the
    // events of a chart that was never painted.
    stopWatchingFirstFrame();
    m_document->undoStack()->disconnect(this);
    m_document->disconnect(this);
    m_session->disconnect(this);
    m_packmlSession->disconnect(this);
    m_verification->disconnect(this);
    m_centralTabs->disconnect(this); // its tabs go with it: not the user's closing them
    m_centralTabs->disconnect(m_grafcetTabs);
    delete m_frontZoom;               // which follows the tab in front
    delete m_chartMarks;
    delete m_machineTab; // its view, which shows the document and the session
    delete m_packmlChartMarks;
    delete m_problemCounter;
    deleteDocks();
    delete m_view;
    delete m_scene;
}

QList<QDockWidget*> MainWindow::docks() const
{
    if (!m_dockFrames.isEmpty())
        return m_dockFrames;
    return {m_stepDock,           m_transitionDock,     m_packmlStateDock, m_packmlCommandsDock,
            m_packmlModesDock,    m_grafcetStepDock,    m_grafcetTransitionDock,
            m_simulationDock,     m_packmlSimulationDock, m_variablesDock,  m_problemsDock, m_stPreviewDock};
}

QDockWidget* MainWindow::dockNamed(const QString& objectName) const
{
    return findChild<QDockWidget*>(objectName, Qt::FindDirectChildrenOnly);
}

void MainWindow::createDocks()
{
    m_stepDock = new StepDock(m_document, m_selection, this);
    m_transitionDock = new TransitionDock(m_document, m_selection, this);
    m_packmlStateDock = new PackmlStateDock(m_document, m_selection, this);
    m_packmlCommandsDock = new PackmlCommandsDock(m_document, m_selection, this);
    m_packmlModesDock = new PackmlModesDock(m_document, m_selection, this);
    connect(m_packmlStateDock, &PackmlStateDock::openGrafcetRequested, this, &MainWindow::openNestedGrafcet);
    m_grafcetStepDock = new GrafcetStepDock(m_document, m_selection, this);
    m_grafcetTransitionDock = new GrafcetTransitionDock(m_document, m_selection, this);
    m_variablesDock = new VariablesDock(m_document, m_selection, this);
    m_problemsDock = new ProblemsDock(m_document, m_selection, m_verification, this);
    connect(m_problemsDock->verificationPanel(), &VerificationPanel::replayRequested, this,
            &MainWindow::replayCounterexample);
    connect(m_stepDock->startGuide(), &StartGuide::exampleRequested, this, [this] { openExample(0); });
    connect(m_stepDock->startGuide(), &StartGuide::userGuideRequested, this, &MainWindow::showUserGuide);
    connect(m_stepDock, &StepDock::openGrafcetRequested, this, &MainWindow::openNestedGrafcet);
    m_stPreviewDock = new StPreviewDock(m_document, m_selection, this);
    onCentralTabChanged();
    m_simulationDock = new SimulationDock(m_session, m_document, this);
    m_packmlSimulationDock = new PackmlSimulationDock(m_packmlSession, m_document, this);
    arrangeDocks(docks());
    for (QDockWidget* dock : docks())
        m_dockContext->watch(dock);
    // The Machine panel opens from View > Machine, beside Variables: closed
    // by default, so the default layout stays the one the column is sized for.
    m_machineDock = new MachineDock(m_document, this);
    m_machineDock->hide();
    tabifyDockWidget(m_variablesDock, m_machineDock);
    followTabInFront();
    // Esc in a property dock goes back to the chart or GRAFCET in front (Enter or F2 there came in).
    for (PropertyDock* dock : std::initializer_list<PropertyDock*>{m_stepDock, m_transitionDock, m_grafcetStepDock,
                                                                  m_grafcetTransitionDock}) {
        const auto goBack = [this] { m_centralTabs->currentWidget()->setFocus(Qt::ShortcutFocusReason); };
        auto* back = new QShortcut(QKeySequence(Qt::Key_Escape), dock, goBack);
        back->setContext(Qt::WidgetWithChildrenShortcut);
        connect(dock, &PropertyDock::leaveRequested, this, goBack);
    }
}

namespace {

// The docks by object name, in the order of MainWindow::docks(), with their
// titles and where the default layout puts them. The GEMMA sheet is wider
// than high, but less so than a screen: a dock below the chart takes height
// the fitted chart needs, while the side has width to spare. So every dock
// goes in one column on the right: Step, Transition and Simulation tabbed
// above, Variables, Problems and Structured Text tabbed below, each group
// with its first dock in front.
enum class DockGroup { Upper, Lower };
struct DockPlace {
    const char* name;
    QString (*title)();
    DockGroup group;
};
constexpr DockPlace kDockPlaces[] = {
    {"stepDock", &StepDock::title, DockGroup::Upper},
    {"transitionDock", &TransitionDock::title, DockGroup::Upper},
    {"packmlStateDock", &PackmlStateDock::title, DockGroup::Upper},
    {"packmlCommandsDock", &PackmlCommandsDock::title, DockGroup::Upper},
    {"packmlModesDock", &PackmlModesDock::title, DockGroup::Upper},
    {"grafcetStepDock", &GrafcetStepDock::title, DockGroup::Upper},
    {"grafcetTransitionDock", &GrafcetTransitionDock::title, DockGroup::Upper},
    {"simulationDock", &SimulationDock::title, DockGroup::Upper},
    {"packmlSimulationDock", &PackmlSimulationDock::title, DockGroup::Upper},
    {"variablesDock", &VariablesDock::title, DockGroup::Lower},
    {"problemsDock", &ProblemsDock::title, DockGroup::Lower},
    {"stPreviewDock", &StPreviewDock::title, DockGroup::Lower},
};

DockGroup defaultGroup(const QDockWidget* dock)
{
    for (const DockPlace& place : kDockPlaces) {
        if (dock->objectName() == QLatin1String(place.name))
            return place.group;
    }
    return DockGroup::Upper;
}

// The first dock of its group in the default layout.
bool isDefaultFront(const DockPlace& place)
{
    return &place == std::find_if(std::cbegin(kDockPlaces), std::cend(kDockPlaces),
                                  [&place](const DockPlace& candidate) { return candidate.group == place.group; });
}

} // namespace

// Empty docks with the real ones' titles and names, so that the window has
// its final layout (and restores the saved one) from the first frame. A tab
// group stands as its front frame alone, and its tab bar comes with the
// docks: building, laying out and painting two tab bars and their six tabs
// was 6 M instructions of the first frame, a seventh of the start-up's own
// work. The default layout gets only the front frames. A saved layout gets
// every frame, because Qt keeps a saved layout's sizes only when the docks
// it names are there; those it had behind a tab are hidden once restored
// (hideFramesTabbedBehind), which spares the tab bars' layout and painting
// but not their building.
void MainWindow::createDockFrames()
{
    const bool frontsOnly = m_settings->windowState().isEmpty();
    for (const DockPlace& place : kDockPlaces) {
        if (frontsOnly && !isDefaultFront(place))
            continue;
        auto* frame = new QDockWidget(place.title(), this);
        frame->setObjectName(QLatin1String(place.name));
        m_dockFrames << frame;
    }
    arrangeDocks(m_dockFrames);
    for (QDockWidget* frame : std::as_const(m_dockFrames))
        m_dockContext->watch(frame);
}

// The docks of each group tabbed behind its first, the lower group's front
// split below the upper one's (`docks` in the order of docks(); the frames
// may be fewer). The fronts are split before anything is tabbed: Qt adds a
// dock split from a tabbed one as one more tab.
void MainWindow::arrangeDocks(const QList<QDockWidget*>& docks)
{
    std::map<DockGroup, QDockWidget*> fronts;
    for (QDockWidget* dock : docks)
        fronts.try_emplace(defaultGroup(dock), dock);
    const auto upper = fronts.find(DockGroup::Upper);
    for (const auto& [group, front] : fronts) {
        addDockWidget(Qt::RightDockWidgetArea, front);
        if (group == DockGroup::Lower && upper != fronts.end())
            splitDockWidget(upper->second, front, Qt::Vertical);
    }
    for (QDockWidget* dock : docks) {
        QDockWidget* front = fronts.at(defaultGroup(dock));
        if (dock != front)
            tabifyDockWidget(front, dock);
    }
    for (const auto& [group, front] : fronts)
        front->raise();
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_firstFrameWatched && event->type() == QEvent::Paint) {
        stopWatchingFirstFrame();
        // After this paint is on screen, not within it.
        QMetaObject::invokeMethod(this, &MainWindow::ensureDocksReady, Qt::QueuedConnection);
        emit firstFrameShown();
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::childEvent(QChildEvent* event)
{
    // Polished once QMainWindow has set the bar up (it elides by default).
    if (event->type() == QEvent::ChildPolished) {
        if (auto* bar = qobject_cast<QTabBar*>(event->child())) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
        }
    }
    QMainWindow::childEvent(event);
}

void MainWindow::stopWatchingFirstFrame()
{
    if (m_firstFrameWatched)
        m_firstFrameWatched->removeEventFilter(this);
    m_firstFrameWatched = nullptr;
}

void MainWindow::ensureDocksReady()
{
    if (!docksReady())
        replaceDockFrames();
}

void MainWindow::deleteDocks()
{
    for (QDockWidget* dock : docks()) {
        m_dockContext->unwatch(dock);
        removeDockWidget(dock);
        delete dock;
    }
    m_stepDock = nullptr;
    m_transitionDock = nullptr;
    m_packmlStateDock = nullptr;
    m_packmlCommandsDock = nullptr;
    m_packmlModesDock = nullptr;
    m_grafcetStepDock = nullptr;
    m_grafcetTransitionDock = nullptr;
    m_variablesDock = nullptr;
    m_problemsDock = nullptr;
    m_stPreviewDock = nullptr;
    if (m_machineDock) {
        removeDockWidget(m_machineDock);
        delete m_machineDock;
    }
    m_machineDock = nullptr;
    m_simulationDock = nullptr;
    m_packmlSimulationDock = nullptr;
    m_dockFrames.clear();
}

// The empty frames of a deferred start give way to the docks, in the saved
// layout, or in the default one at the size the frames have.
void MainWindow::replaceDockFrames()
{
    const QByteArray savedLayout = std::exchange(m_framesLayout, {});
    const QDockWidget* stepFrame = dockNamed(QStringLiteral("stepDock"));
    const QDockWidget* variablesFrame = dockNamed(QStringLiteral("variablesDock"));
    const int columnWidth = stepFrame ? stepFrame->width() : 0;
    const int lowerHeight = variablesFrame ? variablesFrame->height() : 0;
    for (QDockWidget* dock : docks())
        m_viewMenu->removeAction(dock->toggleViewAction());
    deleteDocks();
    createDocks();
    bool restored = false;
    m_dockContext->untracked([&] { restored = !savedLayout.isEmpty() && restoreState(savedLayout); });
    if (!restored) {
        resizeDocks({m_stepDock}, {columnWidth}, Qt::Horizontal);
        resizeDocks({m_variablesDock}, {lowerHeight}, Qt::Vertical);
    }
    m_dockContext->apply();
    applyEditingLock();
    m_viewMenu->insertActions(m_dockActionsEnd, toggleViewActions());
    emit docksBecameReady();
}

QList<QAction*> MainWindow::toggleViewActions() const
{
    QList<QAction*> actions;
    for (QDockWidget* dock : docks())
        actions << dock->toggleViewAction();
    if (m_machineDock && m_dockFrames.isEmpty())
        actions << m_machineDock->toggleViewAction();
    return actions;
}

void MainWindow::createActions()
{
    auto action = [this](const char* name, auto slot, const QKeySequence& shortcut = {}) {
        auto* a = new QAction(this);
        a->setObjectName(QLatin1String(name));
        a->setShortcut(shortcut);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    m_newAction = action("newAction", &MainWindow::newModel, QKeySequence::New);
    m_openAction = action("openAction", &MainWindow::open, QKeySequence::Open);
    m_saveAction = action("saveAction", &MainWindow::save, QKeySequence::Save);
    // QKeySequence::SaveAs is empty on some desktops; Ctrl+Shift+S everywhere.
    m_saveAsAction = action("saveAsAction", &MainWindow::saveAs, Qt::CTRL | Qt::SHIFT | Qt::Key_S);
    m_resetAction = action("resetAction", &MainWindow::resetToTemplate);
    m_quitAction = action("quitAction", &QWidget::close, QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);

    QUndoStack* stack = m_document->undoStack();
    m_undoAction = action("undoAction", [stack] { stack->undo(); }, QKeySequence::Undo);
    m_redoAction = action("redoAction", [stack] { stack->redo(); }, QKeySequence::Redo);
    m_undoAction->setEnabled(stack->canUndo());
    m_redoAction->setEnabled(stack->canRedo());
    connect(stack, &QUndoStack::canUndoChanged, this,
            [this](bool can) { m_undoAction->setEnabled(can && !isSimulating()); });
    connect(stack, &QUndoStack::canRedoChanged, this,
            [this](bool can) { m_redoAction->setEnabled(can && !isSimulating()); });
    // Every keystroke in a text field changes them: only the two actions follow.
    connect(stack, &QUndoStack::undoTextChanged, this, &MainWindow::retitleUndoRedo);
    connect(stack, &QUndoStack::redoTextChanged, this, &MainWindow::retitleUndoRedo);
    m_modelSettingsAction = action("modelSettingsAction", &MainWindow::editModelSettings);
    m_resetLayoutAction = action("resetLayoutAction", &MainWindow::resetLayout);
    // Nothing of the fixed template is deleted: Delete hides. Only while the
    // chart has the focus, so Delete keeps its meaning in text fields and tables.
    m_hideSelectionAction = action("hideSelectionAction", [this] { setSelectionHidden(true); }, QKeySequence::Delete);
    m_hideSelectionAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_view->addAction(m_hideSelectionAction);
    m_showSelectionAction = action("showSelectionAction", [this] { setSelectionHidden(false); },
                                   Qt::SHIFT | Qt::Key_Delete);
    m_showSelectionAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_view->addAction(m_showSelectionAction);

    m_showHiddenAction = new QAction(this);
    m_showHiddenAction->setObjectName("showHiddenAction");
    m_showHiddenAction->setShortcut(Qt::CTRL | Qt::Key_H);
    m_showHiddenAction->setCheckable(true);
    connect(m_showHiddenAction, &QAction::toggled, this, &MainWindow::setShowHidden);
    // On the tab in front (FrontZoom, made with the status bar).
    m_fitAction = action("fitAction", [this] { m_frontZoom->zoomToFit(); }, Qt::CTRL | Qt::Key_0);
    m_actualSizeAction = action("actualSizeAction", [this] { m_frontZoom->zoomToActualSize(); }, Qt::CTRL | Qt::Key_1);
    m_zoomInAction = action("zoomInAction", [this] { m_frontZoom->zoomIn(); }, QKeySequence::ZoomIn);
    m_zoomOutAction = action("zoomOutAction", [this] { m_frontZoom->zoomOut(); }, QKeySequence::ZoomOut);

    m_simulateAction = new QAction(this);
    m_simulateAction->setObjectName("simulateAction");
    m_simulateAction->setShortcut(Qt::Key_F5);
    m_simulateAction->setCheckable(true);
    connect(m_simulateAction, &QAction::toggled, this, [this](bool active) {
        if (isPackml())
            m_packmlSession->setActive(active);
        else
            m_session->setActive(active);
    });
    m_runAction = new QAction(this);
    m_runAction->setObjectName("runSimulationAction");
    m_runAction->setShortcut(Qt::Key_F6);
    m_runAction->setCheckable(true);
    connect(m_runAction, &QAction::toggled, this, [this](bool run) {
        if (isPackml())
            run ? m_packmlSession->run() : m_packmlSession->pause();
        else
            run ? m_session->run() : m_session->pause();
    });
    const auto showRunning = [this](bool running) {
        const QSignalBlocker blocker(m_runAction);
        m_runAction->setChecked(running);
    };
    connect(m_session, &SimulationSession::runningChanged, this, showRunning);
    connect(m_packmlSession, &PackmlSimulationSession::runningChanged, this, showRunning);
    m_scanAction = action("singleScanAction", [this] { isPackml() ? m_packmlSession->stepOnce() : m_session->stepOnce(); },
                          SimulationDock::singleScanShortcut());
    m_resetSimulationAction =
        action("resetSimulationAction", [this] { isPackml() ? m_packmlSession->reset() : m_session->reset(); });
    m_connectAction = action("modbusConnectAction", &MainWindow::connectModbus);
    m_disconnectAction = action("modbusDisconnectAction", [this] { m_modbus->disconnectLink(); });
    m_disconnectAction->setEnabled(false);
    connect(m_modbus, &ModbusConnection::connectedChanged, m_disconnectAction, &QAction::setEnabled);
    // While linked the link's clock runs the scans: Run waits.
    connect(m_modbus, &ModbusConnection::connectedChanged, this,
            [this](bool connected) { m_runAction->setEnabled(!connected && m_session->isActive()); });
    connect(m_modbus, &ModbusConnection::statusChanged, this, [this] {
        if (m_simulationDock)
            m_simulationDock->setLinkStatus(m_modbus->statusText());
    });
    m_stepBackAction = action("stepBackAction", [this] { isPackml() ? m_packmlSession->stepBack() : m_session->stepBack(); },
                              SimulationDock::stepBackShortcut());
    m_stepForwardAction = action("stepForwardAction",
                                 [this] { isPackml() ? m_packmlSession->stepForward() : m_session->stepForward(); },
                                 SimulationDock::stepForwardShortcut());
    connect(m_session, &SimulationSession::stepped, this, &MainWindow::updateHistoryActions);
    connect(m_session, &SimulationSession::historyMoved, this, &MainWindow::updateHistoryActions);
    connect(m_session, &SimulationSession::activeChanged, this, &MainWindow::updateHistoryActions);
    connect(m_packmlSession, &PackmlSimulationSession::stepped, this, &MainWindow::updateHistoryActions);
    connect(m_packmlSession, &PackmlSimulationSession::historyMoved, this, &MainWindow::updateHistoryActions);
    connect(m_packmlSession, &PackmlSimulationSession::activeChanged, this, &MainWindow::updateHistoryActions);
    m_verifyAction = action("verifyAction", &MainWindow::verify, Qt::Key_F7);
    m_verifyAction->setShortcuts({QKeySequence(Qt::Key_F7), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_V)});
    m_exactTimeAction = new QAction(this);
    m_exactTimeAction->setObjectName(QStringLiteral("verifyExactTimeAction"));
    m_exactTimeAction->setCheckable(true);
    connect(m_exactTimeAction, &QAction::toggled, this, [this](bool exact) { m_verification->setExactTime(exact); });
    // Closed loop: offered while the model has a machine (a GEMMA model's only).
    m_withMachineAction = new QAction(this);
    m_withMachineAction->setObjectName(QStringLiteral("verifyWithMachineAction"));
    m_withMachineAction->setCheckable(true);
    connect(m_withMachineAction, &QAction::toggled, this,
            [this](bool withMachine) { m_verification->setWithMachine(withMachine); });
    // Single faults: offered only while verifying with the machine.
    m_singleFaultsAction = new QAction(this);
    m_singleFaultsAction->setObjectName(QStringLiteral("verifySingleFaultsAction"));
    m_singleFaultsAction->setCheckable(true);
    m_singleFaultsAction->setEnabled(false);
    connect(m_singleFaultsAction, &QAction::toggled, this,
            [this](bool singleFaults) { m_verification->setSingleFaults(singleFaults); });
    auto offerMachine = [this] {
        core::VerificationOptions withMachine;
        withMachine.closedLoop = true;
        m_withMachineAction->setEnabled(core::runsClosedLoop(m_document->model(), withMachine));
        m_singleFaultsAction->setEnabled(m_withMachineAction->isEnabled() && m_withMachineAction->isChecked());
    };
    connect(m_withMachineAction, &QAction::toggled, this, offerMachine);
    connect(m_document, &Document::machineChanged, this, offerMachine);
    connect(m_document, &Document::modelReplaced, this, offerMachine);
    connect(m_document, &Document::modelReset, this, offerMachine);
    offerMachine();

    m_userGuideAction = action("userGuideAction", &MainWindow::showUserGuide, QKeySequence::HelpContents);
    m_aboutAction = action("aboutAction", &MainWindow::about);
    m_aboutAction->setMenuRole(QAction::AboutRole);
    m_aboutQtAction = action("aboutQtAction", &QApplication::aboutQt);
    m_aboutQtAction->setMenuRole(QAction::AboutQtRole);

    m_languageGroup = new QActionGroup(this);
    m_languageGroup->setExclusive(true);
    for (const UiLanguage& language : availableLanguages()) {
        QAction* a = m_languageGroup->addAction(language.nativeName);
        a->setObjectName(QStringLiteral("language_") + language.code);
        a->setData(language.code);
        a->setCheckable(true);
        a->setChecked(language.code == m_translators.language());
        connect(a, &QAction::triggered, this, [this, code = language.code] { setLanguage(code); });
    }

    m_recentFiles = new RecentFiles(*m_settings, this);
    connect(m_recentFiles, &RecentFiles::openRequested, this, &MainWindow::openFile);
    m_exportActions = new ExportActions(*m_document, *m_scene, *m_settings, this);
    m_exportActions->setGrafcetInFront([this]() -> GrafcetScene* {
        auto* view = qobject_cast<GrafcetView*>(m_centralTabs->currentWidget());
        return view ? view->grafcetScene() : nullptr;
    });
    m_exportActions->setPackmlChart(m_packmlScene);
    m_chartContextMenu = new ChartContextMenu(
        *m_document, *m_selection,
        ChartContextMenu::SheetActions{m_showHiddenAction, m_fitAction, m_exportActions->chartAction()}, this);
    connect(m_view, &ChartView::contextMenuRequested, this, &MainWindow::showChartContextMenu);
    auto* packmlMenu = new PackmlChartContextMenu(
        *m_document, *m_packmlScene, PackmlChartContextMenu::SheetActions{m_fitAction, m_exportActions->chartAction()},
        this);
    connect(packmlMenu, &PackmlChartContextMenu::openGrafcetRequested, this, &MainWindow::openNestedGrafcet);
    connect(m_packmlView->sheetView(), &PackmlSheetView::contextMenuRequested, this,
            [this, packmlMenu](const ElementRef& element, const QPoint& globalPos) {
                ensureDocksReady();
                QMenu menu(this);
                menu.setObjectName(QStringLiteral("packmlChartContextMenu"));
                packmlMenu->populate(&menu, element);
                menu.exec(globalPos);
            });
    connect(m_chartContextMenu, &ChartContextMenu::openGrafcetRequested, this, &MainWindow::openNestedGrafcet);
    connect(m_view, &ChartView::stepDoubleClicked, this, &MainWindow::openNestedGrafcet);
    connect(m_document, &Document::modelReset, m_grafcetTabs, &GrafcetTabs::closeStale);
    connect(m_document, &Document::modesChanged, m_grafcetTabs, &GrafcetTabs::closeStale);
    connect(m_document, &Document::modeChanged, m_grafcetTabs, &GrafcetTabs::closeStale);
    connect(m_exportActions, &ExportActions::exported, this,
            [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName("fileMenu");
    m_fileMenu->addActions({m_newAction, m_openAction});
    m_fileMenu->addMenu(m_recentFiles->menu());
    m_examplesMenu = m_fileMenu->addMenu(QString());
    m_examplesMenu->setObjectName("examplesMenu");
    for (int i = 0; i < int(exampleModels().size()); ++i) {
        QAction* example = m_examplesMenu->addAction(QString());
        example->setObjectName(QStringLiteral("example_%1").arg(i));
        connect(example, &QAction::triggered, this, [this, i] { openExample(i); });
    }
    m_fileMenu->addActions({m_saveAction, m_saveAsAction});
    m_fileMenu->addSeparator();
    m_fileMenu->addActions({m_exportActions->plcOpenAction(), m_exportActions->structuredTextAction(),
                            m_exportActions->ggGeneratorAction(), m_exportActions->chartAction(),
                            m_exportActions->specificationAction()});
    m_fileMenu->addAction(m_exportActions->printAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_resetAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_editMenu = menuBar()->addMenu(QString());
    m_editMenu->setObjectName("editMenu");
    m_editMenu->addActions({m_undoAction, m_redoAction});
    m_editMenu->addSeparator();
    m_editMenu->addActions({m_hideSelectionAction, m_showSelectionAction});
    m_editMenu->addSeparator();
    m_editMenu->addAction(m_modelSettingsAction);

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName("viewMenu");
    m_viewMenu->addAction(m_showHiddenAction);
    m_viewMenu->addSeparator();
    m_viewMenu->addActions({m_fitAction, m_actualSizeAction, m_zoomInAction, m_zoomOutAction});
    m_viewMenu->addSeparator();
    m_viewMenu->addActions(toggleViewActions());
    m_viewMenu->addAction(m_mainToolBar->toggleViewAction());
    m_viewMenu->addAction(m_resetLayoutAction);
    m_dockActionsEnd = m_viewMenu->addSeparator();
    m_languageMenu = m_viewMenu->addMenu(QString());
    m_languageMenu->setObjectName("languageMenu");
    m_languageMenu->addActions(m_languageGroup->actions());

    m_simulationMenu = menuBar()->addMenu(QString());
    m_simulationMenu->setObjectName("simulationMenu");
    m_simulationMenu->addAction(m_simulateAction);
    m_simulationMenu->addSeparator();
    m_simulationMenu->addActions({m_runAction, m_scanAction, m_stepBackAction, m_stepForwardAction,
                                  m_resetSimulationAction});
    m_simulationMenu->addSeparator();
    m_simulationMenu->addActions({m_connectAction, m_disconnectAction});
    m_simulationMenu->addSeparator();
    m_simulationMenu->addAction(m_verifyAction);
    m_simulationMenu->addAction(m_exactTimeAction);
    m_simulationMenu->addAction(m_withMachineAction);
    m_simulationMenu->addAction(m_singleFaultsAction);

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName("helpMenu");
    m_helpMenu->addAction(m_userGuideAction);
    m_helpMenu->addSeparator();
    m_helpMenu->addActions({m_aboutAction, m_aboutQtAction});
}

// The commands used most, each with its icon and its name: students and
// occasional users find them without the menus.
void MainWindow::createToolBar()
{
    m_mainToolBar = addToolBar(QString());
    m_mainToolBar->setObjectName("mainToolBar");
    m_mainToolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_mainToolBar->setMovable(false);
    const auto add = [this](QAction* action, QStyle::StandardPixmap icon) {
        action->setIcon(style()->standardIcon(icon));
        m_mainToolBar->addAction(action);
    };
    add(m_newAction, QStyle::SP_FileIcon);
    add(m_openAction, QStyle::SP_DirOpenIcon);
    add(m_saveAction, QStyle::SP_DialogSaveButton);
    m_mainToolBar->addSeparator();
    add(m_undoAction, QStyle::SP_ArrowBack);
    add(m_redoAction, QStyle::SP_ArrowForward);
    m_mainToolBar->addSeparator();
    add(m_simulateAction, QStyle::SP_MediaPlay);
    add(m_verifyAction, QStyle::SP_DialogApplyButton);
    m_mainToolBar->addSeparator();
    add(m_exportActions->plcOpenAction(), QStyle::SP_ComputerIcon);
}

void MainWindow::setSelectionHidden(bool hidden)
{
    QList<ElementRef> elements;
    for (const ElementRef& element : m_selection->elements()) {
        if (element.kind == ElementRef::Kind::Step || element.kind == ElementRef::Kind::Transition)
            elements << element;
    }
    if (!elements.isEmpty())
        m_document->push(new SetElementsHiddenCommand(*m_document, elements, hidden));
}

void MainWindow::showChartContextMenu(const ElementRef& element, const QPoint& globalPos)
{
    ensureDocksReady();
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("chartContextMenu"));
    m_chartContextMenu->populate(&menu, element);
    if (isSimulating()) { // simulation locks editing: only the sheet's view entries stay
        for (QAction* action : menu.actions()) {
            if (action != m_showHiddenAction && action != m_fitAction && action != m_exportActions->chartAction())
                action->setEnabled(false);
        }
    }
    menu.exec(globalPos);
}

GrafcetView* MainWindow::grafcetView(const QString& stepId) const
{
    return m_grafcetTabs->view(stepId);
}

bool MainWindow::openNestedGrafcet(const QString& stepId)
{
    return m_grafcetTabs->open(stepId);
}

bool MainWindow::isPackml() const
{
    return m_document->model().templateKind() == core::TemplateKind::PackML;
}

bool MainWindow::isSimulating() const
{
    return m_session->isActive() || m_packmlSession->isActive();
}

// Enabled where the history of the template's session has a scan to go to.
void MainWindow::updateHistoryActions()
{
    m_stepBackAction->setEnabled(isPackml() ? m_packmlSession->canStepBack() : m_session->canStepBack());
    m_stepForwardAction->setEnabled(isPackml() ? m_packmlSession->canStepForward() : m_session->canStepForward());
}

QDockWidget* MainWindow::simulationDock() const
{
    return isPackml() ? static_cast<QDockWidget*>(m_packmlSimulationDock) : m_simulationDock;
}

// The chart's tab has no close button (the bar only hides the one it takes away).
void MainWindow::installChartTab(QWidget* chart)
{
    m_centralTabs->insertTab(0, chart, QString());
    for (QTabBar::ButtonPosition side : {QTabBar::LeftSide, QTabBar::RightSide}) {
        QWidget* close = m_centralTabs->tabBar()->tabButton(0, side);
        m_centralTabs->tabBar()->setTabButton(0, side, nullptr);
        delete close;
    }
}

void MainWindow::applyTemplate()
{
    const core::TemplateKind kind = m_document->model().templateKind();
    const bool packml = kind == core::TemplateKind::PackML;
    QWidget* chart = packml ? static_cast<QWidget*>(m_packmlView) : static_cast<QWidget*>(m_view);
    if (m_centralTabs->widget(0) != chart) {
        m_grafcetTabs->setSwitchingFile(true);
        QWidget* previous = m_centralTabs->widget(0);
        m_centralTabs->removeTab(0);
        previous->hide();
        installChartTab(chart);
        m_centralTabs->setCurrentIndex(0);
        m_grafcetTabs->setSwitchingFile(false);
    }
    m_grafcetTabs->retitle();
    const bool templateChanged = m_dockContext->templateKind() != kind;
    m_dockContext->setTemplate(kind);
    // The template's first panel in front of its group, as at the first start.
    if (QDockWidget* first = templateChanged ? dockNamed(packml ? QStringLiteral("packmlStateDock")
                                                                : QStringLiteral("stepDock"))
                                             : nullptr;
        first && !first->isHidden())
        first->raise();
    // What only the GEMMA chart has: hiding its elements, the GG-Generator format.
    for (QAction* gemmaOnly : {m_hideSelectionAction, m_showSelectionAction, m_showHiddenAction,
                               m_exportActions->ggGeneratorAction()})
        gemmaOnly->setVisible(!packml);
    applyEditingLock();
}

void MainWindow::onSelectionChanged(const ElementRef& element)
{
    if (element.isNested())
        openNestedGrafcet(element.id);
    // A GEMMA step or transition selected from a dock (Problems, a link)
    // while a GRAFCET tab is in front: its dock comes with the chart.
    else if (element.kind == ElementRef::Kind::Step || element.kind == ElementRef::Kind::Transition)
        m_centralTabs->setCurrentIndex(0);
}

void MainWindow::onCentralTabChanged()
{
    if (!m_stPreviewDock)
        return;
    auto* view = qobject_cast<GrafcetView*>(m_centralTabs->currentWidget());
    m_stPreviewDock->setGrafcetInFront(view ? view->grafcetScene()->stepId() : QString());
}

void MainWindow::followTabInFront()
{
    m_dockContext->setGrafcetInFront(qobject_cast<GrafcetView*>(m_centralTabs->currentWidget()) != nullptr);
}

void MainWindow::resetLayout()
{
    ensureDocksReady();
    // While the docks are moved, some stand side by side for a moment and
    // the window grows to their minimum sizes: it gets its size back after.
    const QSize before = size();
    for (QDockWidget* dock : docks()) {
        dock->setFloating(false);
        dock->show();
    }
    arrangeDocks(docks());
    if (m_machineDock) // back beside Variables, open or closed as it was
        tabifyDockWidget(m_variablesDock, m_machineDock);
    m_mainToolBar->show();
    addToolBar(Qt::TopToolBarArea, m_mainToolBar);
    if (!isMaximized() && !isFullScreen())
        resize(before);
    m_dockContext->apply(); // every dock shown above: none is closed now
    applyDefaultLayout();
}

void MainWindow::createStatusBar()
{
    m_problemCounter = new ProblemCounter(*m_document, this);
    m_problemCounter->setVerification(m_verification);
    connect(m_problemCounter, &ProblemCounter::clicked, this, [this] {
        ensureDocksReady();
        m_problemsDock->show();
        m_problemsDock->raise();
    });
    m_zoomIndicator = new ZoomIndicator(this);
    m_frontZoom = new FrontZoom(*m_centralTabs, *m_zoomIndicator, this);
    m_simulationIndicator = new StatusBadge(this);
    m_simulationIndicator->setObjectName("simulationIndicator");
    m_simulationIndicator->hide();
    statusBar()->addPermanentWidget(m_simulationIndicator);
    statusBar()->addPermanentWidget(m_problemCounter);
    statusBar()->addPermanentWidget(m_zoomIndicator);
}

// The dock column sized for the screen: the fitted chart is limited by its
// height, which the column leaves whole, so the column takes the width the
// chart cannot use (within 340 px and 40 % of the window), and its lower
// group a little less than half of its height.
void MainWindow::applyDefaultLayout()
{
    const QSize window = size();
    const int separator = style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent, nullptr, this);
    // From the window's height, not the view's: at the first start the
    // window is not laid out yet.
    int chartHeight = window.height() - menuBar()->sizeHint().height() - statusBar()->sizeHint().height();
    if (toolBarArea(m_mainToolBar) == Qt::TopToolBarArea && !m_mainToolBar->isHidden())
        chartHeight -= m_mainToolBar->sizeHint().height();
    const int spare = window.width() - m_view->widthToFitHeight(chartHeight) - separator;
    const int columnWidth = std::clamp(spare, 340, std::max(340, window.width() * 40 / 100));
    const int lowerHeight = std::clamp(window.height() * 42 / 100, 200, 480);
    // Any dock of the column sizes it: the first one the template shows.
    QDockWidget* inColumn = dockNamed(QStringLiteral("stepDock"));
    if (!inColumn || inColumn->isHidden())
        inColumn = dockNamed(QStringLiteral("variablesDock"));
    resizeDocks({inColumn}, {columnWidth}, Qt::Horizontal);
    resizeDocks({dockNamed(QStringLiteral("variablesDock"))}, {lowerHeight}, Qt::Vertical);
}

void MainWindow::restoreLayout()
{
    if (!restoreGeometry(m_settings->windowGeometry()))
        resize(defaultWindowSize(this));
    const QByteArray state = m_settings->windowState();
    bool restored = false;
    m_dockContext->untracked([&] { restored = restoreState(state); });
    m_dockContext->apply();
    if (!restored) {
        applyDefaultLayout();
        return;
    }
    if (!docksReady()) {
        m_framesLayout = state; // the docks take it once they are built
        m_dockContext->untracked([this] { hideFramesTabbedBehind(m_settings->tabbedBehindDocks()); });
    }
}

// Each group keeps a frame: one is hidden only while another of its group
// stays (a stale list hides nothing it should not).
void MainWindow::hideFramesTabbedBehind(const QStringList& names)
{
    for (QDockWidget* frame : std::as_const(m_dockFrames)) {
        if (!names.contains(frame->objectName()))
            continue;
        const QList<QDockWidget*> group = tabifiedDockWidgets(frame);
        const bool anotherStays = std::any_of(group.cbegin(), group.cend(), [&names](const QDockWidget* other) {
            return !other->isHidden() && !names.contains(other->objectName());
        });
        if (anotherStays)
            frame->hide();
    }
}

// The docks behind another dock's tab now, by what is on screen: none of a
// group whose front dock is not (the window minimised, for instance).
QStringList MainWindow::docksTabbedBehind() const
{
    QStringList behind;
    for (QDockWidget* dock : docks()) {
        const QList<QDockWidget*> group = tabifiedDockWidgets(dock);
        const bool frontShown = std::any_of(group.cbegin(), group.cend(), [](const QDockWidget* other) {
            return !other->visibleRegion().isEmpty();
        });
        if (frontShown && dock->visibleRegion().isEmpty())
            behind << dock->objectName();
    }
    return behind;
}

void MainWindow::saveLayout()
{
    // The frames may lack the docks tabbed behind others: the layout to
    // save is the docks' (closing that early is rare, the docks come right
    // after the first frame).
    ensureDocksReady();
    m_settings->setWindowGeometry(saveGeometry());
    m_settings->setWindowState(saveState());
    m_settings->setTabbedBehindDocks(docksTabbedBehind());
    m_settings->setClosedDocks(m_dockContext->closedDocks());
    m_settings->sync();
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        // The docks retranslate themselves (the event goes on to them); the
        // chart paints its frame titles in the current language; the undo
        // history is worded again before the Edit menu shows its last entry.
        rewordUndoHistory(m_document->undoStack());
        retranslate();
        m_scene->update();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate()
{
    m_grafcetTabs->retitle();
    m_fileMenu->setTitle(tr("&File"));
    m_editMenu->setTitle(tr("&Edit"));
    m_viewMenu->setTitle(tr("&View"));
    m_languageMenu->setTitle(tr("&Language"));
    m_simulationMenu->setTitle(tr("&Simulation"));
    m_helpMenu->setTitle(tr("&Help"));

    m_newAction->setText(tr("&New"));
    m_newAction->setStatusTip(tr("Start a new model from the GEMMA template"));
    m_openAction->setText(tr("&Open…"));
    m_openAction->setStatusTip(tr("Open a GG Studio model, a GG-Generator file or an exported PLCopen XML file"));
    m_saveAction->setText(tr("&Save"));
    m_saveAsAction->setText(tr("Save &As…"));
    m_examplesMenu->setTitle(tr("E&xamples"));
    const std::vector<ExampleModel> examples = exampleModels();
    const QList<QAction*> exampleActions = m_examplesMenu->actions();
    for (int i = 0; i < int(examples.size()) && i < int(exampleActions.size()); ++i) {
        exampleActions[i]->setText(examples[size_t(i)].title);
        exampleActions[i]->setStatusTip(examples[size_t(i)].description);
    }
    m_resetAction->setText(tr("&Reset to Template…"));
    m_resetAction->setStatusTip(tr("Put every state, transition, variable and setting back to the template"));
    m_quitAction->setText(tr("&Quit"));

    //: the Undo button of the toolbar (the Edit menu names the command)
    m_undoAction->setIconText(tr("Undo"));
    //: the Redo button of the toolbar (the Edit menu names the command)
    m_redoAction->setIconText(tr("Redo"));
    retitleUndoRedo();
    m_modelSettingsAction->setText(tr("&Model Settings…"));
    m_modelSettingsAction->setStatusTip(tr("Model name, PLC cycle time and code dialect"));

    m_showHiddenAction->setText(tr("Show &Hidden Elements"));
    m_showHiddenAction->setStatusTip(tr("Draw the hidden states and transitions faded, so they can be selected"));
    m_hideSelectionAction->setText(tr("&Hide Selected Elements"));
    m_hideSelectionAction->setStatusTip(tr("Hide the selected states and transitions: the machine does not need them"));
    m_showSelectionAction->setText(tr("Sho&w Selected Elements"));
    m_showSelectionAction->setStatusTip(tr("Show the selected hidden states and transitions again"));
    m_resetLayoutAction->setText(tr("&Reset Layout"));
    m_resetLayoutAction->setStatusTip(tr("Put the panels and the toolbar back where they were at the first start"));
    m_mainToolBar->setWindowTitle(tr("Main Toolbar"));
    m_exportActions->plcOpenAction()->setIconText(tr("Export PLCopen XML"));
    m_fitAction->setText(tr("&Fit to Window"));
    m_actualSizeAction->setText(tr("&Actual Size (100 %)"));
    m_zoomInAction->setText(tr("Zoom &In"));
    m_zoomOutAction->setText(tr("Zoom &Out"));

    m_simulateAction->setText(tr("&Simulate"));
    m_simulateAction->setStatusTip(tr("Run the model scan by scan; editing is locked while the simulation is on"));
    m_runAction->setText(tr("&Run"));
    m_runAction->setStatusTip(tr("Run scans at the speed set in the Simulation dock, or pause them"));
    m_scanAction->setText(tr("Single S&can"));
    m_resetSimulationAction->setText(tr("R&eset Simulation"));
    m_connectAction->setText(tr("Co&nnect…"));
    m_connectAction->setStatusTip(tr("Link the simulation to a digital twin, a soft PLC or an HMI over Modbus TCP; "
                                     "it then runs in real time"));
    m_disconnectAction->setText(tr("&Disconnect"));
    m_disconnectAction->setStatusTip(tr("End the Modbus TCP link"));
    m_stepBackAction->setText(tr("Step &Back"));
    m_stepBackAction->setStatusTip(tr("Show the previous scan of the run; a scan or Run from there continues "
                                      "from it and drops the later scans"));
    m_stepForwardAction->setText(tr("Step &Forward"));
    m_stepForwardAction->setStatusTip(tr("Show the next scan of the run's history"));
    m_simulationIndicator->setText(tr("Simulation: editing locked"));
    m_verifyAction->setText(tr("&Verify"));
    m_verifyAction->setStatusTip(tr("Prove what the GEMMA layer and the nested GRAFCETs can and cannot do for "
                                    "every input sequence, and check your properties; the findings go to the "
                                    "Problems dock"));
    m_exactTimeAction->setText(tr("Verify with &Exact Time"));
    m_exactTimeAction->setStatusTip(tr("Count time in scans when verifying: every timer elapses exactly when the "
                                       "PLC's would, instead of \"may or may not have elapsed\" (more states)"));
    m_withMachineAction->setText(tr("Verify with the &Machine"));
    m_withMachineAction->setStatusTip(tr("Explore the program with the model's machine: the sensors it drives follow "
                                         "the cylinders and conveyors instead of taking any value"));
    m_singleFaultsAction->setText(tr("Verify with Single &Faults"));
    m_singleFaultsAction->setStatusTip(tr("With the machine, also explore any one fault from any scan on: a sensor "
                                          "stuck or flickering, a cylinder or conveyor jammed"));

    m_userGuideAction->setText(tr("&User Guide"));
    m_userGuideAction->setStatusTip(tr("How to build a model, simulate, verify and export, offline; F1 opens it "
                                       "at the part about the panel you are in"));
    m_aboutAction->setText(tr("&About GG Studio"));
    m_aboutQtAction->setText(tr("About &Qt"));

    for (QAction* a : m_languageGroup->actions())
        a->setChecked(a->data().toString() == m_translators.language());

    m_recentFiles->retranslate();
    m_exportActions->retranslate();
    updateTitle();
}

// The toolbar's buttons keep one short label (retranslate), the command in
// their tooltip: with the command in the label they changed width at every
// keystroke in a text field, and the toolbar was laid out and painted again.
void MainWindow::retitleUndoRedo()
{
    const QString undo = m_document->undoStack()->undoText();
    const QString redo = m_document->undoStack()->redoText();
    m_undoAction->setText(undo.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(undo));
    m_redoAction->setText(redo.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(redo));
    m_undoAction->setToolTip(undo.isEmpty() ? tr("Undo") : tr("Undo %1").arg(undo));
    m_redoAction->setToolTip(redo.isEmpty() ? tr("Redo") : tr("Redo %1").arg(redo));
}

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] — GG Studio").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

bool MainWindow::maybeSave()
{
    if (!m_document->isModified())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Unsaved Changes"),
                    tr("The model “%1” has unsaved changes.").arg(m_document->displayName()),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setInformativeText(tr("Do you want to save them?"));
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save:
        return save();
    case QMessageBox::Discard:
        m_autosave->discard();
        return true;
    default:
        return false;
    }
}

void MainWindow::newModel()
{
    if (!maybeSave())
        return;
    NewModelDialog dialog(NewModelDialog::fromSettingName(m_settings->newModelTemplate()), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_settings->setNewModelTemplate(NewModelDialog::settingName(dialog.choice()));
    m_grafcetTabs->remember();
    m_grafcetTabs->setSwitchingFile(true);
    m_grafcetTabs->closeAll();
    m_document->replaceModel(NewModelDialog::newModel(dialog.choice(), *m_settings), QString(),
                             core::ModelFormat::Native);
    m_grafcetTabs->setSwitchingFile(false);
    m_selection->clear();
    updateTitle();
}

void MainWindow::open()
{
    if (!maybeSave())
        return;
    const QStringList filters{
        tr("All supported files (*.json *.xml)"),
        tr("GG Studio models (*.json)"),
        tr("GG-Generator files (*.json)"),
        tr("GG Studio PLCopen XML (*.xml)"),
        tr("All files (*)"),
    };
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Model"), m_settings->lastModelDirectory(),
                                                      filters.join(QStringLiteral(";;")));
    if (!path.isEmpty())
        loadFile(path);
}

bool MainWindow::openFile(const QString& path)
{
    return maybeSave() && loadFile(path);
}

bool MainWindow::loadFile(const QString& path)
{
    QString error;
    QStringList warnings;
    m_grafcetTabs->remember();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    m_grafcetTabs->setSwitchingFile(true);
    const bool loaded = m_document->load(path, &error, &warnings);
    m_grafcetTabs->setSwitchingFile(false);
    QApplication::restoreOverrideCursor();
    if (!loaded) {
        QMessageBox box(QMessageBox::Critical, tr("Open Model"),
                        tr("Could not open %1.").arg(QDir::toNativeSeparators(path)), QMessageBox::Ok, this);
        box.setObjectName("openErrorBox");
        box.setInformativeText(error);
        box.exec();
        if (!QFileInfo::exists(path))
            m_recentFiles->remove(path);
        return false;
    }
    m_selection->clear();
    m_recentFiles->add(path);
    m_grafcetTabs->setSwitchingFile(true);
    m_grafcetTabs->closeAll();
    m_grafcetTabs->setSwitchingFile(false);
    m_grafcetTabs->restore();
    m_settings->setLastModelDirectory(QFileInfo(path).absolutePath());
    updateTitle();
    switch (m_document->fileFormat()) {
    case core::ModelFormat::Native:
        statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)), kStatusMessageMs);
        break;
    case core::ModelFormat::GGGenerator:
    case core::ModelFormat::PlcOpen:
        statusBar()->showMessage(tr("Imported %1: Save As keeps it as a GG Studio model")
                                     .arg(QDir::toNativeSeparators(path)),
                                 kStatusMessageMs);
        break;
    }
    if (!warnings.isEmpty())
        showLoadWarnings(path, warnings);
    return true;
}

// The loader's own English words: they name keys, POUs and places in the file.
void MainWindow::showLoadWarnings(const QString& path, const QStringList& warnings)
{
    QMessageBox box(QMessageBox::Warning, tr("Open Model"),
                    tr("%1 was opened, but not everything in the file was taken over.")
                        .arg(QDir::toNativeSeparators(path)),
                    QMessageBox::Ok, this);
    box.setObjectName("openWarningBox");
    box.setInformativeText(warnings.join(QLatin1Char('\n')));
    box.exec();
}

void MainWindow::openExample(int index)
{
    const std::vector<ExampleModel> examples = exampleModels();
    if (index < 0 || index >= int(examples.size()) || !maybeSave())
        return;
    const ExampleModel& example = examples[size_t(index)];
    QString error;
    const std::unique_ptr<core::Model> model = loadExampleModel(example, &error);
    if (!model) {
        QMessageBox::critical(this, tr("Open Example"), tr("Could not open the example “%1”.").arg(example.title)
                                                            + QStringLiteral("\n\n") + error);
        return;
    }
    m_document->replaceModel(*model, QString(), core::ModelFormat::Native);
    m_selection->clear();
    updateTitle();
    statusBar()->showMessage(tr("Opened the example “%1” as an untitled copy: Save As keeps your changes")
                                 .arg(example.title),
                             kStatusMessageMs);
}

bool MainWindow::needsSaveAs() const
{
    const QString path = m_document->filePath();
    const QString name = QFileInfo(path).fileName().toLower();
    // Never write native JSON over an imported file: its own tool reads it.
    return path.isEmpty() || m_document->fileFormat() != core::ModelFormat::Native || name.endsWith(".xml")
           || name.endsWith(".gg.json");
}

bool MainWindow::save()
{
    return needsSaveAs() ? saveAs() : saveFile(m_document->filePath());
}

bool MainWindow::saveAs()
{
    QString suggestion = m_document->filePath();
    if (suggestion.isEmpty()) {
        suggestion = QDir(m_settings->lastModelDirectory()).filePath(tr("untitled") + QStringLiteral(".json"));
    } else {
        // An imported "x.gg.json" or "x.xml" becomes "x.json" beside it.
        const QFileInfo info(suggestion);
        suggestion = info.dir().filePath(info.fileName().section('.', 0, 0) + QStringLiteral(".json"));
    }
    QString path = QFileDialog::getSaveFileName(this, tr("Save Model As"), suggestion,
                                                tr("GG Studio models (*.json)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    return saveFile(path);
}

bool MainWindow::saveFile(const QString& path)
{
    QString error;
    if (!m_document->save(path, &error)) {
        QMessageBox::critical(this, tr("Save Model"),
                              tr("Could not save %1.").arg(QDir::toNativeSeparators(path)) + QStringLiteral("\n\n") +
                                  error);
        return false;
    }
    m_recentFiles->add(path);
    m_settings->setLastModelDirectory(QFileInfo(path).absolutePath());
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), kStatusMessageMs);
    return true;
}

bool MainWindow::exportPlcOpen(const QString& path, core::Dialect dialect)
{
    QString error;
    if (m_exportActions->writePlcOpen(path, dialect, &error))
        return true;
    QMessageBox::critical(this, tr("Export Failed"),
                          tr("Could not write %1.").arg(QDir::toNativeSeparators(path)) + QStringLiteral("\n\n") +
                              error);
    return false;
}

void MainWindow::offerRecovery()
{
    if (RecoveryPrompt::offer(this, *m_document)) {
        m_selection->clear();
        updateTitle();
        statusBar()->showMessage(tr("Recovered unsaved changes: save them to keep them"), kStatusMessageMs);
    }
}

void MainWindow::resetToTemplate()
{
    const bool packml = m_document->model().templateKind() == core::TemplateKind::PackML;
    const QString question =
        packml ? tr("Put every command, unit mode, GRAFCET, variable and setting back to a new PackML model "
                    "of this edition? You can undo this.")
               : tr("Put every state, transition, variable and setting back to the GEMMA template? "
                    "You can undo this.");
    const auto answer = QMessageBox::question(this, tr("Reset to Template"), question,
                                              QMessageBox::Reset | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Reset)
        m_document->push(new ResetModelCommand(*m_document));
}

void MainWindow::editModelSettings()
{
    ModelSettingsDialog dialog(*m_document, *m_settings, this);
    dialog.exec();
}

void MainWindow::setShowHidden(bool show)
{
    m_scene->setShowHidden(show);
    m_settings->setShowHidden(show);
}

void MainWindow::setLanguage(const QString& code)
{
    // The translators send QEvent::LanguageChange to every widget.
    m_translators.setLanguage(code);
    m_settings->setLanguage(code);
}

// The guide's part about the panel that has the focus.
UserGuide::Topic MainWindow::helpTopic() const
{
    const std::pair<const QWidget*, UserGuide::Topic> places[] = {
        {m_view, UserGuide::Topic::Chart},
        {m_stepDock, UserGuide::Topic::StepPanel},
        {m_transitionDock, UserGuide::Topic::TransitionPanel},
        {m_grafcetStepDock, UserGuide::Topic::StepPanel},
        {m_grafcetTransitionDock, UserGuide::Topic::TransitionPanel},
        {m_variablesDock, UserGuide::Topic::VariablesPanel},
        {m_problemsDock, UserGuide::Topic::ProblemsPanel},
        {m_stPreviewDock, UserGuide::Topic::StructuredTextPanel},
        {m_simulationDock, UserGuide::Topic::Simulation},
        {m_packmlView, UserGuide::Topic::Packml},
        {m_packmlStateDock, UserGuide::Topic::Packml},
        {m_packmlCommandsDock, UserGuide::Topic::Packml},
        {m_packmlModesDock, UserGuide::Topic::Packml},
        {m_packmlSimulationDock, UserGuide::Topic::Packml},
    };
    for (const QWidget* widget = QApplication::focusWidget(); widget; widget = widget->parentWidget()) {
        for (const auto& [place, topic] : places) {
            if (place && widget == place)
                return topic;
        }
    }
    return UserGuide::Topic::GettingStarted;
}

void MainWindow::showUserGuide()
{
    const UserGuide::Topic topic = helpTopic();
    if (!m_userGuide)
        m_userGuide = new UserGuide(this);
    m_userGuide->showTopic(topic);
}

void MainWindow::about()
{
    QMessageBox::about(
        this, tr("About GG Studio"),
        tr("<h3>GG Studio %1</h3>"
           "<p>An editor for the GEMMA-GRAFCET method: choose the operating modes of a machine on the "
           "GEMMA template, write the conditions of their transitions, and generate the IEC 61131-3 "
           "program that runs them (Structured Text, PLCopen XML).</p>")
            .arg(QStringLiteral(GGSTUDIO_VERSION)));
}

void MainWindow::connectModbus()
{
    if (isPackml()) {
        showEditFailure(tr("The Modbus link is for GEMMA models; PackML models are not linked yet"));
        return;
    }
    auto* dialog = new ModbusConnectDialog(m_document->model().variables(), this);
    dialog->setObjectName(QStringLiteral("modbusConnectDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        QString error;
        if (m_modbus->connectLink(dialog->options(), &error))
            return;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Connect"),
                                    tr("The Modbus link could not start: %1").arg(error), QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    dialog->open();
}

void MainWindow::showEditFailure(const QString& message)
{
    statusBar()->showMessage(message, kStatusMessageMs);
}

void MainWindow::onSimulationActiveChanged(bool active)
{
    {
        const QSignalBlocker blocker(m_simulateAction);
        m_simulateAction->setChecked(active);
    }
    m_runAction->setEnabled(active);
    m_scanAction->setEnabled(active);
    m_resetSimulationAction->setEnabled(active);
    updateHistoryActions();
    m_simulationIndicator->setVisible(active);
    applyEditingLock();
    if (active) {
        ensureDocksReady();
        simulationDock()->show();
        simulationDock()->raise();
    }
    giveSimulationTheColumn(active);
}

// While simulating, the Variables and Problems docks are greyed: when they
// share the column below the Simulation dock (the default layout), they and
// the Structured Text dock of their group are hidden, so that the inputs,
// outputs, explanation and trace get the column's height. They come back as
// they were when the simulation ends. A layout the user made (floating,
// side by side, tabbed with Simulation) is left as it is.
void MainWindow::giveSimulationTheColumn(bool simulating)
{
    if (!docksReady())
        return;
    if (!simulating) {
        bringBackLockedDocks();
        return;
    }
    QDockWidget* simulation = simulationDock();
    const Qt::DockWidgetArea area = dockWidgetArea(simulation);
    const auto belowSimulation = [this, area, simulation](QDockWidget* dock) {
        return dock->toggleViewAction()->isChecked() && !dock->isFloating() && !simulation->isFloating()
            && area != Qt::NoDockWidgetArea && dockWidgetArea(dock) == area
            && !tabifiedDockWidgets(simulation).contains(dock);
    };
    QDockWidget* lowerFront = nullptr;
    const QList<QDockWidget*> lowerDocks{m_variablesDock, m_problemsDock, m_stPreviewDock};
    for (QDockWidget* dock : lowerDocks) {
        if (dock->isVisible() && belowSimulation(dock) && dock->x() == simulation->x())
            lowerFront = dock;
    }
    if (!lowerFront || !simulation->isVisible())
        return;
    m_lowerFrontBeforeSimulation = lowerFront;
    m_simulationDockWithTheColumn = simulation;
    m_columnBeforeSimulation = {simulation->height(), lowerFront->height()};
    for (QDockWidget* dock : lowerDocks) {
        if (belowSimulation(dock)) {
            m_setAsideForSimulation << dock;
            dock->hide();
        }
    }
}

void MainWindow::bringBackLockedDocks()
{
    for (QDockWidget* dock : std::as_const(m_setAsideForSimulation)) {
        if (dock)
            dock->show();
    }
    if (m_lowerFrontBeforeSimulation && m_simulationDockWithTheColumn && m_columnBeforeSimulation.size() == 2) {
        m_lowerFrontBeforeSimulation->raise();
        resizeDocks({m_simulationDockWithTheColumn, m_lowerFrontBeforeSimulation}, m_columnBeforeSimulation,
                    Qt::Vertical);
    }
    m_setAsideForSimulation.clear();
    m_lowerFrontBeforeSimulation = nullptr;
    m_columnBeforeSimulation.clear();
}

void MainWindow::verify()
{
    m_verification->start();
    ensureDocksReady();
    m_problemsDock->show();
    m_problemsDock->raise();
    m_problemsDock->showVerification();
}

void MainWindow::showVerificationStatus()
{
    if (m_verification->isRunning()) {
        statusBar()->showMessage(tr("Verifying…"));
        return;
    }
    QString message;
    if (!m_verification->failure().isEmpty())
        message = tr("Verification failed: %1").arg(m_verification->failure());
    else if (m_verification->wasCancelled() || m_verification->isStale() || !m_verification->hasResult())
        message = tr("Verification cancelled: the model, the Complete settings, the machine's use or Exact Time "
                     "changed");
    else if (m_verification->result().violated())
        message = tr("Verification finished: some properties do not hold (see Problems)");
    else if (m_verification->result().undecided())
        message = tr("Verification finished: nothing is violated, but some properties are undecided (see Problems)");
    else
        message = tr("Verification finished: every property holds");
    statusBar()->showMessage(message, kStatusMessageMs);
}

void MainWindow::replayCounterexample(int findingIndex)
{
    const core::VerificationFinding* finding = m_verification->finding(findingIndex);
    if (!finding || !finding->counterexample)
        return;
    QString error;
    const QString name = tr("%1 counterexample").arg(QString::fromStdString(finding->code));
    const bool started = isPackml() ? (m_packmlSession->setActive(true),
                                       m_packmlSession->startReplayText(finding->counterexample->text, name, &error))
                                    : (m_session->setActive(true),
                                       m_session->startReplayText(finding->counterexample->text, name, &error));
    if (!started) {
        QMessageBox box(QMessageBox::Warning, tr("Replay in Simulator"), tr("Could not replay %1.").arg(name),
                        QMessageBox::Ok, this);
        box.setInformativeText(error);
        box.exec();
        return;
    }
    // Paused at scan 0, like a replay from the Simulation dock: F10 steps, Run plays the rest.
    ensureDocksReady();
    simulationDock()->show();
    simulationDock()->raise();
    // A finding about a nested GRAFCET happens on its tab: watched from the
    // start, and in front again when the replay reaches the situation.
    m_replayedGrafcet = QString::fromStdString(finding->gemmaStep);
    if (!m_replayedGrafcet.isEmpty())
        openNestedGrafcet(m_replayedGrafcet);
}

void MainWindow::onReplayChanged()
{
    if (m_replayedGrafcet.isEmpty() || m_session->isReplaying())
        return;
    const QString stepId = std::exchange(m_replayedGrafcet, QString());
    if (m_session->replayState() == SimulationSession::ReplayState::Finished)
        openNestedGrafcet(stepId);
}

// Editing widgets are disabled rather than left to fail: the Document
// refuses every edit while the simulation runs, and a user expects to see it.
void MainWindow::applyEditingLock()
{
    const bool locked = isSimulating();
    QUndoStack* stack = m_document->undoStack();
    m_undoAction->setEnabled(!locked && stack->canUndo());
    m_redoAction->setEnabled(!locked && stack->canRedo());
    m_modelSettingsAction->setEnabled(!locked);
    m_resetAction->setEnabled(!locked);
    m_hideSelectionAction->setEnabled(!locked);
    m_showSelectionAction->setEnabled(!locked);
    if (!docksReady())
        return; // the docks are built with the lock applied
    for (QDockWidget* dock : std::initializer_list<QDockWidget*>{
             m_stepDock, m_transitionDock, m_packmlStateDock, m_packmlCommandsDock, m_packmlModesDock,
             m_grafcetStepDock, m_grafcetTransitionDock, m_variablesDock})
        dock->widget()->setEnabled(!locked);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    m_grafcetTabs->remember();
    bringBackLockedDocks(); // the layout saved is the one without simulation
    saveLayout();
    // Quit ends the long work at once: the simulation stops scanning and
    // the verification's worker is cancelled and joined, so the process
    // does not outlive its window (what is left of a run that does not
    // end in time is waited for when the runner goes).
    m_session->pause();
    m_packmlSession->pause();
    m_verification->shutdown(kQuitWaitMs);
    event->accept();
}

} // namespace editor
