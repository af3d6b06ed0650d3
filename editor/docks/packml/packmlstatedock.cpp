#include "editor/docks/packml/packmlstatedock.h"

#include "editor/chart/packml/packmlcharttexts.h"
#include "editor/commands/packml/setgrafcetchoicecommand.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/dockreveal.h"
#include "editor/docks/packml/packmldockparts.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/text/packmltexts.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlrules.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace editor {

namespace {

namespace packml = core::packml;
using packml::GrafcetChoice;

// The combo's items carry the choice: None, Own, or a mode number for "same as".
constexpr int kNoneItem = -1;
constexpr int kOwnItem = 0;

int itemData(const GrafcetChoice& choice)
{
    switch (choice.kind) {
    case GrafcetChoice::Kind::Own: return kOwnItem;
    case GrafcetChoice::Kind::SameAs: return choice.sameAsMode;
    case GrafcetChoice::Kind::None: break;
    }
    return kNoneItem;
}

GrafcetChoice choiceOf(int data)
{
    if (data == kNoneItem)
        return GrafcetChoice::none();
    return data == kOwnItem ? GrafcetChoice::own() : GrafcetChoice::sameAs(data);
}

} // namespace

QString PackmlStateDock::title()
{
    return tr("State");
}

PackmlStateDock::PackmlStateDock(Document* document, Selection* selection, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_document(document)
    , m_selection(selection)
{
    setObjectName(QStringLiteral("packmlStateDock"));
    m_pages = new QStackedWidget(this);
    m_placeholder = packmlHintLabel(m_pages);
    m_placeholder->setObjectName(QStringLiteral("placeholder"));
    m_placeholder->setAlignment(Qt::AlignCenter);
    m_placeholder->setMargin(12);
    m_pages->addWidget(m_placeholder);
    auto* scroll = new QScrollArea(m_pages);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(createForm());
    m_pages->addWidget(scroll);
    setWidget(m_pages);

    connect(m_document, &Document::modelReset, this, &PackmlStateDock::refresh);
    connect(m_document, &Document::modesChanged, this, &PackmlStateDock::refresh);
    connect(m_document, &Document::modeChanged, this, &PackmlStateDock::refresh);
    connect(m_document, &Document::packmlSettingsChanged, this, &PackmlStateDock::refresh);
    connect(m_document, &Document::diagnosticsChanged, this, &PackmlStateDock::refresh);
    connect(m_selection, &Selection::changed, this, &PackmlStateDock::onSelectionChanged);
    connect(m_selection, &Selection::focusFieldRequested, this, &PackmlStateDock::onFocusFieldRequested);
    retranslate();
    onSelectionChanged(m_selection->current());
}

QWidget* PackmlStateDock::createForm()
{
    auto* form = new QWidget;
    auto* layout = new QVBoxLayout(form);
    layout->setContentsMargins(6, 6, 6, 6);
    m_titleLabel = new QLabel(form);
    m_titleLabel->setObjectName(QStringLiteral("stateTitle"));
    QFont titleFont = m_titleLabel->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.3);
    m_titleLabel->setFont(titleFont);
    layout->addWidget(m_titleLabel);
    m_kindLabel = new QLabel(form);
    m_kindLabel->setObjectName(QStringLiteral("stateKind"));
    layout->addWidget(m_kindLabel);
    m_meaningLabel = packmlHintLabel(form);
    m_meaningLabel->setObjectName(QStringLiteral("stateMeaning"));
    layout->addWidget(m_meaningLabel);
    m_problems = new DiagnosticList(form);
    m_problems->setObjectName(QStringLiteral("stateProblems"));
    m_problems->setDocument(m_document);
    layout->addWidget(m_problems);

    m_grafcetGroup = new QGroupBox(form);
    m_grafcetGroup->setObjectName(QStringLiteral("grafcetGroup"));
    auto* groupLayout = new QVBoxLayout(m_grafcetGroup);
    m_grafcetHint = packmlHintLabel(m_grafcetGroup);
    m_grafcetHint->setObjectName(QStringLiteral("grafcetHint"));
    groupLayout->addWidget(m_grafcetHint);
    m_grafcetGrid = new QGridLayout;
    groupLayout->addLayout(m_grafcetGrid);
    layout->addWidget(m_grafcetGroup);
    layout->addStretch();
    return form;
}

