#include "editor/docks/gemma/transitiondock.h"

#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setnegatedcommand.h"
#include "editor/commands/setprioritycommand.h"
#include "editor/commands/settokenscommand.h"
#include "editor/commands/settransitionhiddencommand.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/undoshortcutfilter.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/secondarytext.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/gemmastatenames.h"

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {

namespace {

QLabel* hintLabel(QWidget* parent)
{
    auto* label = new WrappingLabel(parent);
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    label->setFont(font);
    useSecondaryText(label);
    return label;
}

// How a BOOL variable occurs in a condition, for its token's polarity (spec §6.4).
struct VariableUse {
    std::string name; // as declared
    bool normallyOpen = false;
    bool normallyClosed = false;
    bool compared = false; // an operand of = or <>: no polarity
};

bool isVariableNode(const core::cond::Expression& expression, int index, const std::string& name)
{
    const core::cond::Node& node = expression.at(index);
    if (node.kind == core::cond::NodeKind::Unary && node.unaryOp == core::cond::UnaryOp::Not)
        return isVariableNode(expression, node.operand, name);
    return node.kind == core::cond::NodeKind::Variable && core::equalsIgnoreCase(node.text, name);
}

std::vector<VariableUse> boolVariableUses(const core::Model& model, const core::cond::Expression& expression)
{
    std::vector<VariableUse> uses;
    for (const core::cond::Literal& literal : core::cond::booleanLiterals(expression)) {
        const core::Variable* variable = model.variable(expression.at(literal.variableNode).text);
        if (!variable || variable->type != core::IecType::Bool)
            continue;
        auto use
            = std::find_if(uses.begin(), uses.end(), [&](const VariableUse& u) { return u.name == variable->name; });
        if (use == uses.end())
            use = uses.insert(uses.end(), VariableUse { variable->name });
        (literal.negated ? use->normallyClosed : use->normallyOpen) = true;
    }
    for (const core::cond::Node& node : expression.nodes) {
        const bool comparison = node.kind == core::cond::NodeKind::Binary
            && (node.binaryOp == core::cond::BinaryOp::Equal || node.binaryOp == core::cond::BinaryOp::NotEqual);
        if (!comparison)
            continue;
        for (VariableUse& use : uses) {
            if (isVariableNode(expression, node.left, use.name) || isVariableNode(expression, node.right, use.name))
                use.compared = true;
        }
    }
    return uses;
}

bool hasToken(const core::Transition& transition, const std::string& name)
{
    return std::any_of(transition.tokens.begin(), transition.tokens.end(),
        [&](const std::string& token) { return core::equalsIgnoreCase(token, name); });
}

} // namespace

QString TransitionDock::title()
{
    return tr("Transition");
}

TransitionDock::TransitionDock(Document* document, Selection* selection, QWidget* parent)
    : PropertyDock(ElementRef::Kind::Transition, title(), document, selection, parent)
{
    setObjectName(QStringLiteral("transitionDock"));
    // The condition checks and the tokens depend on the declared variables.
    refreshOnVariableChanges();
    setPages(scrolling(createForm()));
    retranslate();
}

void TransitionDock::retranslate()
{
    setWindowTitle(title());
    setPlaceholder(tr("Select a transition in the chart to see and edit its condition."));
    m_titleLabel->setToolTip(tr("Click a step to select it"));
    m_conditionLabel->setText(tr("C&ondition:"));
    m_conditionEdit->setPlaceholderText(tr("e.g. Start AND NOT Stop"));
    m_conditionEdit->setToolTip(tr("Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND (&), XOR, "
                                   "OR, comparisons and arithmetic.\nCtrl+Space completes a variable name."));
    m_priorityLabel->setText(tr("&Priority:"));
    m_negatedCheck->setText(tr("&Negated"));
    m_negatedCheck->setToolTip(tr("Negation flips when this transition waits for the nested behaviour of its "
                                  "source:\na negated transition out of a macro-step ignores Complete;\n"
                                  "a negated transition out of an enclosing step waits for Complete."));
    m_hiddenCheck->setText(tr("&Hidden"));
    m_hiddenCheck->setToolTip(tr("A hidden transition is not part of this machine: it generates no code."));
    m_tokenGroup->setTitle(tr("Tokens"));
}

QWidget* TransitionDock::createForm()
{
    auto* form = new QWidget;
    auto* layout = new QVBoxLayout(form);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(6);

    m_titleLabel = new QLabel(form);
    m_titleLabel->setObjectName(QStringLiteral("titleLabel"));
    QFont titleFont = m_titleLabel->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.3);
    m_titleLabel->setFont(titleFont);
    m_titleLabel->setTextFormat(Qt::RichText);
    connect(m_titleLabel, &QLabel::linkActivated, this, &TransitionDock::onStepLinkActivated);
    layout->addWidget(m_titleLabel);
    m_namesLabel = hintLabel(form);
    m_namesLabel->setObjectName(QStringLiteral("namesLabel"));
    layout->addWidget(m_namesLabel);
    m_effectLabel = hintLabel(form);
    m_effectLabel->setObjectName(QStringLiteral("effectLabel"));
    layout->addWidget(m_effectLabel);

    m_conditionLabel = new QLabel(form);
    layout->addWidget(m_conditionLabel);
    m_conditionEdit = new ConditionEdit(form);
    m_conditionEdit->setObjectName(QStringLiteral("conditionEdit"));
    m_conditionLabel->setBuddy(m_conditionEdit);
    connect(m_conditionEdit, &ConditionEdit::textEdited, this, &TransitionDock::onConditionEdited);
    layout->addWidget(m_conditionEdit);
    m_problemList = new DiagnosticList(form);
    m_problemList->setDocument(document());
    m_problemList->setObjectName(QStringLiteral("problemList"));
    layout->addWidget(m_problemList);

    auto* fields = new QFormLayout;
    fields->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_prioritySpin = new QSpinBox(form);
    m_prioritySpin->setObjectName(QStringLiteral("prioritySpin"));
    m_prioritySpin->setKeyboardTracking(false); // one command per value, not per digit
    UndoShortcutFilter::installAfterCommit(m_prioritySpin);
    m_prioritySpin->setMinimumWidth(m_prioritySpin->fontMetrics().horizontalAdvance(QStringLiteral("00 of 00")) + 40);
    connect(m_prioritySpin, &QSpinBox::valueChanged, this, &TransitionDock::onPriorityChanged);
    auto* priorityRow = new QHBoxLayout;
    priorityRow->addWidget(m_prioritySpin);
    priorityRow->addStretch();
    m_priorityLabel = new QLabel(form);
    m_priorityLabel->setBuddy(m_prioritySpin);
    fields->addRow(m_priorityLabel, priorityRow);

    auto* flags = new QHBoxLayout;
    m_negatedCheck = new QCheckBox(form);
    m_negatedCheck->setObjectName(QStringLiteral("negatedCheck"));
    connect(m_negatedCheck, &QCheckBox::toggled, this, &TransitionDock::onNegatedToggled);
    m_hiddenCheck = new QCheckBox(form);
    m_hiddenCheck->setObjectName(QStringLiteral("hiddenCheck"));
    connect(m_hiddenCheck, &QCheckBox::toggled, this, &TransitionDock::onHiddenToggled);
    flags->addWidget(m_negatedCheck);
    flags->addWidget(m_hiddenCheck);
    flags->addStretch();
    fields->addRow(flags);
    m_negatedHint = hintLabel(form);
    m_negatedHint->setObjectName(QStringLiteral("negatedHint"));
    fields->addRow(m_negatedHint);
    layout->addLayout(fields);

    m_tokenGroup = new QGroupBox(form);
    m_tokenGroup->setObjectName(QStringLiteral("tokenGroup"));
    m_tokenLayout = new QVBoxLayout(m_tokenGroup);
    m_tokenLayout->setSpacing(2);
    m_tokenHint = hintLabel(m_tokenGroup);
    m_tokenHint->setObjectName(QStringLiteral("tokenHint"));
    m_tokenLayout->addWidget(m_tokenHint);
    layout->addWidget(m_tokenGroup);
    layout->addStretch();
    return form;
}

