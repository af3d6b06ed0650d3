#pragma once

#include "editor/app/userguide.h"
#include "editor/elementref.h"

#include "core/model/model.h"

#include <QMainWindow>
#include <QPointer>

#include <memory>

class QAction;
class QActionGroup;
class QDockWidget;
class QMenu;
class QTabWidget;
class QToolBar;

namespace editor {

class Autosave;
class ChartContextMenu;
class ChartScene;
class ChartView;
class DockContext;
class GrafcetStepDock;
class GrafcetTabs;
class MachineDock;
class MachineTab;
class GrafcetTransitionDock;
class GrafcetView;
class Document;
class ExportActions;
class PackmlChartBinding;
class PackmlCommandsDock;
class PackmlModesDock;
class PackmlSimulationDock;
class PackmlSimulationMarks;
class PackmlSimulationSession;
class PackmlStateDock;
class PackmlChartScene;
class PackmlChartView;
class ProblemCounter;
class ProblemsDock;
class RecentFiles;
class Selection;
class Settings;
class ModbusConnection;
class SimulationChartMarks;
class SimulationDock;
class SimulationSession;
class StatusBadge;
class StPreviewDock;
class StepDock;
class TransitionDock;
class Translators;
class VariablesDock;
class VerificationRunner;
class ZoomIndicator;
class FrontZoom;

// GG Studio's window: the chart in the middle, the Step and Transition docks
// on the right, Variables, Problems and the ST preview below. It edits one
// Document; the file, export and settings work lives in helpers
// (RecentFiles, ExportActions, ModelSettingsDialog, RecoveryPrompt).
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    // When the docks' contents are built. The application shows the chart
    // first: the docks open as empty frames of their final size and fill in
    // right after the first frame, which makes the start a third shorter.
    enum class DockContents { Immediate, AfterFirstFrame };

    // The translators are the application's: the Language menu switches them.
    explicit MainWindow(Translators& translators, DockContents contents = DockContents::Immediate,
                        QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return m_document; }
    Selection* selection() const { return m_selection; }
    ChartScene* chartScene() const { return m_scene; }
    ChartView* chartView() const { return m_view; }
    // The central area: the GEMMA chart first, then a tab per open nested GRAFCET.
    QTabWidget* centralTabs() const { return m_centralTabs; }
    // The tab of `stepId`'s nested GRAFCET; nullptr when it is not open.
    GrafcetView* grafcetView(const QString& stepId) const;
    ExportActions* exportActions() const { return m_exportActions; }
    // The Machine tab (nullptr view while the model has no machine).
    MachineTab* machineTab() const { return m_machineTab; }
    SimulationSession* simulationSession() const { return m_session; }
    // Simulation > Connect's link to a digital twin over Modbus TCP.
    ModbusConnection* modbusConnection() const { return m_modbus; }
    VerificationRunner* verificationRunner() const { return m_verification; }
    // False while the docks are the empty frames of DockContents::AfterFirstFrame.
    bool docksReady() const { return m_dockFrames.isEmpty(); }

signals:
    // The chart was painted for the first time (DockContents::AfterFirstFrame).
    void firstFrameShown();
    // The docks' contents were built (once, after the first frame).
    void docksBecameReady();

public slots:
    // Asks to save unsaved changes first. A file that cannot be read leaves
    // the open model untouched and says why; false then, or when cancelled.
    bool openFile(const QString& path);
    // Native JSON. False, after saying why, when the file cannot be written.
    bool saveFile(const QString& path);
    // The writing of File > Export PLCopen XML, without its questions.
    bool exportPlcOpen(const QString& path, core::Dialect dialect);
    // The models autosave kept from a session that ended without saving.
    void offerRecovery();
    // Opens (or brings to the front) the tab of `stepId`'s nested GRAFCET,
    // with its structured editing (GrafcetActions); false when the step has
    // none and is a simple step (a macro-step or an enclosing step without
    // one opens on an empty drawing that offers to create it).
    bool openNestedGrafcet(const QString& stepId);
    // Simulation > Connect…: the dialog (not modal to the event loop), then
    // the link; a link that cannot start says why.
    void connectModbus();

protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    QList<QDockWidget*> docks() const;
    QList<QAction*> toggleViewActions() const;
    void createDocks();
    void createDockFrames();
    void arrangeDocks(const QList<QDockWidget*>& docks);
    void hideFramesTabbedBehind(const QStringList& names);
    QStringList docksTabbedBehind() const;
    QDockWidget* dockNamed(const QString& objectName) const;
    void deleteDocks();
    void replaceDockFrames();
    // Builds the docks' contents now if they were deferred.
    void ensureDocksReady();
    bool eventFilter(QObject* watched, QEvent* event) override;
    // The dock groups' tab bars show whole titles and scroll: the upper group
    // has five docks, more than a laptop's column holds once elided ("S…").
    void childEvent(QChildEvent* event) override;
    void stopWatchingFirstFrame();
    void createActions();
    void createMenus();
    void createToolBar();
    void showChartContextMenu(const ElementRef& element, const QPoint& globalPos);
    // Edit > Hide / Show Selected Elements: one undoable command for all.
    void setSelectionHidden(bool hidden);
    void createStatusBar();
    void applyDefaultLayout();
    void restoreLayout();
    void saveLayout();
    // View > Reset Layout: every panel back in its place of the first start.
    void resetLayout();
    void retranslate();
    void retitleUndoRedo();

