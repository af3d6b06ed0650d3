#include "editor/grafcet/grafcetscene.h"

#include "editor/chart/chartstyle.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetwiringitem.h"
#include "editor/text/diagnostictext.h"

#include "core/model/model.h"

#include <QFontMetricsF>
#include <QGraphicsSceneHelpEvent>
#include <QStringList>
#include <QToolTip>

namespace editor {

namespace {

// The errors and warnings of one nested element: what is marked red.
std::vector<core::Diagnostic> problemsOf(const Document& document, const ElementRef& element)
{
    std::vector<core::Diagnostic> problems = document.diagnosticsFor(element);
    std::erase_if(problems, [](const core::Diagnostic& d) { return d.severity == core::Severity::Info; });
    return problems;
}

} // namespace

GrafcetScene::GrafcetScene(Document* document, const QString& stepId, QObject* parent)
    : QGraphicsScene(parent)
    , m_document(document)
    , m_stepId(stepId)
{
    connect(document, &Document::grafcetChanged, this, [this](const QString& changed) {
        if (changed == m_stepId)
            rebuild();
    });
    connect(document, &Document::modelReset, this, &GrafcetScene::rebuild);
    connect(document, &Document::diagnosticsChanged, this, &GrafcetScene::applyProblemMarks);
    rebuild();
}

GrafcetScene::~GrafcetScene()
{
    // ~QGraphicsScene deselects the items it deletes: that is no user's
    // choice, and whoever follows the selection may be gone already.
    disconnect(this, &QGraphicsScene::selectionChanged, nullptr, nullptr);
}

double GrafcetScene::textWidth(std::string_view text)
{
    static const QFontMetricsF metrics(chartstyle::font());
    return metrics.horizontalAdvance(QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())));
}

void GrafcetScene::rebuild()
{
    const core::Grafcet* grafcet = m_document->model().grafcet(m_stepId.toStdString());
    core::GrafcetLayout layout = grafcet ? core::layoutGrafcet(*grafcet, &GrafcetScene::textWidth) : core::GrafcetLayout{};
    m_rebuilding = true;
    if (!grafcet || !relabel(*grafcet, layout))
        makeItems(grafcet, std::move(layout));
    m_rebuilding = false;
    emit rebuilt();
}

// Typing in a receptivity most often changes only its label: the items stay
// (with their selection), the others are not drawn again and the view keeps
// its scroll range, which a whole new set of items would cost at every
// keystroke. A label that moves anything else or resizes the drawing (the
// widest one, whose links route around it) makes the items again.
bool GrafcetScene::relabel(const core::Grafcet& grafcet, core::GrafcetLayout& layout)
{
    if (!m_wiring || layout.boundingRect != m_layout.boundingRect || layout.steps != m_layout.steps
        || layout.links != m_layout.links || layout.lines != m_layout.lines
        || layout.transitions.size() != m_layout.transitions.size())
        return false;
    for (std::size_t i = 0; i < layout.transitions.size(); ++i) {
        const core::GrafcetTransitionLayout& now = layout.transitions[i];
        const core::GrafcetTransitionLayout& before = m_layout.transitions[i];
        if (now.number != before.number || now.barCenter != before.barCenter || now.detached != before.detached
            || !m_transitions.contains(now.number))
            return false;
    }
    for (const core::GrafcetTransitionLayout& transition : layout.transitions) {
        const core::GrafcetTransition* model = grafcet.transition(transition.number);
        m_transitions.value(transition.number)->setReceptivity(transition, model ? model->receptivity : std::string());
    }
    m_layout = std::move(layout);
    return true;
}

void GrafcetScene::makeItems(const core::Grafcet* grafcet, core::GrafcetLayout layout)
{
    clear();
    m_steps.clear();
    m_transitions.clear();
    m_layout = std::move(layout);
    m_wiring = new GrafcetWiringItem(m_layout);
    addItem(m_wiring);
    for (const core::GrafcetStepLayout& step : m_layout.steps) {
        auto* item = new GrafcetStepItem(step);
        addItem(item);
        m_steps.insert(step.number, item);
    }
    if (grafcet) {
        for (const core::GrafcetTransitionLayout& transition : m_layout.transitions) {
            const core::GrafcetTransition* model = grafcet->transition(transition.number);
            auto* item = new GrafcetTransitionItem(transition, model ? model->receptivity : std::string());
            addItem(item);
            m_transitions.insert(transition.number, item);
        }
    }
    setSceneRect(drawingRect());
    applyProblemMarks();
}

void GrafcetScene::setProblemMarksShown(bool shown)
{
    if (m_problemMarksShown == shown)
        return;
    m_problemMarksShown = shown;
    applyProblemMarks();
}

void GrafcetScene::applyProblemMarks()
{
    for (GrafcetStepItem* item : std::as_const(m_steps)) {
        bool ownProblem = false;
        QList<int> actions;
        if (m_problemMarksShown) {
            for (const core::Diagnostic& d : problemsOf(*m_document, ElementRef::grafcetStep(m_stepId, item->number()))) {
                if (d.actionIndex >= 0)
                    actions << d.actionIndex;
                else
                    ownProblem = true;
            }
        }
        item->setProblemMarks(ownProblem, actions);
    }
    for (GrafcetTransitionItem* item : std::as_const(m_transitions))
        item->setProblemMark(m_problemMarksShown
                             && !problemsOf(*m_document, ElementRef::grafcetTransition(m_stepId, item->number())).empty());
}

QString GrafcetScene::problemToolTip(const ElementRef& element) const
{
    QStringList lines;
    for (const core::Diagnostic& d : problemsOf(*m_document, element))
        lines << diagnosticText(d).toHtmlEscaped();
    // Rich text, so that a long message wraps.
    return lines.isEmpty() ? QString() : QStringLiteral("<p>") + lines.join(QStringLiteral("<br/>")) + QStringLiteral("</p>");
}

QString GrafcetScene::toolTipAt(QPointF scenePos) const
{
    if (!m_problemMarksShown)
        return {};
    for (const QGraphicsItem* item : items(scenePos, Qt::IntersectsItemShape, Qt::DescendingOrder)) {
        if (const auto* step = qgraphicsitem_cast<const GrafcetStepItem*>(item))
            return problemToolTip(ElementRef::grafcetStep(m_stepId, step->number()));
        if (const auto* transition = qgraphicsitem_cast<const GrafcetTransitionItem*>(item))
            return problemToolTip(ElementRef::grafcetTransition(m_stepId, transition->number()));
    }
    return {};
}

// Built when one shows, in the UI language of that moment; elsewhere the
// items' own tooltips, as QGraphicsScene shows them.
void GrafcetScene::helpEvent(QGraphicsSceneHelpEvent* event)
{
    const QString text = toolTipAt(event->scenePos());
    if (text.isEmpty()) {
        QGraphicsScene::helpEvent(event);
        return;
    }
    QToolTip::showText(event->screenPos(), text, event->widget());
    event->setAccepted(true);
}

QRectF GrafcetScene::drawingRect() const
{
    const core::Rect& bounds = m_layout.boundingRect;
    return QRectF(bounds.x, bounds.y, std::max(bounds.width, 1.0), std::max(bounds.height, 1.0));
}

} // namespace editor
