#include "editor/window/packmlsettingswidget.h"

#include "editor/commands/packml/packmlsettingscommands.h"
#include "editor/document.h"
#include "editor/style/secondarytext.h"
#include "editor/text/packmltexts.h"

#include "core/model/model.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

namespace editor {

namespace {

namespace packml = core::packml;

packml::Options optionsOf(const QComboBox* edition, const QCheckBox* hold, const QCheckBox* complete)
{
    packml::Options options;
    options.edition = static_cast<packml::Edition>(edition->currentData().toInt());
    options.holdInSuspended = hold->isChecked();
    options.completeInSuspendedHeld = complete->isChecked();
    return options;
}

} // namespace

PackmlSettingsWidget::PackmlSettingsWidget(Document& document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_editionCombo(new QComboBox(this))
    , m_holdInSuspendedCheck(new QCheckBox(this))
    , m_completeInSuspendedHeldCheck(new QCheckBox(this))
    , m_initialStateCombo(new QComboBox(this))
    , m_editionHint(new QLabel(this))
{
    setObjectName(QStringLiteral("packmlSettings"));
    const packml::Configuration& configuration = *document.model().packml();

    m_editionCombo->setObjectName(QStringLiteral("editionCombo"));
    m_editionCombo->addItem(QStringLiteral("ISA-TR88.00.02-2015"), static_cast<int>(packml::Edition::Y2015));
    m_editionCombo->addItem(QStringLiteral("ISA-TR88.00.02-2022"), static_cast<int>(packml::Edition::Y2022));
    m_editionCombo->setCurrentIndex(m_editionCombo->findData(static_cast<int>(configuration.options.edition)));
    connect(m_editionCombo, &QComboBox::activated, this, &PackmlSettingsWidget::onEditionChosen);
    m_editionHint->setObjectName(QStringLiteral("editionHint"));
    m_editionHint->setWordWrap(true);
    useSecondaryText(m_editionHint);

    m_holdInSuspendedCheck->setObjectName(QStringLiteral("holdInSuspendedCheck"));
    m_holdInSuspendedCheck->setText(tr("&Hold accepted in Suspended"));
    m_holdInSuspendedCheck->setToolTip(tr("Suspended → Holding on Hold, an optional transition of the 2015 "
                                          "model and a standard one of 2022"));
    m_holdInSuspendedCheck->setChecked(configuration.options.holdInSuspended);
    m_completeInSuspendedHeldCheck->setObjectName(QStringLiteral("completeInSuspendedHeldCheck"));
    m_completeInSuspendedHeldCheck->setText(tr("C&omplete accepted in Suspended and Held"));
    m_completeInSuspendedHeldCheck->setToolTip(tr("Suspended and Held → Completing on the Complete command "
                                                  "(2022 edition only)"));
    m_completeInSuspendedHeldCheck->setChecked(configuration.options.completeInSuspendedHeld);
    connect(m_completeInSuspendedHeldCheck, &QCheckBox::toggled, this, &PackmlSettingsWidget::updateOptionStates);

    m_initialStateCombo->setObjectName(QStringLiteral("initialStateCombo"));
    for (packml::State state : {packml::State::Stopped, packml::State::Idle, packml::State::Aborted})
        m_initialStateCombo->addItem(packmltext::stateName(state), static_cast<int>(state));
    int index = m_initialStateCombo->findData(static_cast<int>(configuration.initialState));
    if (index < 0) { // kept as written in the file (PM003)
        m_initialStateCombo->addItem(packmltext::stateName(configuration.initialState),
                                     static_cast<int>(configuration.initialState));
        index = m_initialStateCombo->count() - 1;
    }
    m_initialStateCombo->setCurrentIndex(index);
    m_initialStateCombo->setToolTip(tr("The state at power-up: Stopped as usual, Aborted for a unit that must be "
                                       "cleared after a power loss, Idle for one with nothing to reset"));

    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("PackML &edition:"), m_editionCombo);
    form->addRow(QString(), m_editionHint);
    form->addRow(QString(), m_holdInSuspendedCheck);
    form->addRow(QString(), m_completeInSuspendedHeldCheck);
    form->addRow(tr("Initial &state:"), m_initialStateCombo);
    updateOptionStates();
}

void PackmlSettingsWidget::onEditionChosen()
{
    const auto edition = static_cast<packml::Edition>(m_editionCombo->currentData().toInt());
    const packml::Options defaults = packml::defaultOptions(edition);
    m_holdInSuspendedCheck->setChecked(defaults.holdInSuspended);
    m_completeInSuspendedHeldCheck->setChecked(defaults.completeInSuspendedHeld);
    updateOptionStates();
}

void PackmlSettingsWidget::updateOptionStates()
{
    const bool is2022 = m_editionCombo->currentData().toInt() == static_cast<int>(packml::Edition::Y2022);
    // A 2015 model that has it set (PM017) can still clear it.
    m_completeInSuspendedHeldCheck->setEnabled(is2022 || m_completeInSuspendedHeldCheck->isChecked());
    m_editionHint->setText(is2022 ? tr("2022: Execute is left on the Complete command, which a new model "
                                       "conditions on Cmd_Complete; its State Complete leads nowhere.")
                                  : tr("2015: Execute's State Complete leads to Completing; there is no "
                                       "Complete command."));
}

std::vector<QUndoCommand*> PackmlSettingsWidget::pendingCommands() const
{
    std::vector<QUndoCommand*> commands;
    const packml::Configuration* configuration = m_document.model().packml();
    if (!configuration)
        return commands;
    const packml::Options options
        = optionsOf(m_editionCombo, m_holdInSuspendedCheck, m_completeInSuspendedHeldCheck);
    if (!(options == configuration->options))
        commands.push_back(new SetPackmlOptionsCommand(m_document, options));
    const auto state = static_cast<packml::State>(m_initialStateCombo->currentData().toInt());
    if (state != configuration->initialState)
        commands.push_back(new SetPackmlInitialStateCommand(m_document, state));
    return commands;
}

} // namespace editor
