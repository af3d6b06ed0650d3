#include "editor/docks/grafcettransitiondock.h"

#include "editor/commands/setreceptivitycommand.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/gemma/transitiondock.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/secondarytext.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/gemmastatenames.h"

#include "core/model/model.h"

#include <QAction>
#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace editor {

namespace {

// "2, 3" with each number a link that selects that step.
QString stepLinks(const std::vector<int>& steps)
{
    QStringList links;
    for (int step : steps)
        links << QStringLiteral("<a href=\"%1\">%1</a>").arg(step);
    return links.join(QStringLiteral(", "));
}

QLabel* linkLabel(const QString& objectName, QWidget* parent)
{
    auto* label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setTextFormat(Qt::RichText);
    label->setTextInteractionFlags(Qt::LinksAccessibleByMouse | Qt::LinksAccessibleByKeyboard);
    return label;
}

} // namespace

QString GrafcetTransitionDock::title()
{
    return tr("Nested Transition");
}

GrafcetTransitionDock::GrafcetTransitionDock(Document* document, Selection* selection, QWidget* parent)
    : PropertyDock(ElementRef::Kind::GrafcetTransition, title(), document, selection, parent)
{
    setObjectName(QStringLiteral("grafcetTransitionDock"));
    // The receptivity's checks and completion depend on the declared variables.
    refreshOnVariableChanges();
    setPages(scrolling(createForm()));
    retranslate();
}

void GrafcetTransitionDock::retranslate()
{
    // Its tab shows only while a GRAFCET tab is in front, the GEMMA Transition
    // dock hidden (DockContext): the short title keeps the three tabs of the
    // column whole at 1366 x 768 in German. The View menu says which it is.
    setWindowTitle(TransitionDock::title());
    toggleViewAction()->setText(title());
    setPlaceholder(tr("Select a transition in a nested GRAFCET's tab to see and edit its receptivity."));
    m_upstreamLabel->setText(tr("From steps:"));
    m_downstreamLabel->setText(tr("To steps:"));
    m_upstreamSteps->setToolTip(tr("Click a step to select it"));
    m_downstreamSteps->setToolTip(tr("Click a step to select it"));
    m_receptivityLabel->setText(tr("&Receptivity:"));
    m_receptivityEdit->setPlaceholderText(tr("e.g. PartPresent AND X3, ↑Start, 5s/X2"));
    m_receptivityEdit->setToolTip(
        tr("Structured Text as in GEMMA conditions, plus X3 (step 3 is active), ↑a or RE a (rising edge), ↓a or "
           "FE a (falling edge), 5s/X3 (step 3 active for 5 s) and Complete.\nCtrl+Space completes a name."));
}

QWidget* GrafcetTransitionDock::createForm()
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
    layout->addWidget(m_titleLabel);
    m_grafcetLabel = new WrappingLabel(form);
    m_grafcetLabel->setObjectName(QStringLiteral("grafcetLabel"));
    useSecondaryText(m_grafcetLabel);
    layout->addWidget(m_grafcetLabel);

    auto* links = new QFormLayout;
    m_upstreamSteps = linkLabel(QStringLiteral("upstreamSteps"), form);
    m_downstreamSteps = linkLabel(QStringLiteral("downstreamSteps"), form);
    connect(m_upstreamSteps, &QLabel::linkActivated, this, &GrafcetTransitionDock::onStepLinkActivated);
    connect(m_downstreamSteps, &QLabel::linkActivated, this, &GrafcetTransitionDock::onStepLinkActivated);
    m_upstreamLabel = new QLabel(form);
    m_downstreamLabel = new QLabel(form);
    links->addRow(m_upstreamLabel, m_upstreamSteps);
    links->addRow(m_downstreamLabel, m_downstreamSteps);
    layout->addLayout(links);

    m_receptivityLabel = new QLabel(form);
    layout->addWidget(m_receptivityLabel);
    m_receptivityEdit = new ConditionEdit(form);
    m_receptivityEdit->setObjectName(QStringLiteral("receptivityEdit"));
    m_receptivityLabel->setBuddy(m_receptivityEdit);
    connect(m_receptivityEdit, &ConditionEdit::textEdited, this, &GrafcetTransitionDock::onReceptivityEdited);
    layout->addWidget(m_receptivityEdit);
    m_problemList = new DiagnosticList(form);
    m_problemList->setDocument(document());
    m_problemList->setObjectName(QStringLiteral("problemList"));
    layout->addWidget(m_problemList);
    layout->addStretch();
    return form;
}

