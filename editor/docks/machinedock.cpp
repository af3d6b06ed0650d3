#include "editor/docks/machinedock.h"

#include "editor/commands/addmachinecomponentcommand.h"
#include "editor/commands/editmachinecomponentcommand.h"
#include "editor/commands/removemachinecomponentcommand.h"
#include "editor/document.h"
#include "editor/machine/machinetext.h"

#include "core/model/iectypes.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {

namespace {

using core::machine::ComponentKind;
using core::machine::SignalDirection;

// The variables a role may be wired to: BOOL outputs for what the program
// drives, BOOL inputs for what the machine or the operator sets.
QStringList fittingVariables(const core::Model& model, SignalDirection direction)
{
    const core::VariableKind wanted =
        direction == SignalDirection::Actuator ? core::VariableKind::Output : core::VariableKind::Input;
    QStringList names;
    for (const core::Variable& variable : model.variables()) {
        if (variable.type == core::IecType::Bool && variable.kind == wanted)
            names << QString::fromStdString(variable.name);
    }
    return names;
}

std::string kindKey(ComponentKind kind)
{
    return std::string(core::machine::componentKindName(kind));
}

} // namespace

QString MachineDock::title()
{
    return tr("Machine");
}

MachineDock::MachineDock(Document* document, QWidget* parent)
    : QDockWidget(parent)
    , m_document(document)
{
    setObjectName(QStringLiteral("machineDock"));
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    m_list = new QListWidget(content);
    m_list->setObjectName(QStringLiteral("machineComponents"));
    m_list->setMinimumHeight(fontMetrics().height() * 4);
    layout->addWidget(m_list, 1);
    auto* buttons = new QHBoxLayout;
    m_kind = new QComboBox(content);
    m_kind->setObjectName(QStringLiteral("machineKind"));
    m_add = new QPushButton(content);
    m_add->setObjectName(QStringLiteral("addMachineComponent"));
    m_remove = new QPushButton(content);
    m_remove->setObjectName(QStringLiteral("removeMachineComponent"));
    buttons->addWidget(m_kind, 1);
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    layout->addLayout(buttons);
    m_empty = new QLabel(content);
    m_empty->setWordWrap(true);
    layout->addWidget(m_empty);
    m_form = new QWidget(content);
    m_formLayout = new QFormLayout(m_form);
    m_formLayout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_form, 2);
    // Scrolled: the panel shares the lower group's height and must not make the window taller.
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    scroll->setMinimumHeight(fontMetrics().height() * 3); // not the form's: it scrolls
    setWidget(scroll);

    connect(m_add, &QPushButton::clicked, this, &MachineDock::addComponent);
    connect(m_remove, &QPushButton::clicked, this, &MachineDock::removeComponent);
    connect(m_list, &QListWidget::currentRowChanged, this, &MachineDock::rebuildForm);
    connect(m_document, &Document::machineChanged, this, &MachineDock::refreshList);
    connect(m_document, &Document::modelReset, this, &MachineDock::refreshList);
    connect(m_document, &Document::variablesChanged, this, &MachineDock::rebuildForm);
    connect(m_document, &Document::variableChanged, this, &MachineDock::rebuildForm);
    connect(m_document, &Document::readOnlyChanged, this, &MachineDock::applyLock);
    retranslate();
    refreshList();
    applyLock();
}

void MachineDock::changeEvent(QEvent* event)
{
    QDockWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslate();
}

void MachineDock::retranslate()
{
    setWindowTitle(title());
    {
        const QSignalBlocker blocker(m_kind);
        const int kind = m_kind->currentIndex();
        m_kind->clear();
        for (ComponentKind each : core::machine::allComponentKinds())
            m_kind->addItem(machinetext::kindName(each), static_cast<int>(each));
        m_kind->setCurrentIndex(std::max(kind, 0));
    }
    m_add->setText(tr("Add"));
    m_add->setToolTip(tr("Add a component of the kind chosen beside"));
    m_remove->setText(tr("Remove"));
    m_remove->setToolTip(tr("Remove the selected component and its wiring"));
    m_empty->setText(tr("The model has no machine yet. Add its components to simulate in closed loop: the "
                        "machine then sets the sensors."));
    refreshList();
}

void MachineDock::applyLock()
{
    widget()->setEnabled(!m_document->isReadOnly());
}

int MachineDock::currentComponent() const
{
    return m_list->currentRow();
}

void MachineDock::selectComponent(int component)
{
    m_list->setCurrentRow(component);
}

