#pragma once

#include "core/templates/packml/packmltemplate.h"

#include <QMap>
#include <QWidget>

class QCheckBox;
class QGroupBox;
class QLabel;
class QLineEdit;

namespace editor {

class ConditionEdit;
class DiagnosticList;
class Document;

// The fields of one unit mode in the Modes panel (spec packml.md §3): its
// name (user modes; 1..3 keep Production, Maintenance, Manual), comment,
// request condition, the states it disables and the states where it allows
// a mode change, as check lists, and its problems. Every change is one
// undoable command. The disabled list stays consistent as §3.2 says
// (packml::consistentListing): a check shows what the mode does (a Held that
// an enabled Holding keeps is shown enabled), and checking Held disables
// Holding and Unholding with it.
class PackmlModeForm : public QWidget {
    Q_OBJECT

public:
    PackmlModeForm(Document* document, QWidget* parent = nullptr);

    int mode() const { return m_mode; }
    // Shows mode `number` (which must exist) and fills the fields.
    void setMode(int number);
    void refresh();
    void retranslate();
    // "name", "comment", "condition" (the request), "disabled", "modeChange".
    void focusField(const QString& field);

private:
    QWidget* createStateLists();
    void refreshName();
    void refreshRequest();
    void refreshStateLists();
    void onNameCommitted();
    void onDisabledToggled(core::packml::State state);
    void onModeChangeToggled(core::packml::State state, bool allowed);

    Document* m_document;
    int m_mode = 0;
    QLabel* m_nameLabel;
    QLineEdit* m_nameEdit;
    QLabel* m_commentLabel;
    QLineEdit* m_commentEdit;
    QLabel* m_requestLabel;
    ConditionEdit* m_requestEdit;
    DiagnosticList* m_problems;
    QGroupBox* m_disabledGroup = nullptr;
    QGroupBox* m_modeChangeGroup = nullptr;
    QLabel* m_disabledHint = nullptr;
    QMap<core::packml::State, QCheckBox*> m_disabledChecks;
    QMap<core::packml::State, QCheckBox*> m_modeChangeChecks;
};

} // namespace editor