const core::GrafcetTransition* GrafcetTransitionDock::transition() const
{
    const core::Grafcet* grafcet = document()->model().grafcet(elementId().toStdString());
    return grafcet ? grafcet->transition(elementNumber()) : nullptr;
}

void GrafcetTransitionDock::refreshForm()
{
    const core::GrafcetTransition* shown = transition();
    const QString stepId = elementId();
    //: A transition of the nested GRAFCET of a GEMMA step: "F1 T2"
    m_titleLabel->setText(tr("%1 T%2").arg(stepId).arg(shown->number));
    m_grafcetLabel->setText(tr("In the nested GRAFCET of %1 %2").arg(stepId, officialStateName(stepId)));
    refreshLinks(*shown);
    refreshReceptivity(*shown);
    m_problemList->setDiagnostics(document()->diagnosticsFor(element()));
}

void GrafcetTransitionDock::refreshLinks(const core::GrafcetTransition& transition)
{
    m_upstreamSteps->setText(stepLinks(transition.upstream));
    m_downstreamSteps->setText(stepLinks(transition.downstream));
}

void GrafcetTransitionDock::refreshReceptivity(const core::GrafcetTransition& transition)
{
    const QString receptivity = fromStd(transition.receptivity);
    m_receptivityEdit->setText(receptivity);
    m_receptivityEdit->setVariableNames(completions());
    QList<ConditionEdit::Problem> problems;
    for (const core::Diagnostic& diagnostic : document()->diagnosticsFor(element())) {
        if (diagnostic.field != "receptivity" || !diagnostic.span)
            continue;
        ConditionEdit::Problem problem;
        problem.begin = ConditionEdit::positionOfByte(receptivity, diagnostic.span->begin);
        problem.end = ConditionEdit::positionOfByte(receptivity, diagnostic.span->end);
        problem.message = diagnosticText(diagnostic);
        problem.error = diagnostic.severity == core::Severity::Error;
        problems << problem;
    }
    m_receptivityEdit->setProblems(problems);
}

// The declared variables, the activities of this GRAFCET's steps, Complete.
QStringList GrafcetTransitionDock::completions() const
{
    QStringList names;
    for (const core::Variable& variable : document()->model().variables())
        names << fromStd(variable.name);
    if (const core::Grafcet* grafcet = document()->model().grafcet(elementId().toStdString())) {
        for (const core::GrafcetStep& step : grafcet->steps())
            names << QStringLiteral("X%1").arg(step.number);
    }
    names << QStringLiteral("Complete");
    return names;
}

void GrafcetTransitionDock::focusField(const QString& field)
{
    const int end = static_cast<int>(m_receptivityEdit->text().size());
    // Enter on the drawing: the whole receptivity, to type over it (TRUE, as new transitions have).
    if (field == QLatin1String("main")) {
        m_receptivityEdit->selectRange(0, end);
        return;
    }
    // A problem: its first error selected, to type over it.
    for (const ConditionEdit::Problem& problem : m_receptivityEdit->problems()) {
        if (problem.error) {
            m_receptivityEdit->selectRange(problem.begin, problem.end);
            return;
        }
    }
    m_receptivityEdit->selectRange(end, end);
}

void GrafcetTransitionDock::onReceptivityEdited(const QString& text)
{
    if (!elementId().isEmpty())
        document()->push(new SetReceptivityCommand(*document(), elementId(), elementNumber(), text));
}

void GrafcetTransitionDock::onStepLinkActivated(const QString& number)
{
    selection()->select(ElementRef::grafcetStep(elementId(), number.toInt()));
}

} // namespace editor