void MachineDock::refreshList()
{
    const int current = m_list->currentRow();
    const core::machine::Machine& machine = m_document->model().machine();
    {
        const QSignalBlocker blocker(m_list);
        m_list->clear();
        for (const core::machine::Component& component : machine.components)
            m_list->addItem(QStringLiteral("%1 (%2)").arg(QString::fromStdString(component.name),
                                                          machinetext::kindName(component.kind)));
        // The first component's form rather than an empty panel.
        m_list->setCurrentRow(current < 0 ? 0 : std::min(current, m_list->count() - 1));
    }
    m_empty->setVisible(machine.empty());
    rebuildForm();
}

QString MachineDock::uniqueName(const QString& base) const
{
    const core::machine::Machine& machine = m_document->model().machine();
    QString name = base;
    for (int n = 2; machine.find(name.toStdString()); ++n)
        name = base + QString::number(n);
    return name;
}

void MachineDock::addComponent()
{
    const auto kind = static_cast<ComponentKind>(m_kind->currentData().toInt());
    // A name from the kind's file key, an identifier in any language: "Conveyor", "PushButton2".
    QString base;
    for (const QString& word : QString::fromStdString(kindKey(kind)).split(QLatin1Char('-')))
        base += word.left(1).toUpper() + word.mid(1);
    core::machine::Component component = core::machine::makeComponent(kind, uniqueName(base).toStdString());
    if (m_document->push(new AddMachineComponentCommand(*m_document, std::move(component))))
        selectComponent(static_cast<int>(m_document->model().machine().components.size()) - 1);
}

void MachineDock::removeComponent()
{
    const int component = currentComponent();
    if (component < 0)
        return;
    m_document->push(new RemoveMachineComponentCommand(*m_document, static_cast<std::size_t>(component)));
}

void MachineDock::edit(const QString& field, const std::function<void(core::machine::Component&)>& change)
{
    const int component = currentComponent();
    const core::machine::Machine& machine = m_document->model().machine();
    if (component < 0 || static_cast<std::size_t>(component) >= machine.components.size())
        return;
    core::machine::Component edited = machine.components[static_cast<std::size_t>(component)];
    change(edited);
    if (!m_document->push(
            new EditMachineComponentCommand(*m_document, static_cast<std::size_t>(component), edited, field)))
        rebuildForm(); // refused: the fields show the model again
}

QComboBox* MachineDock::roleCombo(const QString& roleKey) const
{
    for (const RoleField& role : m_roles) {
        if (role.key == roleKey)
            return role.combo;
    }
    return nullptr;
}

QSpinBox* MachineDock::parameterSpin(const QString& parameterKey) const
{
    for (const ParameterField& parameter : m_parameters) {
        if (parameter.key == parameterKey)
            return parameter.spin;
    }
    return nullptr;
}