void TransitionDock::focusField(const QString& field)
{
    if (field == QLatin1String("tokens")) {
        QWidget* target = m_tokenChecks.isEmpty() ? static_cast<QWidget*>(m_tokenGroup) : m_tokenChecks.front();
        target->setFocus(Qt::OtherFocusReason);
    } else if (field == QLatin1String("negated")) {
        m_negatedCheck->setFocus(Qt::OtherFocusReason);
    } else if (field == QLatin1String("priority")) {
        m_prioritySpin->setFocus(Qt::OtherFocusReason);
    } else if (field == QLatin1String("hidden")) {
        m_hiddenCheck->setFocus(Qt::OtherFocusReason);
    } else {
        focusCondition();
    }
}

// Selects the first problem of the condition, so the user can type over it.
void TransitionDock::focusCondition()
{
    for (const ConditionEdit::Problem& problem : m_conditionEdit->problems()) {
        if (problem.error) {
            m_conditionEdit->selectRange(problem.begin, problem.end);
            return;
        }
    }
    const int end = static_cast<int>(m_conditionEdit->text().size());
    m_conditionEdit->selectRange(end, end);
}

void TransitionDock::refreshForm()
{
    const core::Transition* transition = document()->model().transition(transitionId().toStdString());
    refreshHeader(*transition);
    refreshCondition(*transition);
    refreshPriority(*transition);
    refreshNegation(*transition);
    refreshTokens(*transition);
    m_problemList->setDiagnostics(document()->diagnosticsFor(element()));
}