void PackmlStateDock::retranslate()
{
    setWindowTitle(title());
    m_placeholder->setText(tr("Select a state in the PackML chart to see what it means and what runs in it."));
    m_grafcetGroup->setTitle(tr("Nested GRAFCET per mode"));
}

void PackmlStateDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        refresh();
    }
    QDockWidget::changeEvent(event);
}

void PackmlStateDock::onSelectionChanged(const ElementRef& element)
{
    if (element.kind != ElementRef::Kind::PackmlState)
        return; // keeps the state shown while a command or a mode is worked on
    m_state = element.id;
    m_selectedMode = element.number;
    refresh();
    if (!m_state.isEmpty())
        raiseOverPropertySibling(this);
}

// "grafcet" (the chart's Choose Its GRAFCET): the choice of the mode the
// state was picked in, in front and focused.
void PackmlStateDock::onFocusFieldRequested(const ElementRef& element, const QString& field)
{
    if (element.kind != ElementRef::Kind::PackmlState || field != QLatin1String("grafcet"))
        return;
    onSelectionChanged(element);
    for (const ModeRow& row : std::as_const(m_modeRows)) {
        if (row.mode == element.number && row.choice) {
            revealDock(this);
            row.choice->setFocus(Qt::OtherFocusReason);
            return;
        }
    }
}

void PackmlStateDock::refresh()
{
    const packml::Configuration* configuration = m_document->model().packml();
    const auto state = packml::findState(m_state.toStdString());
    if (!configuration || !state) {
        m_pages->setCurrentIndex(0);
        clearModeRows();
        return;
    }
    m_pages->setCurrentIndex(1);
    refreshHeader(*state);
    m_problems->setDiagnostics(m_document->diagnosticsFor(ElementRef::packmlState(m_state)));
    refreshGrafcets(*state);
}

void PackmlStateDock::refreshHeader(packml::State state)
{
    const packml::Configuration& configuration = *m_document->model().packml();
    const bool completed = state == packml::State::Complete && configuration.options.edition == packml::Edition::Y2022;
    const QString name = completed ? QStringLiteral("Completed") : packmltext::stateName(state); // spec §2.1
    //: a PackML state's title: its PackTags number and name, "6 Execute"
    m_titleLabel->setText(tr("%1 %2").arg(static_cast<int>(state)).arg(name));
    m_kindLabel->setText(packmltext::stateKindName(packml::stateInfo(state).kind));
    m_meaningLabel->setText(packmltext::stateMeaning(state));
}

void PackmlStateDock::clearModeRows()
{
    for (ModeRow& row : m_modeRows) {
        for (QWidget* widget : {static_cast<QWidget*>(row.label), static_cast<QWidget*>(row.choice),
                                static_cast<QWidget*>(row.open)}) {
            m_grafcetGrid->removeWidget(widget);
            widget->hide();
            widget->setParent(nullptr);
            widget->deleteLater(); // a combo may be the one whose activation led here
        }
    }
    m_modeRows.clear();
}