    void newModel();
    void open();
    bool save();
    bool saveAs();
    void resetToTemplate();
    void editModelSettings();
    void setShowHidden(bool show);
    void setLanguage(const QString& code);
    void about();
    // Help > User Guide (F1), at the part about the focused panel.
    void showUserGuide();
    UserGuide::Topic helpTopic() const;

    // Save / Discard / Cancel for unsaved changes; true when the caller may go on.
    bool maybeSave();
    bool loadFile(const QString& path);
    void showLoadWarnings(const QString& path, const QStringList& warnings);
    // File > Examples: the shipped example as an untitled copy.
    void openExample(int index);
    // Whether Save must ask for a name: untitled, or read from another format.
    bool needsSaveAs() const;
    void updateTitle();
    void showEditFailure(const QString& message);
    // Simulation mode: locks the editing actions and docks, shows the dock.
    void onSimulationActiveChanged(bool active);
    // While simulating, the Simulation dock takes most of the dock column
    // from the docks below it (locked then), and gives it back at the end.
    void giveSimulationTheColumn(bool simulating);
    void bringBackLockedDocks();
    // The chart of the model's template in the first tab, its docks and
    // actions: after every new model (New, Open, an example, a recovery).
    void applyTemplate();
    bool isPackml() const;
    // Either template's simulation session is active.
    bool isSimulating() const;
    void updateHistoryActions();
    // The Simulation dock of the model's template.
    QDockWidget* simulationDock() const;
    void installChartTab(QWidget* chart);
    // A nested element selected (the Problems dock, a link) shows its GRAFCET's tab.
    void onSelectionChanged(const ElementRef& element);
    // The Structured Text dock shows the function block of the GRAFCET in front.
    void onCentralTabChanged();
    // The property docks of the tab in front (DockContext).
    void followTabInFront();
    void applyEditingLock();
    // Verify: runs the verifier and shows its findings in the Problems dock.
    void verify();
    void showVerificationStatus();
    // Starts the simulation on a finding's counterexample and plays it.
    void replayCounterexample(int findingIndex);
    void onReplayChanged();

