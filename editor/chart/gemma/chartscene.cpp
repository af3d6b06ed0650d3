#include "editor/chart/gemma/chartscene.h"

#include "core/templates/gemma/gemmachartlayout.h"
#include "editor/chart/chartstyle.h"
#include "editor/chart/gemma/frameitem.h"
#include "editor/chart/gemma/stepitem.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/chart/layoutconversion.h"
#include "editor/document.h"
#include "editor/selection.h"

#include <QGraphicsSceneHelpEvent>
#include <QGraphicsView>
#include <QScopedValueRollback>
#include <QToolTip>
#include <QSet>

namespace editor {

ChartScene::ChartScene(Document* document, Selection* selection, QObject* parent)
    : QGraphicsScene(parent)
    , m_document(document)
    , m_selection(selection)
{
    Q_ASSERT(document && selection);
    buildItems();

    connect(m_document, &Document::stepChanged, this, &ChartScene::onStepChanged);
    connect(m_document, &Document::transitionChanged, this, &ChartScene::onTransitionChanged);
    connect(m_document, &Document::modelReset, this, &ChartScene::onModelReset);
    // A nested GRAFCET gained or lost its steps: the step's mark follows.
    connect(m_document, &Document::grafcetChanged, this, [this](const QString& stepId) {
        if (StepItem* item = stepItem(stepId))
            item->refresh();
    });
    connect(m_document, &Document::diagnosticsChanged, this, &ChartScene::onDiagnosticsChanged);
    connect(m_selection, &Selection::changed, this, &ChartScene::onSelectionChanged);
    connect(m_selection, &Selection::elementsChanged, this, &ChartScene::selectFromSelection);
    connect(this, &QGraphicsScene::selectionChanged, this, &ChartScene::onSceneSelectionChanged);

    onModelReset();
    onDiagnosticsChanged();
}

ChartScene::~ChartScene()
{
    // ~QGraphicsScene deselects the items it deletes, when this is no longer
    // a ChartScene to hear of it.
    disconnect(this, &QGraphicsScene::selectionChanged, this, nullptr);
}

void ChartScene::buildItems()
{
    const core::ChartLayout& layout = core::templateLayout();
    setSceneRect(toQRectF(layout.sceneRect));

    for (const core::FrameLayout& frame : layout.frames) {
        auto* item = new FrameItem(frame);
        addItem(item);
        m_frames << item;
    }
    for (const core::StepLayout& step : layout.steps) {
        auto* item = new StepItem(*m_document, step);
        addItem(item);
        m_steps << item;
        m_stepItems.insert(item->id(), item);
    }
    for (const core::TransitionLayout& transition : layout.transitions) {
        auto* item = new TransitionItem(*m_document, transition);
        addItem(item);
        m_transitions << item;
        m_transitionItems.insert(item->id(), item);
        m_transitionsBySource[item->sourceId()] << item;
        m_transitionsByEnd[item->sourceId()] << item;
        m_transitionsByEnd[item->targetId()] << item;
    }
}

FrameItem* ChartScene::frameItem(core::Family family) const
{
    for (FrameItem* frame : m_frames) {
        if (frame->family() == family)
            return frame;
    }
    return nullptr;
}

void ChartScene::setShowHidden(bool show)
{
    if (m_showHidden == show)
        return;
    m_showHidden = show;
    for (StepItem* item : std::as_const(m_steps))
        applyVisibility(item, item->isHiddenInModel());
    for (TransitionItem* item : std::as_const(m_transitions))
        applyVisibility(item, item->isHiddenInModel());
    selectFromSelection();
}

void ChartScene::setActiveStep(const QString& id)
{
    if (m_activeStep == id)
        return;
    if (StepItem* old = stepItem(m_activeStep))
        old->setActive(false);
    m_activeStep = id;
    if (StepItem* item = stepItem(id))
        item->setActive(true);
}

void ChartScene::setFiredTransition(const QString& id)
{
    if (m_firedTransition == id)
        return;
    if (TransitionItem* old = transitionItem(m_firedTransition))
        old->setFired(false);
    m_firedTransition = id;
    if (TransitionItem* item = transitionItem(id))
        item->setFired(true);
}

void ChartScene::setCompleteMark(const QString& stepId, std::optional<bool> complete)
{
    if (StepItem* item = stepItem(stepId))
        item->setCompleteMark(complete);
}

void ChartScene::setTokenMarks(const QString& transitionId, const QList<bool>& tokens)
{
    if (TransitionItem* item = transitionItem(transitionId))
        item->setTokenMarks(tokens);
}

void ChartScene::setNestedRunning(const QString& stepId, const std::optional<QString>& activeSteps)
{
    if (StepItem* item = stepItem(stepId))
        item->setNestedRunning(activeSteps);
}

void ChartScene::clearSimulationMarks()
{
    setActiveStep(QString());
    setFiredTransition(QString());
    for (StepItem* item : std::as_const(m_steps)) {
        item->setCompleteMark(std::nullopt);
        item->setNestedRunning(std::nullopt);
    }
    for (TransitionItem* item : std::as_const(m_transitions))
        item->setTokenMarks({});
}

QList<QGraphicsItem*> ChartScene::tabOrder() const
{
    QList<QGraphicsItem*> order;
    for (StepItem* item : m_steps) {
        if (item->isVisible())
            order << item;
    }
    for (TransitionItem* item : m_transitions) {
        if (item->isVisible())
            order << item;
    }
    return order;
}

QString ChartScene::toolTipAt(QPointF scenePos, const QTransform& viewportTransform) const
{
    const QList<QGraphicsItem*> hits = items(scenePos, Qt::IntersectsItemShape, Qt::DescendingOrder, viewportTransform);
    for (const QGraphicsItem* item : hits) {
        if (const auto* step = qgraphicsitem_cast<const StepItem*>(item))
            return step->toolTipText();
        if (const auto* transition = qgraphicsitem_cast<const TransitionItem*>(item))
            return transition->toolTipText();
    }
    return {};
}

// Tooltips are built when one shows, not for every item at every change
// (and at start-up, where the fifty of them were 0.8 M instructions).
void ChartScene::helpEvent(QGraphicsSceneHelpEvent* event)
{
    // The event comes from a view's viewport.
    const auto* view = event->widget() ? qobject_cast<const QGraphicsView*>(event->widget()->parentWidget()) : nullptr;
    const QString text = toolTipAt(event->scenePos(), view ? view->viewportTransform() : QTransform());
    QToolTip::showText(text.isEmpty() ? QPoint() : event->screenPos(), text, event->widget());
    event->setAccepted(!text.isEmpty());
}

QGraphicsItem* ChartScene::itemFor(const ElementRef& element) const
{
    switch (element.kind) {
    case ElementRef::Kind::Step: return stepItem(element.id);
    case ElementRef::Kind::Transition: return transitionItem(element.id);
    default: return nullptr;
    }
}

ElementRef ChartScene::elementOf(const QGraphicsItem* item)
{
    if (auto* step = qgraphicsitem_cast<const StepItem*>(item))
        return ElementRef::step(step->id());
    if (auto* transition = qgraphicsitem_cast<const TransitionItem*>(item))
        return ElementRef::transition(transition->id());
    return {};
}

void ChartScene::onStepChanged(const QString& id)
{
    if (StepItem* item = stepItem(id))
        refreshStep(item);
    QSet<QString> sources;
    for (TransitionItem* transition : m_transitionsByEnd.value(id))
        sources.insert(transition->sourceId());
    for (const QString& source : std::as_const(sources))
        refreshTransitionsFrom(source);
    selectFromSelection();
}

void ChartScene::onTransitionChanged(const QString& id)
{
    if (TransitionItem* item = transitionItem(id)) {
        refreshTransitionsFrom(item->sourceId());
        selectFromSelection();
    }
}

void ChartScene::onModelReset()
{
    for (StepItem* item : std::as_const(m_steps))
        refreshStep(item);
    for (TransitionItem* item : std::as_const(m_transitions))
        refreshTransition(item);
    selectFromSelection();
}

void ChartScene::retranslate()
{
    for (FrameItem* frame : std::as_const(m_frames))
        frame->retranslate();
    update();
}

void ChartScene::onDiagnosticsChanged()
{
    // A step is also marked for the problems of its nested GRAFCET's
    // elements: from the chart, that is where they are found.
    for (StepItem* item : std::as_const(m_steps))
        item->setProblemMark(m_document->hasProblems(ElementRef::step(item->id()))
                             || m_document->nestedProblemCount(item->id()) > 0);
    for (TransitionItem* item : std::as_const(m_transitions))
        item->setProblemMark(m_document->hasProblems(ElementRef::transition(item->id())));
}

void ChartScene::refreshStep(StepItem* item)
{
    item->refresh();
    applyVisibility(item, item->isHiddenInModel());
}

void ChartScene::refreshTransitionsFrom(const QString& source)
{
    for (TransitionItem* item : m_transitionsBySource.value(source))
        refreshTransition(item);
}

void ChartScene::refreshTransition(TransitionItem* item)
{
    item->refresh();
    applyVisibility(item, item->isHiddenInModel());
}

void ChartScene::applyVisibility(QGraphicsItem* item, bool hiddenInModel)
{
    // Hiding a selected item deselects it; that is not the user choosing
    // nothing, so the shared Selection keeps the element (the docks may
    // still be editing it).
    const QScopedValueRollback<bool> guard(m_syncingSelection, true);
    item->setVisible(!hiddenInModel || m_showHidden);
    item->setOpacity(hiddenInModel ? chartstyle::kHiddenOpacity : 1.0);
}

void ChartScene::onSceneSelectionChanged()
{
    if (m_syncingSelection)
        return;
    const QList<QGraphicsItem*> selected = selectedItems();
    if (selected.isEmpty()) {
        const ElementRef::Kind kind = m_selection->current().kind;
        if (kind == ElementRef::Kind::Step || kind == ElementRef::Kind::Transition)
            m_selection->clear();
        return;
    }
    // Several with Ctrl+click or the rubber band: the docks show the one
    // just added, or keep showing the current one while it stays selected.
    QList<ElementRef> elements;
    for (QGraphicsItem* item : selected) {
        const ElementRef element = elementOf(item);
        if (!element.isNull())
            elements << element;
    }
    if (elements.isEmpty())
        return;
    ElementRef current = elements.contains(m_selection->current()) ? m_selection->current() : elements.first();
    const QList<ElementRef>& before = m_selection->elements();
    for (const ElementRef& element : elements) {
        if (!before.contains(element))
            current = element;
    }
    m_selection->selectMany(elements, current);
}

void ChartScene::onSelectionChanged(const ElementRef&)
{
    selectFromSelection();
}

void ChartScene::selectFromSelection()
{
    QSet<QGraphicsItem*> wanted;
    for (const ElementRef& element : m_selection->elements()) {
        QGraphicsItem* item = itemFor(element);
        if (item && item->isVisible())
            wanted.insert(item);
    }
    const QList<QGraphicsItem*> selected = selectedItems();
    if (QSet<QGraphicsItem*>(selected.begin(), selected.end()) == wanted)
        return;
    const QScopedValueRollback<bool> guard(m_syncingSelection, true);
    clearSelection();
    for (QGraphicsItem* item : wanted)
        item->setSelected(true);
}

} // namespace editor