void PackmlStateDock::refreshGrafcets(packml::State state)
{
    clearModeRows();
    const bool holds = packml::holdsGrafcet(state);
    m_grafcetHint->setText(holds ? tr("Own: a nested GRAFCET for this mode; Same as: the one of another mode; "
                                      "None: the state's skeleton (%1).")
                                       .arg(state == packml::State::Execute
                                                ? tr("Execute waits for a command")
                                                : tr("the state completes at once"))
                                 : tr("A wait state runs no GRAFCET."));
    if (!holds)
        return;
    const packml::Configuration& configuration = *m_document->model().packml();
    std::vector<const packml::Mode*> modes;
    if (const packml::Mode* selected = configuration.mode(m_selectedMode))
        modes.push_back(selected); // the mode the state was picked in comes first
    for (const packml::Mode& mode : configuration.modes)
        if (mode.number != m_selectedMode)
            modes.push_back(&mode);
    for (const packml::Mode* mode : modes) {
        ModeRow row;
        row.mode = mode->number;
        row.label = new QLabel(PackmlChartTexts::modeTitle(*mode), m_grafcetGroup);
        QFont font = row.label->font();
        font.setBold(mode->number == m_selectedMode);
        row.label->setFont(font);
        row.choice = new QComboBox(m_grafcetGroup);
        row.choice->setObjectName(QStringLiteral("choice_%1").arg(mode->number));
        // "Same as 12 Changeover" may be wider than a dock: the combo narrows, its popup does not.
        row.choice->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        row.choice->setMinimumContentsLength(8);
        row.label->setBuddy(row.choice);
        row.open = new QPushButton(tr("Open GRAFCET"), m_grafcetGroup);
        row.open->setObjectName(QStringLiteral("open_%1").arg(mode->number));
        const int number = mode->number;
        connect(row.choice, &QComboBox::activated, this, [this, number](int index) { onChoiceActivated(number, index); });
        connect(row.open, &QPushButton::clicked, this, [this, number] { onOpen(number); });
        fillChoice(row, state);
        const int line = static_cast<int>(m_modeRows.size());
        m_grafcetGrid->addWidget(row.label, line, 0);
        m_grafcetGrid->addWidget(row.choice, line, 1);
        m_grafcetGrid->addWidget(row.open, line, 2);
        m_grafcetGrid->setColumnStretch(1, 1);
        m_modeRows << row;
    }
}

void PackmlStateDock::fillChoice(ModeRow& row, packml::State state)
{
    const packml::Configuration& configuration = *m_document->model().packml();
    const packml::Mode& mode = *configuration.mode(row.mode);
    const GrafcetChoice& current = mode.grafcetChoice(state);
    row.choice->addItem(tr("None (skeleton)"), kNoneItem);
    row.choice->addItem(tr("Own GRAFCET"), kOwnItem);
    // "Same as k" names k's own GRAFCET: no chains (spec §4).
    for (const packml::Mode& other : configuration.modes)
        if (other.number != mode.number && other.grafcetChoice(state).kind == GrafcetChoice::Kind::Own)
            row.choice->addItem(tr("Same as %1").arg(PackmlChartTexts::modeTitle(other)), other.number);
    int index = row.choice->findData(itemData(current));
    if (index < 0) { // a "same as" kept as written that names no usable GRAFCET (PM015)
        row.choice->addItem(tr("Same as mode %1 (no GRAFCET there)").arg(current.sameAsMode), current.sameAsMode);
        index = row.choice->count() - 1;
    }
    row.choice->setCurrentIndex(index);
    const bool disabled = mode.disabled.contains(state);
    row.choice->setEnabled(!disabled || current.kind != GrafcetChoice::Kind::None);
    row.choice->setToolTip(disabled ? tr("%1 is disabled in this mode: nothing runs there.")
                                          .arg(packmltext::stateName(state))
                                    : QString());
    const std::string key = packml::grafcetKey(row.mode, state);
    row.open->setEnabled(m_document->model().effectiveGrafcet(key) != nullptr
                         || (current.kind == GrafcetChoice::Kind::Own));
}

void PackmlStateDock::onChoiceActivated(int mode, int index)
{
    const auto state = packml::findState(m_state.toStdString());
    ModeRow* row = nullptr;
    for (ModeRow& candidate : m_modeRows)
        if (candidate.mode == mode)
            row = &candidate;
    if (!state || !row)
        return;
    const GrafcetChoice choice = choiceOf(row->choice->itemData(index).toInt());
    if (!m_document->push(new SetGrafcetChoiceCommand(*m_document, mode, *state, choice)))
        refresh(); // refused: the combo shows the model again
}

void PackmlStateDock::onOpen(int mode)
{
    const auto state = packml::findState(m_state.toStdString());
    const packml::Configuration* configuration = m_document->model().packml();
    const packml::Mode* shown = configuration ? configuration->mode(mode) : nullptr;
    if (!state || !shown)
        return;
    const GrafcetChoice& choice = shown->grafcetChoice(*state);
    const int owner = choice.kind == GrafcetChoice::Kind::SameAs ? choice.sameAsMode : mode;
    emit openGrafcetRequested(QString::fromStdString(packml::grafcetKey(owner, *state)));
}

} // namespace editor
