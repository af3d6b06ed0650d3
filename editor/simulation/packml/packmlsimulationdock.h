#pragma once

#include "core/templates/packml/packmltemplate.h"

#include <QDockWidget>
#include <QHash>
#include <QString>

class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;
class QTabWidget;
class QTableView;
class QToolButton;
class QVBoxLayout;
class QWidget;

namespace editor {

class Document;
class LampIndicator;
class PackmlSimulationSession;
class PackmlTraceModel;
class PackmlVariablesPanel;

// Plays a PackML simulation (issue 34, Simulation): start and end, run,
// pause, single scan, step back and forward, reset and speed; the unit's
// commands as push buttons (the ones the current state accepts in bold)
// with what became of the latest press ("Hold is not accepted in Idle"),
// the unit-mode selector (picking a mode requests it), the inputs (BOOLs as
// toggles, the others, PackTags included, as text fields), what the program
// writes (BOOLs as lamps, numbers as values, StateCurrent and
// UnitModeCurrent included); the trace of scans; a scenario replayed with
// its expectations met or failed. Everything it shows is the scan the
// session shows, a past one while stepping through the history.
class PackmlSimulationDock : public QDockWidget {
    Q_OBJECT

public:
    static QString title();

    PackmlSimulationDock(PackmlSimulationSession* session, Document* document, QWidget* parent = nullptr);

    PackmlSimulationSession* session() const { return m_session; }

    QPushButton* startButton() const { return m_startButton; }
    QToolButton* runButton() const { return m_runButton; }
    QToolButton* stepButton() const { return m_stepButton; }
    QToolButton* stepBackButton() const { return m_backButton; }
    QToolButton* stepForwardButton() const { return m_forwardButton; }
    QToolButton* resetButton() const { return m_resetButton; }
    QSpinBox* speedSpin() const { return m_speedSpin; }
    QLabel* statusLabel() const { return m_statusLabel; }
    QLabel* requestLabel() const { return m_requestLabel; }
    QComboBox* modeSelector() const { return m_modeSelector; }
    // The function block of the current (mode, state): its instance, the
    // active steps of its GRAFCET or that it has none, its Complete.
    QLabel* instanceLabel() const { return m_instanceLabel; }
    // The SC of an instance without GRAFCET: from its skeleton, TRUE or
    // FALSE by hand (shown only for such an instance).
    QComboBox* completeCombo() const { return m_completeCombo; }
    QTableView* traceView() const { return m_traceView; }
    PackmlTraceModel* traceModel() const { return m_traceModel; }
    QLabel* replayLabel() const { return m_replayLabel; }
    QListWidget* failureList() const { return m_failureList; }

    // nullptr when the edition has no such command or the session is inactive.
    QPushButton* commandButton(core::packml::Command command) const;
    // Does the state shown accept the command in the mode shown (it is drawn bold)?
    bool isCommandAccepted(core::packml::Command command) const;
    // The widgets of a variable: a toggle for a BOOL input, a text field for
    // another input, a lamp for a BOOL output, a value label for another output.
    PackmlVariablesPanel* variablesPanel() const { return m_variables; }
    QToolButton* inputToggle(const QString& variable) const;
    QLineEdit* inputField(const QString& variable) const;
    LampIndicator* outputLamp(const QString& variable) const;
    QLabel* outputValue(const QString& variable) const;

    // Replays a scenario file; problems go to the replay label. The Open
    // button asks for the file, then calls it.
    bool replayFile(const QString& path);

protected:
    void changeEvent(QEvent* event) override;

private:
    QWidget* buildControls();
    QWidget* buildUnitTab();
    QWidget* buildTraceTab();
    QWidget* buildScenarioTab();
    void connectSession();
    void retranslate();
    void rebuildForProgram();
    void clearProgramWidgets();
    void addCommandButtons();
    void addModes();
    void openScenario();

    void refresh();
    void refreshControls();
    void refreshStatus();
    void refreshCommands();
    void refreshRequest();
    void refreshInstance();
    void refreshReplay();
    void selectShownScan();

    PackmlSimulationSession* m_session;
    Document* m_document;

    QPushButton* m_startButton = nullptr;
    QToolButton* m_runButton = nullptr;
    QToolButton* m_stepButton = nullptr;
    QToolButton* m_backButton = nullptr;
    QToolButton* m_forwardButton = nullptr;
    QToolButton* m_resetButton = nullptr;
    QToolButton* m_endButton = nullptr;
    QSpinBox* m_speedSpin = nullptr;
    QLabel* m_speedLabel = nullptr;
    QLabel* m_statusLabel = nullptr;
    QTabWidget* m_tabs = nullptr;

    QLabel* m_commandsTitle = nullptr;
    QGridLayout* m_commandsGrid = nullptr;
    QLabel* m_requestLabel = nullptr;
    QLabel* m_modeTitle = nullptr;
    QComboBox* m_modeSelector = nullptr;
    QLabel* m_instanceTitle = nullptr;
    QLabel* m_instanceLabel = nullptr;
    QComboBox* m_completeCombo = nullptr;
    PackmlVariablesPanel* m_variables = nullptr;
    QHash<int, QPushButton*> m_commandButtons; // by CntrlCmd number

    QTableView* m_traceView = nullptr;
    PackmlTraceModel* m_traceModel = nullptr;

    QPushButton* m_replayButton = nullptr;
    QLabel* m_replayLabel = nullptr;
    QListWidget* m_failureList = nullptr;
    QString m_replayError; // the latest scenario refused, until the next replay or reset
};

} // namespace editor
