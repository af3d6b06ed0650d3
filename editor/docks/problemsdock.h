#pragma once

#include "core/checks/diagnostic.h"

#include <QDockWidget>
#include <QHash>
#include <QSet>

class QTabWidget;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace editor {

class Document;
class Selection;
class PropertiesPanel;
class VerificationPanel;
class VerificationRunner;

// Every diagnostic of the model (severity, code, element, message), with a
// filter button per severity that shows its count. Double-clicking (or
// Enter on) a problem selects its element and asks for the field at fault,
// which the Step, Transition and Variables docks focus; a problem of a
// nested GRAFCET's step or transition selects it (its tab opens) and the
// Nested Step or Nested Transition dock focuses the field. Given a
// VerificationRunner, the live checks and the verification findings are two
// categories, each on its own tab (VerificationPanel).
class ProblemsDock : public QDockWidget {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    enum Column { CodeColumn, ElementColumn, MessageColumn };

    ProblemsDock(Document* document, Selection* selection, QWidget* parent = nullptr);
    ProblemsDock(Document* document, Selection* selection, VerificationRunner* verification,
                 QWidget* parent = nullptr);

    QTreeWidget* view() const { return m_view; }
    // nullptr without a VerificationRunner.
    VerificationPanel* verificationPanel() const { return m_verificationPanel; }
    PropertiesPanel* propertiesPanel() const { return m_propertiesPanel; }
    QTabWidget* tabs() const { return m_tabs; }
    // Brings the Verification tab to the front.
    void showVerification();
    void showProperties();
    // Selects the element of a problem row and asks to focus its field.
    void activate(QTreeWidgetItem* item);
    // The quick fix of the current row ("Declare 'start' as INPUT BOOL"), in
    // the rows' context menu and on Ctrl+.; hidden for a row without one.
    QAction* declareAction() const { return m_declareAction; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    QToolButton* createFilterButton(core::Severity severity, const QString& objectName);
    void refresh();
    // The row of a problem of a nested GRAFCET's element goes under the row
    // that stands for that GRAFCET (one per GEMMA step, made on first use).
    QTreeWidgetItem* grafcetGroup(const QString& stepId, QList<QTreeWidgetItem*>& topLevel,
                                  QHash<QString, QTreeWidgetItem*>& groups) const;
    void updateGroupTexts();
    void updateFilterButtons();
    void updateTabTexts();
    void applyFilter();
    void copySelected();
    void updateDeclareAction();
    void declareCurrent();
    const core::Diagnostic* currentDiagnostic() const;
    bool isShown(core::Severity severity) const;

    Document* m_document;
    Selection* m_selection;
    QTreeWidget* m_view;
    QAction* m_copyAction = nullptr;
    QAction* m_declareAction = nullptr;
    QToolButton* m_errorsButton = nullptr;
    QToolButton* m_warningsButton = nullptr;
    QToolButton* m_infoButton = nullptr;
    VerificationRunner* m_verification = nullptr;
    VerificationPanel* m_verificationPanel = nullptr;
    PropertiesPanel* m_propertiesPanel = nullptr;
    QTabWidget* m_tabs = nullptr;
    QSet<QString> m_collapsedGroups; // GEMMA step ids whose GRAFCET group the user closed
};

} // namespace editor
