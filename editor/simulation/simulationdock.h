#pragma once

#include <QDockWidget>
#include <QKeySequence>
#include <QList>
#include <QStringList>

class QAbstractButton;
class QCheckBox;
class QComboBox;
class QGridLayout;
class QLabel;
class QListWidget;
class QModelIndex;
class QPushButton;
class QSpinBox;
class QStackedWidget;
class QTabWidget;
class QTableView;
class QToolButton;
class QTreeWidget;
class QWidget;

namespace core {
class NestedEngine;
struct NestedExplanation;
} // namespace core

namespace editor {

class Document;
class LampIndicator;
class SimulationSession;
class TraceTableModel;

// Plays the simulation: run, pause, single scan, reset and speed; the
// inputs (BOOL variables as toggles with a momentary Press button for push
// buttons, numbers as spin boxes in their IEC range) and, read only, what
// the program writes (BOOLs as lamps); Unstable when a nested GRAFCET finds
// no stable situation; Complete of each
// nested step, automatic or manual; why the active step's transitions do or
// do not fire, and for a step with a nested GRAFCET its state and why its
// transitions do or do not fire; the trace; recording and replaying scenario files. The
// session lives in the window; a change of language rewords the dock in
// place, the running simulation included.
class SimulationDock : public QDockWidget {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    // Simulation > Single Scan, Step Back and Step Forward, named in the dock's texts.
    static QKeySequence singleScanShortcut();
    static QKeySequence stepBackShortcut();
    static QKeySequence stepForwardShortcut();
    enum ExplanationColumn { TransitionColumn, StatusColumn };

    SimulationDock(SimulationSession* session, Document* document, QWidget* parent = nullptr);

    SimulationSession* session() const { return m_session; }
    QTreeWidget* explanationView() const { return m_explanationView; }
    QTableView* traceView() const { return m_traceView; }
    TraceTableModel* traceModel() const { return m_traceModel; }
    QListWidget* failureList() const { return m_failureList; }
    QLabel* replayLabel() const { return m_replayLabel; }
    QLabel* statusLabel() const { return m_statusLabel; }
    // The Modbus link's status (Simulation > Connect); hidden when empty.
    QLabel* linkLabel() const { return m_linkLabel; }
    void setLinkStatus(const QString& text);
    // "Unstable: ..." while a nested GRAFCET's last call found no stable
    // situation (until stable); hidden otherwise.
    QLabel* unstableLabel() const { return m_unstableLabel; }
    QToolButton* stepBackButton() const { return m_backButton; }
    QToolButton* stepForwardButton() const { return m_forwardButton; }

    // The input widgets of a variable or nested step; nullptr when none.
    QAbstractButton* toggleButton(const QString& variable) const;
    QAbstractButton* pressButton(const QString& variable) const;
    QWidget* valueEditor(const QString& variable) const; // QSpinBox or QDoubleSpinBox
    QComboBox* completeModeCombo(const QString& stepId) const;
    QCheckBox* manualCompleteCheck(const QString& stepId) const;

    // File > Save / Open dialogs, then the session's recording or replay.
    void recordScenario();
    void replayScenario();

protected:
    void changeEvent(QEvent* event) override;

private:
    enum Tab { ExplanationTab, TraceTab, ScenarioTab };

    // The widgets of one input row, by Simulator::variableNames() index.
    struct InputRow {
        int variable = -1; // index among the simulator's variables
        QString name;
        QAbstractButton* toggle = nullptr;
        QAbstractButton* press = nullptr;
        QWidget* editor = nullptr;
        QLabel* shown = nullptr; // an output or internal variable: its value, read only
        LampIndicator* lamp = nullptr; // beside `shown` for a BOOL
        QLabel* label = nullptr;       // the variable's name
        QLabel* fault = nullptr;       // a machine sensor: its fault, hidden while sound
    };
    struct CompleteRow {
        QString stepId;
        QComboBox* mode = nullptr;
        QCheckBox* manual = nullptr;
        QLabel* output = nullptr;
    };

    void retranslate();
    void setFixedTexts();
    QWidget* createOffPage();
    QWidget* createOnPage();
    QWidget* createControls();
    QWidget* createExplanationTab();
    QWidget* createTraceTab();
    QWidget* createScenarioTab();
    void buildInputRows();
    void addBoolRow(int index, int row);
    void addNumberRow(int index, int row);
    // An output or internal variable: the program writes it, the user watches it.
    void addValueRow(int index, int row);
    void showSensorFaultMenu(const QString& sensor, QWidget* over, const QPoint& at);
    void syncSensorFault(const InputRow& row);
    void addCompleteRow(const QString& stepId, int row);

    void onActiveChanged(bool active);
    void onRunningChanged(bool running);
    void onStepped();
    void syncInputs();
    // The values of the outputs and internal variables, after each scan.
    void syncOutputs();
    void syncCompletes();
    void refreshStatus();
    void refreshUnstable();
    void refreshExplanation();
    void addNestedExplanation(const core::NestedEngine& engine, const core::NestedExplanation& nested);
    void refreshReplay();
    void refreshReplayLabel();
    void refreshFailureList();
    void refreshHistoryButtons();
    // The trace row of the scan shown while stepping through the history.
    void selectViewedScan();
    void showTraceRow(const QModelIndex& index);
    void onHistoryMoved();
    void setNumber(int index, double value);

    SimulationSession* m_session;
    Document* m_document;
    QStackedWidget* m_pages = nullptr;
    QLabel* m_introLabel = nullptr;
    QPushButton* m_startButton = nullptr;
    QToolButton* m_runButton = nullptr;
    QToolButton* m_stepButton = nullptr;
    QToolButton* m_resetButton = nullptr;
    QToolButton* m_backButton = nullptr;
    QToolButton* m_forwardButton = nullptr;
    QToolButton* m_endButton = nullptr;
    QLabel* m_speedLabel = nullptr;
    QSpinBox* m_speedSpin = nullptr;
    QLabel* m_statusLabel = nullptr;
    QLabel* m_unstableLabel = nullptr;
    QWidget* m_inputsWidget = nullptr;
    QGridLayout* m_inputsLayout = nullptr;
    QTabWidget* m_tabs = nullptr;
    QLabel* m_activeLabel = nullptr;
    QTreeWidget* m_explanationView = nullptr;
    QTableView* m_traceView = nullptr;
    TraceTableModel* m_traceModel = nullptr;
    QPushButton* m_recordButton = nullptr;
    QPushButton* m_replayButton = nullptr;
    QLabel* m_replayLabel = nullptr;
    QLabel* m_linkLabel = nullptr;
    QListWidget* m_failureList = nullptr;
    QWidget* m_scenarioTab = nullptr;

    QList<InputRow> m_inputRows;
    QList<CompleteRow> m_completeRows;
    QStringList m_shownExplanation; // what the explanation view shows, to skip identical refreshes
};

} // namespace editor
