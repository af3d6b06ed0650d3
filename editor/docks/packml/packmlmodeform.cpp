#include "editor/docks/packml/packmlmodeform.h"

#include "editor/commands/packml/packmlmodetextcommands.h"
#include "editor/commands/packml/setmodestatescommand.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/packml/packmldockparts.h"
#include "editor/docks/undoshortcutfilter.h"
#include "editor/document.h"
#include "editor/stdstring.h"
#include "editor/text/packmltexts.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlrules.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace editor {

namespace {

namespace packml = core::packml;

QString stateObjectName(const char* prefix, packml::State state)
{
    return QLatin1String(prefix) + toQString(packml::stateName(state));
}

void setCheckedQuietly(QCheckBox* check, bool checked)
{
    const QSignalBlocker blocker(check);
    check->setChecked(checked);
}

} // namespace

PackmlModeForm::PackmlModeForm(Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* fields = new QFormLayout;
    fields->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    m_nameEdit = new QLineEdit(this);
    m_nameEdit->setObjectName(QStringLiteral("nameEdit"));
    UndoShortcutFilter::install(m_nameEdit);
    // Committed as a whole: a name half typed may be taken or reserved.
    connect(m_nameEdit, &QLineEdit::editingFinished, this, &PackmlModeForm::onNameCommitted);
    m_nameLabel = new QLabel(this);
    m_nameLabel->setBuddy(m_nameEdit);
    fields->addRow(m_nameLabel, m_nameEdit);

    m_commentEdit = new QLineEdit(this);
    m_commentEdit->setObjectName(QStringLiteral("commentEdit"));
    UndoShortcutFilter::install(m_commentEdit);
    connect(m_commentEdit, &QLineEdit::textEdited, this, [this](const QString& text) {
        m_document->push(new SetModeCommentCommand(*m_document, m_mode, text));
    });
    m_commentLabel = new QLabel(this);
    m_commentLabel->setBuddy(m_commentEdit);
    fields->addRow(m_commentLabel, m_commentEdit);
    layout->addLayout(fields);

    m_requestLabel = new QLabel(this);
    layout->addWidget(m_requestLabel);
    m_requestEdit = new ConditionEdit(this);
    m_requestEdit->setObjectName(QStringLiteral("requestEdit"));
    m_requestLabel->setBuddy(m_requestEdit);
    connect(m_requestEdit, &ConditionEdit::textEdited, this, [this](const QString& text) {
        m_document->push(new SetModeRequestCommand(*m_document, m_mode, text));
    });
    layout->addWidget(m_requestEdit);
    m_problems = new DiagnosticList(this);
    m_problems->setObjectName(QStringLiteral("modeProblems"));
    m_problems->setDocument(m_document);
    layout->addWidget(m_problems);
    layout->addWidget(createStateLists());
    retranslate();
}

QWidget* PackmlModeForm::createStateLists()
{
    auto* lists = new QWidget(this);
    auto* layout = new QHBoxLayout(lists);
    layout->setContentsMargins(0, 0, 0, 0);

    m_disabledGroup = new QGroupBox(lists);
    m_disabledGroup->setObjectName(QStringLiteral("disabledGroup"));
    auto* disabledLayout = new QVBoxLayout(m_disabledGroup);
    disabledLayout->setSpacing(1);
    for (const packml::StateInfo& info : packml::states()) {
        auto* check = new QCheckBox(toQString(info.name), m_disabledGroup);
        check->setObjectName(stateObjectName("disabled_", info.state));
        const packml::State state = info.state;
        connect(check, &QCheckBox::toggled, this, [this, state] { onDisabledToggled(state); });
        disabledLayout->addWidget(check);
        m_disabledChecks.insert(state, check);
    }
    m_disabledHint = packmlHintLabel(m_disabledGroup);
    disabledLayout->addWidget(m_disabledHint);
    disabledLayout->addStretch();
    layout->addWidget(m_disabledGroup, 1);

    m_modeChangeGroup = new QGroupBox(lists);
    m_modeChangeGroup->setObjectName(QStringLiteral("modeChangeGroup"));
    auto* changeLayout = new QVBoxLayout(m_modeChangeGroup);
    changeLayout->setSpacing(1);
    for (const packml::StateInfo& info : packml::states()) {
        if (!packml::mayAllowModeChange(info.state))
            continue;
        auto* check = new QCheckBox(toQString(info.name), m_modeChangeGroup);
        check->setObjectName(stateObjectName("modeChange_", info.state));
        const packml::State state = info.state;
        connect(check, &QCheckBox::toggled, this, [this, state](bool on) { onModeChangeToggled(state, on); });
        changeLayout->addWidget(check);
        m_modeChangeChecks.insert(state, check);
    }
    changeLayout->addStretch();
    layout->addWidget(m_modeChangeGroup, 1);
    return lists;
}

