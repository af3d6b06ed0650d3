#include "editor/simulation/packml/packmlvariablespanel.h"

#include "editor/simulation/lampindicator.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/stdstring.h"

#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

namespace editor {

namespace {

QLabel* boldLabel(QWidget* parent)
{
    auto* label = new QLabel(parent);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

void clearGrid(QGridLayout* grid)
{
    while (QLayoutItem* item = grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
}

} // namespace

PackmlVariablesPanel::PackmlVariablesPanel(PackmlSimulationSession* session, QWidget* parent)
    : QWidget(parent)
    , m_session(session)
    , m_inputsTitle(boldLabel(this))
    , m_inputsGrid(new QGridLayout())
    , m_outputsTitle(boldLabel(this))
    , m_outputsGrid(new QGridLayout())
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_inputsTitle);
    layout->addLayout(m_inputsGrid);
    layout->addWidget(m_outputsTitle);
    layout->addLayout(m_outputsGrid);
    retranslate();
}

void PackmlVariablesPanel::retranslate()
{
    m_inputsTitle->setText(tr("Inputs"));
    m_outputsTitle->setText(tr("Outputs"));
}

void PackmlVariablesPanel::clear()
{
    m_inputToggles.clear();
    m_inputFields.clear();
    m_outputLamps.clear();
    m_outputValues.clear();
    clearGrid(m_inputsGrid);
    clearGrid(m_outputsGrid);
}

void PackmlVariablesPanel::rebuild()
{
    clear();
    if (!m_session->isActive())
        return;
    for (const core::Variable& variable : m_session->simulator()->program().variables) {
        const bool isBool = variable.type == core::IecType::Bool;
        if (variable.kind == core::VariableKind::Input)
            addInput(fromStd(variable.name), isBool);
        else if (variable.kind == core::VariableKind::Output)
            addOutput(fromStd(variable.name), isBool);
    }
    refresh();
}

void PackmlVariablesPanel::addInput(const QString& name, bool isBool)
{
    const int row = m_inputsGrid->rowCount();
    if (isBool) {
        auto* toggle = new QToolButton(this);
        toggle->setObjectName(QStringLiteral("toggle_") + name);
        toggle->setText(name);
        toggle->setCheckable(true);
        connect(toggle, &QToolButton::toggled, this, [this, name](bool on) { m_session->setInput(name, core::cond::Value(on)); });
        m_inputsGrid->addWidget(toggle, row, 0, 1, 2);
        m_inputToggles.insert(name, toggle);
        return;
    }
    auto* field = new QLineEdit(this);
    field->setObjectName(QStringLiteral("value_") + name);
    connect(field, &QLineEdit::editingFinished, this, [this, name, field] {
        QString error;
        if (!m_session->setInputText(name, field->text().trimmed(), &error))
            field->setToolTip(error);
        refresh(); // a refused value shows the current one again
    });
    m_inputsGrid->addWidget(new QLabel(name, this), row, 0);
    m_inputsGrid->addWidget(field, row, 1);
    m_inputFields.insert(name, field);
}

void PackmlVariablesPanel::addOutput(const QString& name, bool isBool)
{
    const int row = m_outputsGrid->rowCount();
    m_outputsGrid->addWidget(new QLabel(name, this), row, 0);
    if (isBool) {
        auto* lamp = new LampIndicator(this);
        lamp->setObjectName(QStringLiteral("lamp_") + name);
        m_outputsGrid->addWidget(lamp, row, 1, Qt::AlignLeft);
        m_outputLamps.insert(name, lamp);
        return;
    }
    auto* value = new QLabel(this);
    value->setObjectName(QStringLiteral("shown_") + name);
    m_outputsGrid->addWidget(value, row, 1);
    m_outputValues.insert(name, value);
}

void PackmlVariablesPanel::refresh()
{
    const core::packml::PackmlSimulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    const auto valueOf = [simulator](const QString& name) { return simulator->value(name.toStdString()); };
    const auto textOf = [&valueOf](const QString& name) { return fromStd(core::cond::formatValue(*valueOf(name))); };
    const std::optional<core::cond::Value> on(true);
    for (auto it = m_inputToggles.cbegin(); it != m_inputToggles.cend(); ++it) {
        const QSignalBlocker blocker(it.value());
        it.value()->setChecked(valueOf(it.key()) == on);
    }
    for (auto it = m_inputFields.cbegin(); it != m_inputFields.cend(); ++it)
        if (!it.value()->hasFocus())
            it.value()->setText(textOf(it.key()));
    for (auto it = m_outputLamps.cbegin(); it != m_outputLamps.cend(); ++it)
        it.value()->setOn(valueOf(it.key()) == on);
    for (auto it = m_outputValues.cbegin(); it != m_outputValues.cend(); ++it)
        it.value()->setText(textOf(it.key()));
}

} // namespace editor
