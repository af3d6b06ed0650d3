#include "editor/docks/packml/packmlmodesdock.h"

#include "editor/chart/packml/packmlcharttexts.h"
#include "editor/commands/packml/addmodecommand.h"
#include "editor/commands/packml/packmlsettingscommands.h"
#include "editor/commands/packml/removemodecommand.h"
#include "editor/docks/dockreveal.h"
#include "editor/docks/packml/packmldockparts.h"
#include "editor/docks/packml/packmlmodeform.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"

#include "core/model/model.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace editor {

namespace {

namespace packml = core::packml;

} // namespace

QString PackmlModesDock::title()
{
    return tr("Modes");
}

PackmlModesDock::PackmlModesDock(Document* document, Selection* selection, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_document(document)
    , m_selection(selection)
{
    setObjectName(QStringLiteral("packmlModesDock"));
    m_pages = new QStackedWidget(this);
    m_notPackml = packmlHintLabel(m_pages);
    m_notPackml->setObjectName(QStringLiteral("notPackml"));
    m_notPackml->setAlignment(Qt::AlignCenter);
    m_notPackml->setMargin(12);
    m_pages->addWidget(m_notPackml);
    auto* scroll = new QScrollArea(m_pages);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(createPage());
    m_pages->addWidget(scroll);
    setWidget(m_pages);

    connect(m_document, &Document::modelReset, this, &PackmlModesDock::refresh);
    connect(m_document, &Document::modesChanged, this, &PackmlModesDock::refresh);
    connect(m_document, &Document::modeChanged, this, &PackmlModesDock::refresh);
    connect(m_document, &Document::packmlSettingsChanged, this, &PackmlModesDock::refresh);
    connect(m_document, &Document::diagnosticsChanged, this, &PackmlModesDock::refresh);
    connect(m_document, &Document::variablesChanged, this, &PackmlModesDock::refresh);
    connect(m_selection, &Selection::changed, this, &PackmlModesDock::onSelectionChanged);
    connect(m_selection, &Selection::focusFieldRequested, this, &PackmlModesDock::onFocusFieldRequested);
    retranslate();
    refresh();
}

QWidget* PackmlModesDock::createPage()
{
    auto* page = new QWidget;
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(6, 6, 6, 6);

    m_list = new QListWidget(page);
    m_list->setObjectName(QStringLiteral("modeList"));
    m_list->setMaximumHeight(m_list->fontMetrics().height() * 8);
    connect(m_list, &QListWidget::currentRowChanged, this, &PackmlModesDock::onRowChanged);
    layout->addWidget(m_list);

    auto* buttons = new QHBoxLayout;
    m_numberSpin = new QSpinBox(page);
    m_numberSpin->setObjectName(QStringLiteral("newModeNumber"));
    m_numberSpin->setRange(packml::kFirstUserMode, packml::kMaxModeNumber);
    connect(m_numberSpin, &QSpinBox::valueChanged, this, &PackmlModesDock::refreshButtons);
    m_addButton = new QPushButton(page);
    m_addButton->setObjectName(QStringLiteral("addModeButton"));
    connect(m_addButton, &QPushButton::clicked, this, &PackmlModesDock::onAdd);
    m_removeButton = new QPushButton(page);
    m_removeButton->setObjectName(QStringLiteral("removeModeButton"));
    connect(m_removeButton, &QPushButton::clicked, this, &PackmlModesDock::onRemove);
    buttons->addWidget(m_numberSpin);
    buttons->addWidget(m_addButton);
    buttons->addWidget(m_removeButton);
    buttons->addStretch();
    layout->addLayout(buttons);

    auto* initial = new QHBoxLayout;
    m_initialLabel = new QLabel(page);
    m_initialCombo = new QComboBox(page);
    m_initialCombo->setObjectName(QStringLiteral("initialModeCombo"));
    m_initialLabel->setBuddy(m_initialCombo);
    connect(m_initialCombo, &QComboBox::activated, this, &PackmlModesDock::onInitialModeChosen);
    initial->addWidget(m_initialLabel);
    initial->addWidget(m_initialCombo, 1);
    layout->addLayout(initial);

    m_formTitle = new QLabel(page);
    m_formTitle->setObjectName(QStringLiteral("modeTitle"));
    QFont titleFont = m_formTitle->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.2);
    m_formTitle->setFont(titleFont);
    layout->addWidget(m_formTitle);
    m_form = new PackmlModeForm(m_document, page);
    layout->addWidget(m_form);
    layout->addStretch();
    return page;
}

void PackmlModesDock::retranslate()
{
    setWindowTitle(title());
    m_notPackml->setText(tr("Unit modes belong to PackML models: this model follows GEMMA."));
    m_numberSpin->setToolTip(tr("The number of the next user mode (PackTags UnitMode)"));
    m_addButton->setText(tr("&Add Mode"));
    m_addButton->setToolTip(tr("Adds a user mode with this number: every state enabled, mode changes in "
                               "Stopped, Idle and Aborted"));
    m_removeButton->setText(tr("&Remove"));
    m_initialLabel->setText(tr("&Initial mode:"));
    m_initialCombo->setToolTip(tr("The mode the unit is in at power-up"));
    m_form->retranslate();
    refreshButtons();
}

void PackmlModesDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

int PackmlModesDock::currentMode() const
{
    return m_document->model().packml() ? m_form->mode() : 0;
}

void PackmlModesDock::refresh()
{
    const packml::Configuration* configuration = m_document->model().packml();
    m_pages->setCurrentIndex(configuration ? 1 : 0);
    if (!configuration)
        return;
    int shown = m_form->mode();
    if (!configuration->mode(shown))
        shown = configuration->mode(configuration->initialMode) ? configuration->initialMode
                                                                : configuration->modes.front().number;
    refreshList();
    refreshInitialMode();
    showMode(shown);
}

void PackmlModesDock::refreshList()
{
    const packml::Configuration& configuration = *m_document->model().packml();
    const QSignalBlocker blocker(m_list);
    m_list->clear();
    for (const packml::Mode& mode : configuration.modes) {
        auto* item = new QListWidgetItem(PackmlChartTexts::modeTitle(mode), m_list);
        item->setData(Qt::UserRole, mode.number);
        item->setToolTip(toQString(mode.comment));
        if (m_document->hasProblems(ElementRef::packmlMode(mode.number)))
            item->setForeground(Qt::red);
    }
}

void PackmlModesDock::refreshInitialMode()
{
    const packml::Configuration& configuration = *m_document->model().packml();
    const QSignalBlocker blocker(m_initialCombo);
    m_initialCombo->clear();
    for (const packml::Mode& mode : configuration.modes)
        m_initialCombo->addItem(PackmlChartTexts::modeTitle(mode), mode.number);
    m_initialCombo->setCurrentIndex(m_initialCombo->findData(configuration.initialMode));
}

void PackmlModesDock::refreshButtons()
{
    const packml::Configuration* configuration = m_document->model().packml();
    if (!configuration)
        return;
    const int free = AddModeCommand::firstFreeUserMode(m_document->model());
    m_addButton->setEnabled(free != 0 && !configuration->mode(m_numberSpin->value()));
    m_numberSpin->setEnabled(free != 0);
    m_removeButton->setEnabled(m_form->mode() != 1 && configuration->mode(m_form->mode()));
    m_removeButton->setToolTip(m_form->mode() == 1 ? tr("Production is the mode every unit has")
                                                   : tr("Removes the mode with its GRAFCETs"));
}

void PackmlModesDock::showMode(int number)
{
    const packml::Mode* mode = m_document->model().packml()->mode(number);
    if (!mode)
        return;
    m_form->setMode(number);
    m_formTitle->setText(PackmlChartTexts::modeTitle(*mode));
    for (int row = 0; row < m_list->count(); ++row) {
        if (m_list->item(row)->data(Qt::UserRole).toInt() == number) {
            const QSignalBlocker blocker(m_list);
            m_list->setCurrentRow(row);
        }
    }
    const int free = AddModeCommand::firstFreeUserMode(m_document->model());
    if (free != 0 && m_document->model().packml()->mode(m_numberSpin->value())) {
        const QSignalBlocker blocker(m_numberSpin);
        m_numberSpin->setValue(free);
    }
    refreshButtons();
}

void PackmlModesDock::onRowChanged(int row)
{
    if (row < 0)
        return;
    const int number = m_list->item(row)->data(Qt::UserRole).toInt();
    showMode(number);
    m_selection->select(ElementRef::packmlMode(number));
}

void PackmlModesDock::onAdd()
{
    const int number = m_numberSpin->value();
    const QString name = AddModeCommand::suggestedName(m_document->model(), number);
    if (m_document->push(new AddModeCommand(*m_document, number, name))) {
        showMode(number);
        m_selection->select(ElementRef::packmlMode(number), QStringLiteral("name"));
    }
}

void PackmlModesDock::onRemove()
{
    m_document->push(new RemoveModeCommand(*m_document, m_form->mode()));
}

void PackmlModesDock::onInitialModeChosen(int index)
{
    m_document->push(new SetPackmlInitialModeCommand(*m_document, m_initialCombo->itemData(index).toInt()));
}

void PackmlModesDock::onSelectionChanged(const ElementRef& element)
{
    // A state or transition picked on the chart names the mode the chart shows.
    const bool namesMode = element.kind == ElementRef::Kind::PackmlMode
        || element.kind == ElementRef::Kind::PackmlState || element.kind == ElementRef::Kind::PackmlTransition;
    const packml::Configuration* configuration = m_document->model().packml();
    if (!configuration || !namesMode || !configuration->mode(element.number))
        return;
    showMode(element.number);
}

void PackmlModesDock::onFocusFieldRequested(const ElementRef& element, const QString& field)
{
    const packml::Configuration* configuration = m_document->model().packml();
    if (!configuration || element.kind != ElementRef::Kind::PackmlMode || !configuration->mode(element.number))
        return;
    showMode(element.number);
    revealDock(this);
    m_form->focusField(field);
}

} // namespace editor
