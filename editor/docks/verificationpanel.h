#pragma once

#include "core/checks/diagnostic.h"

#include <QSet>
#include <QString>
#include <QWidget>

class QAction;
class QLabel;
class QSpinBox;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace core {
struct VerificationFinding;
}

namespace editor {

class Selection;
class VerificationRunner;

// The Verification category of the Problems dock: a Verify button, what the
// last run found (severity, code, elements, counterexample length, message;
// errors first; the findings about a nested GRAFCET under a row of its
// GEMMA step) and, for the current finding, Show on Chart (selects its first
// element, a nested one on its GRAFCET's tab) and Replay in Simulator (asked
// of the window through replayRequested()).
// After a change of the model, or of the Complete assumptions (Simulation
// dock), the findings stay, greyed, with a note, until the next run. A label
// says which nested steps the shown findings assume Complete automatic.
class VerificationPanel : public QWidget {
    Q_OBJECT

public:
    enum Column { CodeColumn, ElementColumn, ScansColumn, MessageColumn };

    VerificationPanel(VerificationRunner* runner, Selection* selection, QWidget* parent = nullptr);

    QTreeWidget* view() const { return m_view; }
    QLabel* statusLabel() const { return m_statusLabel; }
    QLabel* assumptionsLabel() const { return m_assumptionsLabel; }
    QAction* verifyAction() const { return m_verifyAction; }
    // How long a verification may run (seconds), remembered in the settings.
    QSpinBox* timeLimitBox() const { return m_timeLimitBox; }
    QAction* showOnChartAction() const { return m_showAction; }
    QAction* replayAction() const { return m_replayAction; }

    // The index of the row's finding in the runner's result; -1 for none
    // (a GEMMA step's row grouping the findings about its nested GRAFCET).
    static int findingIndex(const QTreeWidgetItem* item);
    void showOnChart(const QTreeWidgetItem* item);
    void replay(const QTreeWidgetItem* item);

signals:
    // The user asked to replay the counterexample of this finding.
    void replayRequested(int findingIndex);

protected:
    void changeEvent(QEvent* event) override;

private:
    void setUpTimeLimit();
    void retranslate();
    void refresh();
    void refreshStatus();
    void refreshAssumptions();
    void updateActions();
    void copySelected();
    QTreeWidgetItem* findingItem(const core::VerificationFinding& finding, int index, bool stale) const;
    QTreeWidgetItem* groupItem(const QString& stepId, core::Severity worst, bool stale) const;
    void greyOut(QTreeWidgetItem* item) const;
    void showGrouped(bool grouped);

    VerificationRunner* m_runner;
    Selection* m_selection;
    QTreeWidget* m_view;
    QLabel* m_statusLabel;
    QLabel* m_assumptionsLabel;
    QAction* m_verifyAction;
    QAction* m_showAction;
    QAction* m_replayAction;
    QAction* m_copyAction;
    QLabel* m_timeLimitLabel;
    QSpinBox* m_timeLimitBox;
    QSet<QString> m_collapsedGroups; // GEMMA step ids
};

} // namespace editor