void TransitionDock::refreshHeader(const core::Transition& transition)
{
    const core::Model& model = document()->model();
    const QString source = fromStd(transition.source);
    const QString target = fromStd(transition.target);
    const auto link = [](const QString& id) { return QStringLiteral("<a href=\"%1\">%1</a>").arg(id); };
    const QString sourceText = transition.isFamilyTransition() ? tr("F (family)").toHtmlEscaped() : link(source);
    //: a transition: source step, arrow, target step
    m_titleLabel->setText(tr("%1 → %2").arg(sourceText, link(target)));
    const QString sourceName
        = transition.isFamilyTransition() ? officialFamilyName(core::Family::F) : officialStateName(source);
    m_namesLabel->setText(tr("%1 → %2").arg(sourceName, officialStateName(target)));

    const QString reason = ineffectiveReason(model, transition);
    m_effectLabel->setText(reason.isEmpty() ? QString() : tr("Not effective (%1): generates no code.").arg(reason));
    m_effectLabel->setVisible(!reason.isEmpty());
}

void TransitionDock::refreshCondition(const core::Transition& transition)
{
    const QString condition = fromStd(transition.condition);
    m_conditionEdit->setText(condition);

    QStringList names;
    for (const core::Variable& variable : document()->model().variables())
        names << fromStd(variable.name);
    m_conditionEdit->setVariableNames(names);

    QList<ConditionEdit::Problem> problems;
    for (const core::Diagnostic& diagnostic : document()->diagnosticsFor(element())) {
        if (diagnostic.field != "condition" || !diagnostic.span)
            continue;
        ConditionEdit::Problem problem;
        problem.begin = ConditionEdit::positionOfByte(condition, diagnostic.span->begin);
        problem.end = ConditionEdit::positionOfByte(condition, diagnostic.span->end);
        problem.message = diagnosticText(diagnostic);
        problem.error = diagnostic.severity == core::Severity::Error;
        problems << problem;
    }
    m_conditionEdit->setProblems(problems);
}

namespace {

// QSpinBox's setters lay the form out again even when nothing changes: at
// every keystroke in the condition, the dock's whole form was.
void showPriority(QSpinBox* spin, int minimum, int maximum, const QString& suffix, const QString& special)
{
    if (spin->specialValueText() != special)
        spin->setSpecialValueText(special);
    if (spin->minimum() != minimum || spin->maximum() != maximum)
        spin->setRange(minimum, maximum);
    if (spin->suffix() != suffix)
        spin->setSuffix(suffix);
}

} // namespace

void TransitionDock::refreshPriority(const core::Transition& transition)
{
    const core::Model& model = document()->model();
    const QSignalBlocker blocker(m_prioritySpin);
    const int priority = model.priority(transition.id);
    if (transition.isFamilyTransition() || priority == 0) {
        showPriority(m_prioritySpin, 0, 0, QString(), transition.isFamilyTransition() ? tr("First") : tr("None"));
        m_prioritySpin->setEnabled(false);
        m_prioritySpin->setToolTip(transition.isFamilyTransition()
                ? tr("The family transition is evaluated before the own transitions of every visible F state.")
                : tr("Only effective transitions have a priority: show this transition and both its steps first."));
        return;
    }
    const int count = static_cast<int>(model.effectiveOutgoing(transition.source).size());
    //: after the priority in its spin box: "2 of 5"
    showPriority(m_prioritySpin, 1, count, tr(" of %1").arg(count), QString());
    m_prioritySpin->setValue(priority);
    m_prioritySpin->setEnabled(count > 1);
    m_prioritySpin->setToolTip(tr("1 is evaluated first among the effective transitions out of %1; the others "
                                  "move to make room.")
                                   .arg(fromStd(transition.source)));
}