void PackmlModeForm::retranslate()
{
    m_nameLabel->setText(tr("Name:"));
    m_nameEdit->setToolTip(tr("User modes (4 to 31) take an IEC identifier that no other mode has and the "
                              "generated code does not use; it becomes part of function block names.\nModes 1 "
                              "to 3 are Production, Maintenance and Manual."));
    m_commentLabel->setText(tr("Comment:"));
    m_commentEdit->setPlaceholderText(tr("What the unit does in this mode"));
    m_requestLabel->setText(tr("Request condition:"));
    m_requestEdit->setPlaceholderText(tr("None: requested through UnitMode only (e.g. KeyManual)"));
    m_requestEdit->setToolTip(tr("Requests this mode at its rising edge, as a rising edge of "
                                 "UnitModeChangeRequest with UnitMode set to its number does."));
    m_disabledGroup->setTitle(tr("Disabled states"));
    m_disabledHint->setText(tr("Stopped, Idle, Execute and Aborted are never disabled. Disabling Held, Suspended "
                               "or Complete disables the acting states of its loop; enabling one of those "
                               "enables it again."));
    m_modeChangeGroup->setTitle(tr("Mode change allowed in"));
    m_modeChangeGroup->setToolTip(tr("A change to or from this mode is granted in a state that both modes "
                                     "list and the requested mode enables."));
}

void PackmlModeForm::setMode(int number)
{
    m_mode = number;
    refresh();
}

void PackmlModeForm::refresh()
{
    const packml::Configuration* configuration = m_document->model().packml();
    if (!configuration || !configuration->mode(m_mode))
        return;
    refreshName();
    refreshRequest();
    refreshStateLists();
}

void PackmlModeForm::refreshName()
{
    const packml::Mode& mode = *m_document->model().packml()->mode(m_mode);
    const QString name = toQString(mode.displayName());
    if (m_nameEdit->text() != name && !m_nameEdit->isModified()) { // not over the user's typing
        const QSignalBlocker blocker(m_nameEdit);
        m_nameEdit->setText(name);
    }
    m_nameEdit->setReadOnly(m_mode < packml::kFirstUserMode);
    const QString comment = toQString(mode.comment);
    if (m_commentEdit->text() != comment) {
        const QSignalBlocker blocker(m_commentEdit);
        m_commentEdit->setText(comment);
    }
}

void PackmlModeForm::refreshRequest()
{
    const packml::Mode& mode = *m_document->model().packml()->mode(m_mode);
    const QString request = toQString(mode.request);
    m_requestEdit->setText(request);
    m_requestEdit->setVariableNames(declaredVariableNames(m_document->model()));
    const std::vector<core::Diagnostic> diagnostics = m_document->diagnosticsFor(ElementRef::packmlMode(m_mode));
    m_requestEdit->setProblems(conditionProblems(request, diagnostics));
    m_problems->setDiagnostics(diagnostics);
}