// The form of the selected component, built again after each change: a
// component's fields depend on its kind, and the model's variables may have changed.
void MachineDock::rebuildForm()
{
    // Later: the field whose edit rebuilt the form is still in its signal.
    while (m_formLayout->rowCount() > 0) {
        const QFormLayout::TakeRowResult row = m_formLayout->takeRow(0);
        for (QLayoutItem* item : {row.labelItem, row.fieldItem}) {
            if (!item)
                continue;
            if (QWidget* field = item->widget()) {
                field->hide();
                field->deleteLater();
            }
            delete item;
        }
    }
    m_roles.clear();
    m_parameters.clear();
    m_name = nullptr;
    m_contact = nullptr;
    m_conveyor = nullptr;
    const int index = currentComponent();
    const core::machine::Machine& machine = m_document->model().machine();
    m_remove->setEnabled(index >= 0);
    if (index < 0 || static_cast<std::size_t>(index) >= machine.components.size())
        return;
    const core::machine::Component& component = machine.components[static_cast<std::size_t>(index)];
    const core::machine::ComponentKindSpec& spec = core::machine::kindSpec(component.kind);

    m_name = new QLineEdit(QString::fromStdString(component.name), m_form);
    m_name->setObjectName(QStringLiteral("machineComponentName"));
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string name = m_name->text().trimmed().toStdString();
        edit(QStringLiteral("name"), [&name](core::machine::Component& c) { c.name = name; });
    });
    m_formLayout->addRow(tr("Name"), m_name);
    m_formLayout->addRow(tr("Kind"), new QLabel(machinetext::kindName(component.kind), m_form));

    for (std::size_t role = 0; role < spec.roles.size(); ++role) {
        const QString key = QString::fromUtf8(spec.roles[role].key.data(), static_cast<qsizetype>(spec.roles[role].key.size()));
        auto* combo = new QComboBox(m_form);
        combo->setObjectName(QStringLiteral("machineRole_") + key);
        combo->addItem(tr("(not wired)"), QString());
        for (const QString& variable : fittingVariables(m_document->model(), spec.roles[role].direction))
            combo->addItem(variable, variable);
        const QString wired = role < component.wires.size() ? QString::fromStdString(component.wires[role]) : QString();
        int at = combo->findData(wired, Qt::UserRole, Qt::MatchFixedString);
        if (at < 0 && !wired.isEmpty()) { // wired to a variable that does not fit: shown, for the checks name it
            combo->addItem(wired, wired);
            at = combo->count() - 1;
        }
        combo->setCurrentIndex(std::max(at, 0));
        combo->setToolTip(spec.roles[role].direction == SignalDirection::Actuator
                              ? tr("A BOOL output of the program, which drives the component")
                              : tr("A BOOL input of the program, which the component sets"));
        connect(combo, &QComboBox::activated, this, [this, combo, key] {
            const std::string variable = combo->currentData().toString().toStdString();
            edit(key, [&](core::machine::Component& c) { c.setSignal(key.toStdString(), variable); });
        });
        m_formLayout->addRow(machinetext::roleName(spec.roles[role].key), combo);
        m_roles << RoleField{key, combo};
    }
    for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
        const core::machine::ParameterSpec& parameter = spec.parameters[p];
        const QString key = QString::fromUtf8(parameter.key.data(), static_cast<qsizetype>(parameter.key.size()));
        auto* spin = new QSpinBox(m_form);
        spin->setObjectName(QStringLiteral("machineParameter_") + key);
        switch (parameter.kind) {
        case core::machine::ParameterKind::TravelTime:
            spin->setRange(1, static_cast<int>(core::machine::kMaxMachineTimeMs));
            break;
        case core::machine::ParameterKind::Delay:
            spin->setRange(0, static_cast<int>(core::machine::kMaxMachineTimeMs));
            break;
        case core::machine::ParameterKind::PartCount:
            spin->setRange(-1, static_cast<int>(core::machine::kMaxParts));
            spin->setSpecialValueText(tr("Unlimited"));
            break;
        }
        spin->setValue(static_cast<int>(component.parameters[p]));
        spin->setKeyboardTracking(false);
        connect(spin, &QSpinBox::valueChanged, this, [this, key](int value) {
            edit(key, [&](core::machine::Component& c) { c.setParameter(key.toStdString(), value); });
        });
        m_formLayout->addRow(machinetext::parameterName(parameter.key), spin);
        m_parameters << ParameterField{key, spin};
    }
    if (spec.hasContact) {
        m_contact = new QComboBox(m_form);
        m_contact->setObjectName(QStringLiteral("machineContact"));
        for (core::machine::Contact contact : {core::machine::Contact::NormallyOpen, core::machine::Contact::NormallyClosed})
            m_contact->addItem(machinetext::contactName(contact), static_cast<int>(contact));
        m_contact->setCurrentIndex(component.contact == core::machine::Contact::NormallyClosed ? 1 : 0);
        connect(m_contact, &QComboBox::activated, this, [this] {
            const auto contact = static_cast<core::machine::Contact>(m_contact->currentData().toInt());
            edit(QStringLiteral("contact"), [contact](core::machine::Component& c) { c.contact = contact; });
        });
        m_formLayout->addRow(tr("Contact"), m_contact);
    }
    if (spec.feedsConveyor) {
        m_conveyor = new QComboBox(m_form);
        m_conveyor->setObjectName(QStringLiteral("machineConveyor"));
        m_conveyor->addItem(tr("(none)"), QString());
        for (const core::machine::Component& other : machine.components) {
            if (other.kind == ComponentKind::Conveyor)
                m_conveyor->addItem(QString::fromStdString(other.name), QString::fromStdString(other.name));
        }
        m_conveyor->setCurrentIndex(
            std::max(m_conveyor->findData(QString::fromStdString(component.conveyor), Qt::UserRole, Qt::MatchFixedString), 0));
        connect(m_conveyor, &QComboBox::activated, this, [this] {
            const std::string conveyor = m_conveyor->currentData().toString().toStdString();
            edit(QStringLiteral("conveyor"), [&conveyor](core::machine::Component& c) { c.conveyor = conveyor; });
        });
        m_formLayout->addRow(tr("Feeds"), m_conveyor);
    }
}

} // namespace editor