void TransitionDock::refreshNegation(const core::Transition& transition)
{
    {
        const QSignalBlocker negatedBlocker(m_negatedCheck);
        m_negatedCheck->setChecked(transition.negated);
    }
    {
        const QSignalBlocker hiddenBlocker(m_hiddenCheck);
        m_hiddenCheck->setChecked(transition.hidden);
    }
    const core::Step* source = document()->model().step(transition.source);
    const QString id = fromStd(transition.source);
    QString hint;
    if (transition.isFamilyTransition()) {
        hint = tr("Negation has no effect here: family transitions never wait for Complete.");
    } else if (!source || source->type == core::StepType::Simple) {
        hint = tr("Negation has no effect here: %1 is a simple step, and only transitions out of macro-steps and "
                  "enclosing steps wait for Complete.")
                   .arg(id);
    } else if (source->type == core::StepType::Macro) {
        hint = transition.negated
            ? tr("Fires without waiting for the nested behaviour of macro-step %1 to complete.").arg(id)
            : tr("Waits until the nested behaviour of macro-step %1 is complete (%1.Complete). Negate it to fire "
                 "at once.")
                  .arg(id);
    } else {
        hint = transition.negated
            ? tr("Waits until the nested behaviour of enclosing step %1 is complete (%1.Complete).").arg(id)
            : tr("Fires whatever the nested behaviour of enclosing step %1 is doing. Negate it to wait for "
                 "%1.Complete.")
                  .arg(id);
    }
    m_negatedHint->setText(hint);
}

QList<TransitionDock::TokenRow> TransitionDock::tokenRows(const core::Transition& transition, QString* hint) const
{
    const core::Model& model = document()->model();
    const core::Step* source = model.step(transition.source);
    const bool applies = !transition.isFamilyTransition() && source && core::hasNestedBehaviour(source->type);
    const QString sourceId = fromStd(transition.source);
    const int priority = model.priority(transition.id);
    const core::cond::ParseResult parsed = core::cond::parse(transition.condition);
    const std::vector<VariableUse> uses
        = parsed.ok() ? boolVariableUses(model, parsed.expression) : std::vector<VariableUse>();

    QList<TokenRow> rows;
    for (const VariableUse& use : uses) {
        TokenRow row;
        row.variable = fromStd(use.name);
        row.checked = hasToken(transition, use.name);
        const bool polar = !use.compared && use.normallyOpen != use.normallyClosed;
        if (use.compared)
            row.text = tr("Token on %1 (compared: no polarity)").arg(row.variable);
        else if (!polar)
            row.text = tr("Token on %1 (both NO and NC)").arg(row.variable);
        else if (use.normallyClosed)
            row.text = tr("Token on %1 (NC)").arg(row.variable);
        else
            row.text = tr("Token on %1 (NO)").arg(row.variable);
        // What cannot be a token may still be unchecked.
        row.enabled = row.checked || (polar && applies);
        if (!polar)
            row.toolTip = tr("A token replaces a literal %1 or NOT %1: rewrite the condition so that %1 has one "
                             "polarity.")
                              .arg(row.variable);
        else
            row.toolTip = (use.normallyClosed
                    ? tr("Normally closed: remembers that %1 was FALSE while the nested behaviour of %2 was not "
                         "complete.")
                    : tr("Normally open: remembers that %1 was TRUE while the nested behaviour of %2 was not "
                         "complete."))
                              .arg(row.variable, sourceId);
        if (polar && applies && priority > 0)
            row.toolTip
                += QLatin1Char('\n') + tr("Generated as %1_%2_%3_MEM.").arg(row.variable, sourceId).arg(priority);
        rows << row;
    }
    // Tokens the condition no longer justifies stay visible, so they can be removed.
    for (const std::string& token : transition.tokens) {
        const bool listed = std::any_of(
            uses.begin(), uses.end(), [&](const VariableUse& use) { return core::equalsIgnoreCase(use.name, token); });
        if (listed)
            continue;
        TokenRow row;
        row.variable = fromStd(token);
        row.checked = true;
        row.text = tr("Token on %1 (not a BOOL variable of the condition)").arg(row.variable);
        row.toolTip = tr("Uncheck to remove this token.");
        rows << row;
    }

    if (!applies)
        *hint = transition.isFamilyTransition()
            ? tr("Family transitions never wait for Complete, so tokens do not apply to them.")
            : tr("Tokens apply to transitions out of macro-steps and enclosing steps; %1 is a simple step.")
                  .arg(sourceId);
    else if (!parsed.ok())
        *hint = tr("Correct the condition to choose its tokens.");
    else if (uses.empty())
        *hint = tr("The condition uses no BOOL variable.");
    else
        *hint = tr("A token keeps a short pulse of a BOOL variable that occurs while the nested behaviour of %1 "
                   "is not yet complete.")
                    .arg(sourceId);
    return rows;
}