void PackmlModeForm::refreshStateLists()
{
    const packml::Configuration& configuration = *m_document->model().packml();
    const packml::Mode& mode = *configuration.mode(m_mode);
    const packml::StateSet enabled = packml::enabledStates(mode.disabled).enabled;
    // The 2022 edition displays state 17 as "Completed" (spec §2.1).
    const QString complete = configuration.options.edition == packml::Edition::Y2022 ? QStringLiteral("Completed")
                                                                                   : QStringLiteral("Complete");
    m_disabledChecks.value(packml::State::Complete)->setText(complete);
    m_modeChangeChecks.value(packml::State::Complete)->setText(complete);
    for (auto it = m_disabledChecks.begin(); it != m_disabledChecks.end(); ++it) {
        setCheckedQuietly(it.value(), !enabled.contains(it.key()));
        it.value()->setEnabled(packml::stateInfo(it.key()).mayBeDisabled);
        it.value()->setToolTip(packmltext::stateMeaning(it.key()));
    }
    for (auto it = m_modeChangeChecks.begin(); it != m_modeChangeChecks.end(); ++it) {
        const bool allowed = mode.modeChange.contains(it.key());
        setCheckedQuietly(it.value(), allowed);
        const bool stateEnabled = enabled.contains(it.key());
        // Greyed where it can have no effect, yet still unchecked when listed.
        it.value()->setEnabled(stateEnabled || allowed);
        it.value()->setToolTip(stateEnabled ? QString()
                                            : tr("%1 is disabled in this mode: no change can be granted there.")
                                                  .arg(toQString(packml::stateName(it.key()))));
    }
}

void PackmlModeForm::focusField(const QString& field)
{
    if (field == QLatin1String("name") || field == QLatin1String("number"))
        m_nameEdit->setFocus(Qt::OtherFocusReason);
    else if (field == QLatin1String("comment"))
        m_commentEdit->setFocus(Qt::OtherFocusReason);
    else if (field == QLatin1String("disabled"))
        m_disabledGroup->setFocus(Qt::OtherFocusReason);
    else if (field == QLatin1String("modeChange"))
        m_modeChangeGroup->setFocus(Qt::OtherFocusReason);
    else if (field == QLatin1String("condition")) {
        const QList<ConditionEdit::Problem>& problems = m_requestEdit->problems();
        const int end = static_cast<int>(m_requestEdit->text().size());
        if (problems.isEmpty())
            m_requestEdit->selectRange(end, end);
        else
            m_requestEdit->selectRange(problems.front().begin, problems.front().end);
    }
}

void PackmlModeForm::onNameCommitted()
{
    const packml::Mode* mode = m_document->model().packml() ? m_document->model().packml()->mode(m_mode) : nullptr;
    if (!mode || m_mode < packml::kFirstUserMode || m_nameEdit->text() == toQString(mode->name)) {
        m_nameEdit->setModified(false);
        return;
    }
    m_document->push(new RenameModeCommand(*m_document, m_mode, m_nameEdit->text()));
    // Refused, editFailed said why and the model's name comes back.
    const QSignalBlocker blocker(m_nameEdit);
    m_nameEdit->setText(toQString(m_document->model().packml()->mode(m_mode)->displayName()));
}

void PackmlModeForm::onDisabledToggled(packml::State state)
{
    const packml::Mode* mode = m_document->model().packml()->mode(m_mode);
    const packml::StateSet listing = packml::consistentListing(mode->disabled, state);
    m_document->push(new SetModeStatesCommand(*m_document, m_mode, SetModeStatesCommand::List::Disabled, listing));
    refreshStateLists(); // a refused or empty change puts the box back
}

void PackmlModeForm::onModeChangeToggled(packml::State state, bool allowed)
{
    packml::StateSet states = m_document->model().packml()->mode(m_mode)->modeChange;
    if (allowed)
        states.insert(state);
    else
        states.erase(state);
    m_document->push(new SetModeStatesCommand(*m_document, m_mode, SetModeStatesCommand::List::ModeChange, states));
    refreshStateLists();
}

} // namespace editor