    Translators& m_translators;
    std::unique_ptr<Settings> m_settings;
    Document* m_document;
    Selection* m_selection;
    Autosave* m_autosave;
    ChartScene* m_scene;
    ChartView* m_view;
    QTabWidget* m_centralTabs;
    PackmlChartScene* m_packmlScene;
    PackmlChartView* m_packmlView;
    PackmlChartBinding* m_packmlBinding;
    GrafcetTabs* m_grafcetTabs;
    DockContext* m_dockContext = nullptr;
    StepDock* m_stepDock = nullptr;
    TransitionDock* m_transitionDock = nullptr;
    PackmlStateDock* m_packmlStateDock = nullptr;
    PackmlCommandsDock* m_packmlCommandsDock = nullptr;
    PackmlModesDock* m_packmlModesDock = nullptr;
    GrafcetStepDock* m_grafcetStepDock = nullptr;
    GrafcetTransitionDock* m_grafcetTransitionDock = nullptr;
    VariablesDock* m_variablesDock = nullptr;
    ProblemsDock* m_problemsDock = nullptr;
    StPreviewDock* m_stPreviewDock = nullptr;
    MachineDock* m_machineDock = nullptr;
    RecentFiles* m_recentFiles = nullptr;
    ExportActions* m_exportActions = nullptr;
    ProblemCounter* m_problemCounter = nullptr;
    ZoomIndicator* m_zoomIndicator = nullptr;
    FrontZoom* m_frontZoom = nullptr;
    SimulationSession* m_session = nullptr;
    SimulationChartMarks* m_chartMarks = nullptr;
    MachineTab* m_machineTab = nullptr;
    SimulationDock* m_simulationDock = nullptr;
    PackmlSimulationSession* m_packmlSession = nullptr;
    PackmlSimulationMarks* m_packmlChartMarks = nullptr;
    PackmlSimulationDock* m_packmlSimulationDock = nullptr;
    QPointer<QDockWidget> m_simulationDockWithTheColumn; // while the simulation has the column
    QList<int> m_columnBeforeSimulation; // the Simulation dock's and the lower docks' heights
    QList<QPointer<QDockWidget>> m_setAsideForSimulation; // hidden while the simulation has their room
    QPointer<QDockWidget> m_lowerFrontBeforeSimulation;
    StatusBadge* m_simulationIndicator = nullptr;
    VerificationRunner* m_verification = nullptr;
    // The GEMMA step whose nested GRAFCET the counterexample being replayed
    // is about; empty when the replay is none of a nested finding.
    QString m_replayedGrafcet;

    QMenu* m_fileMenu = nullptr;
    QMenu* m_examplesMenu = nullptr;
    QMenu* m_editMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_languageMenu = nullptr;
    QMenu* m_simulationMenu = nullptr;
    QMenu* m_helpMenu = nullptr;

    QAction* m_newAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_saveAsAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_modelSettingsAction = nullptr;
    QAction* m_resetLayoutAction = nullptr;
    QAction* m_hideSelectionAction = nullptr;
    QAction* m_showSelectionAction = nullptr;
    QToolBar* m_mainToolBar = nullptr;
    ChartContextMenu* m_chartContextMenu = nullptr;
    QAction* m_showHiddenAction = nullptr;
    QAction* m_fitAction = nullptr;
    QAction* m_actualSizeAction = nullptr;
    QAction* m_zoomInAction = nullptr;
    QAction* m_zoomOutAction = nullptr;
    QAction* m_simulateAction = nullptr;
    QAction* m_runAction = nullptr;
    QAction* m_scanAction = nullptr;
    QAction* m_resetSimulationAction = nullptr;
    QAction* m_connectAction = nullptr;
    QAction* m_disconnectAction = nullptr;
    ModbusConnection* m_modbus = nullptr;
    QAction* m_stepBackAction = nullptr;
    QAction* m_stepForwardAction = nullptr;
    QAction* m_verifyAction = nullptr;
    QAction* m_exactTimeAction = nullptr;
    QAction* m_withMachineAction = nullptr;
    QAction* m_singleFaultsAction = nullptr;
    QAction* m_userGuideAction = nullptr;
    UserGuide* m_userGuide = nullptr; // made on first use
    QAction* m_aboutAction = nullptr;
    QAction* m_aboutQtAction = nullptr;
    QActionGroup* m_languageGroup = nullptr;
    QAction* m_dockActionsEnd = nullptr; // the separator after the docks in the View menu
    // The empty frames that stand for the docks until their contents are built.
    QList<QDockWidget*> m_dockFrames;
    // The saved layout the frames took, for the docks (empty: the default one).
    QByteArray m_framesLayout;
    // The chart's viewport until its first paint (DockContents::AfterFirstFrame).
    QWidget* m_firstFrameWatched = nullptr;
};

} // namespace editor