void TransitionDock::refreshTokens(const core::Transition& transition)
{
    QString hint;
    const QList<TokenRow> rows = tokenRows(transition, &hint);
    m_tokenHint->setText(hint);

    bool sameBoxes = rows.size() == m_tokenRows.size();
    for (qsizetype i = 0; sameBoxes && i < rows.size(); ++i)
        sameBoxes = rows[i].variable == m_tokenRows[i].variable && rows[i].text == m_tokenRows[i].text;
    if (!sameBoxes) {
        // Rebuilt only when the boxes change, so a click keeps the focus on its box.
        for (QCheckBox* check : std::as_const(m_tokenChecks)) {
            // Later: the box may be the one whose toggle led here.
            m_tokenLayout->removeWidget(check);
            check->hide();
            check->setParent(nullptr);
            check->deleteLater();
        }
        m_tokenChecks.clear();
        for (const TokenRow& row : rows) {
            auto* check = new QCheckBox(row.text, m_tokenGroup);
            check->setObjectName(QStringLiteral("tokenCheck_") + row.variable);
            const QString variable = row.variable;
            connect(check, &QCheckBox::toggled, this, [this, variable](bool on) { onTokenToggled(variable, on); });
            m_tokenLayout->addWidget(check);
            m_tokenChecks << check;
        }
    }
    m_tokenRows = rows;
    for (qsizetype i = 0; i < rows.size(); ++i) {
        QCheckBox* check = m_tokenChecks[i];
        const QSignalBlocker blocker(check);
        check->setChecked(rows[i].checked);
        check->setEnabled(rows[i].enabled);
        check->setToolTip(rows[i].toolTip);
    }
}

void TransitionDock::onConditionEdited(const QString& text)
{
    if (!transitionId().isEmpty())
        document()->push(new SetConditionCommand(*document(), transitionId(), text));
}

void TransitionDock::onPriorityChanged(int priority)
{
    if (!transitionId().isEmpty() && priority > 0)
        document()->push(new SetPriorityCommand(*document(), transitionId(), priority));
    refresh();
}

void TransitionDock::onNegatedToggled(bool checked)
{
    if (!transitionId().isEmpty())
        document()->push(new SetNegatedCommand(*document(), transitionId(), checked));
    refresh();
}

void TransitionDock::onHiddenToggled(bool checked)
{
    if (!transitionId().isEmpty())
        document()->push(new SetTransitionHiddenCommand(*document(), transitionId(), checked));
    refresh();
}

void TransitionDock::onTokenToggled(const QString& variable, bool checked)
{
    const core::Transition* transition = document()->model().transition(transitionId().toStdString());
    if (!transition)
        return;
    QStringList tokens;
    for (const std::string& token : transition->tokens) {
        if (!core::equalsIgnoreCase(token, variable.toStdString()))
            tokens << fromStd(token);
    }
    if (checked)
        tokens << variable;
    document()->push(new SetTokensCommand(*document(), transitionId(), tokens));
    refresh();
}

void TransitionDock::onStepLinkActivated(const QString& stepId)
{
    selection()->select(ElementRef::step(stepId));
}

} // namespace editor
