#include "editor/window/modelsettingsdialog.h"

#include "editor/app/settings.h"
#include "editor/commands/setcycletimecommand.h"
#include "editor/commands/setdialectcommand.h"
#include "editor/commands/setevolutionrulecommand.h"
#include "editor/commands/setmodelnamecommand.h"
#include "editor/commands/undohistorywording.h"
#include "editor/document.h"
#include "editor/export/exportoptionsdialog.h"
#include "editor/style/secondarytext.h"
#include "editor/window/packmlsettingswidget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QUndoStack>
#include <QVBoxLayout>

#include <vector>

namespace editor {

ModelSettingsDialog::ModelSettingsDialog(Document& document, Settings& settings, QWidget* parent)
    : QDialog(parent)
    , m_document(document)
    , m_settings(settings)
    , m_nameEdit(new QLineEdit(this))
    , m_cycleTimeSpin(new QSpinBox(this))
    , m_dialectCombo(new QComboBox(this))
    , m_evolutionCombo(new QComboBox(this))
    , m_evolutionDescription(new QLabel(this))
    , m_defaultsCheck(new QCheckBox(this))
{
    setObjectName("modelSettingsDialog");
    setWindowTitle(tr("Model Settings"));
    const core::ModelSettings& current = document.model().settings();

    m_nameEdit->setObjectName("nameEdit");
    m_nameEdit->setText(QString::fromStdString(current.name));
    m_nameEdit->setToolTip(tr("The project name written into the exported PLCopen XML"));

    m_cycleTimeSpin->setObjectName("cycleTimeSpin");
    m_cycleTimeSpin->setRange(core::kMinCycleTimeMs, core::kMaxCycleTimeMs);
    m_cycleTimeSpin->setSuffix(tr(" ms"));
    m_cycleTimeSpin->setValue(current.cycleTimeMs);
    m_cycleTimeSpin->setToolTip(tr("The period of the cyclic PLC task that runs GEMMA"));

    m_dialectCombo->setObjectName("dialectCombo");
    for (core::Dialect d : {core::Dialect::Iec, core::Dialect::Codesys})
        m_dialectCombo->addItem(ExportOptionsDialog::dialectText(d), static_cast<int>(d));
    m_dialectCombo->setCurrentIndex(m_dialectCombo->findData(static_cast<int>(current.dialect)));
    m_dialectCombo->setToolTip(tr("The flavour of the generated Structured Text and its preview"));

    m_evolutionCombo->setObjectName("evolutionCombo");
    m_evolutionCombo->addItem(tr("One evolution per scan"), static_cast<int>(core::EvolutionRule::OneEvolutionPerScan));
    m_evolutionCombo->addItem(tr("Until stable"), static_cast<int>(core::EvolutionRule::UntilStable));
    m_evolutionCombo->setCurrentIndex(m_evolutionCombo->findData(static_cast<int>(current.evolution)));
    m_evolutionCombo->setToolTip(tr("How a nested GRAFCET evolves in one call of its function block"));
    m_evolutionDescription->setObjectName("evolutionDescription");
    m_evolutionDescription->setWordWrap(true);
    useSecondaryText(m_evolutionDescription);
    connect(m_evolutionCombo, &QComboBox::currentIndexChanged, this, &ModelSettingsDialog::updateEvolutionDescription);
    updateEvolutionDescription();

    m_defaultsCheck->setObjectName("defaultsCheck");
    m_defaultsCheck->setText(tr("Use the cycle time and dialect for &new models"));

    auto* form = new QFormLayout;
    form->addRow(tr("&Name:"), m_nameEdit);
    form->addRow(tr("PLC &cycle time:"), m_cycleTimeSpin);
    form->addRow(tr("&Dialect:"), m_dialectCombo);
    form->addRow(tr("&Evolution rule:"), m_evolutionCombo);
    form->addRow(QString(), m_evolutionDescription);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    if (document.model().packml()) {
        auto* group = new QGroupBox(tr("PackML"), this);
        auto* groupLayout = new QVBoxLayout(group);
        m_packmlSettings = new PackmlSettingsWidget(document, group);
        groupLayout->addWidget(m_packmlSettings);
        layout->addWidget(group);
    }
    layout->addWidget(m_defaultsCheck);
    layout->addWidget(buttons);
    setMinimumWidth(fontMetrics().averageCharWidth() * 60);
}

QString ModelSettingsDialog::evolutionRuleDescription(core::EvolutionRule rule)
{
    if (rule == core::EvolutionRule::UntilStable)
        return tr("Each scan repeats evolutions until no transition can fire (IEC 60848's search for stability), at "
                  "most one more than the GRAFCET has transitions; if the last one still fires, the function block "
                  "reports Unstable.");
    return tr("Each scan fires the transitions enabled at its start once, as SFC runtimes such as CODESYS do.");
}

void ModelSettingsDialog::updateEvolutionDescription()
{
    const auto rule = static_cast<core::EvolutionRule>(m_evolutionCombo->currentData().toInt());
    m_evolutionDescription->setText(evolutionRuleDescription(rule));
}

void ModelSettingsDialog::accept()
{
    apply();
    QDialog::accept();
}

void ModelSettingsDialog::apply()
{
    const core::ModelSettings& current = m_document.model().settings();
    const std::string name = m_nameEdit->text().trimmed().toStdString();
    const int cycleTime = m_cycleTimeSpin->value();
    const auto dialect = static_cast<core::Dialect>(m_dialectCombo->currentData().toInt());
    const auto evolution = static_cast<core::EvolutionRule>(m_evolutionCombo->currentData().toInt());

    std::vector<QUndoCommand*> commands;
    if (!name.empty() && name != current.name)
        commands.push_back(new SetModelNameCommand(m_document, QString::fromStdString(name)));
    if (cycleTime != current.cycleTimeMs)
        commands.push_back(new SetCycleTimeCommand(m_document, cycleTime));
    if (dialect != current.dialect)
        commands.push_back(new SetDialectCommand(m_document, dialect));
    if (evolution != current.evolution)
        commands.push_back(new SetEvolutionRuleCommand(m_document, evolution));
    if (m_packmlSettings) {
        const std::vector<QUndoCommand*> packml = m_packmlSettings->pendingCommands();
        commands.insert(commands.end(), packml.begin(), packml.end());
    }

    // One undo step for the whole dialog.
    QUndoStack* stack = m_document.undoStack();
    if (commands.size() > 1)
        beginWordedMacro(stack, [] { return tr("Change model settings"); });
    for (QUndoCommand* command : commands)
        m_document.push(command);
    if (commands.size() > 1)
        stack->endMacro();

    if (m_defaultsCheck->isChecked()) {
        m_settings.setDefaultCycleTimeMs(cycleTime);
        m_settings.setDefaultDialect(dialect);
    }
}

} // namespace editor
