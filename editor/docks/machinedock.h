#pragma once

#include <QDockWidget>
#include <QList>

#include "core/machine/machine.h"

#include <functional>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;
class QWidget;

namespace editor {

class Document;

// The virtual machine's components (docs/simulation.md, "The virtual
// machine"): add one of a kind, remove one, and for the selected one its
// name, the variable of each role (drop-downs of the variables that fit:
// BOOL outputs for what the program drives, BOOL inputs for sensors and
// the operator's inputs), its times, contact and conveyor. Each change is
// one undoable command; the dock follows the model and is locked while
// simulating, like the other property docks.
class MachineDock : public QDockWidget {
    Q_OBJECT

public:
    static QString title();

    explicit MachineDock(Document* document, QWidget* parent = nullptr);

    QListWidget* componentList() const { return m_list; }
    QComboBox* kindCombo() const { return m_kind; }
    QPushButton* addButton() const { return m_add; }
    QPushButton* removeButton() const { return m_remove; }
    QLineEdit* nameEdit() const { return m_name; }
    // The selected component's fields; nullptr when it has no such role or parameter.
    QComboBox* roleCombo(const QString& roleKey) const;
    QSpinBox* parameterSpin(const QString& parameterKey) const;
    QComboBox* contactCombo() const { return m_contact; }
    QComboBox* conveyorCombo() const { return m_conveyor; }

    // The component selected in the list; -1 when none.
    int currentComponent() const;
    void selectComponent(int component);

    // Adds a component of the kind in the combo, named after its kind and unique.
    void addComponent();
    void removeComponent();

protected:
    void changeEvent(QEvent* event) override;

private:
    struct RoleField {
        QString key;
        QComboBox* combo = nullptr;
    };
    struct ParameterField {
        QString key;
        QSpinBox* spin = nullptr;
    };

    void retranslate();
    void refreshList();
    void rebuildForm();
    void applyLock();
    void edit(const QString& field, const std::function<void(core::machine::Component&)>& change);
    QString uniqueName(const QString& base) const;

    Document* m_document;
    QListWidget* m_list = nullptr;
    QComboBox* m_kind = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    QWidget* m_form = nullptr;
    QFormLayout* m_formLayout = nullptr;
    QLabel* m_empty = nullptr;
    QLineEdit* m_name = nullptr;
    QComboBox* m_contact = nullptr;
    QComboBox* m_conveyor = nullptr;
    QList<RoleField> m_roles;
    QList<ParameterField> m_parameters;
};

} // namespace editor
