#include "editor/grafcet/grafcetselectionsync.h"

#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/selection.h"

#include <QScopedValueRollback>
#include <QSet>

namespace editor {

namespace {

// Room kept around an item scrolled into view, in view pixels.
constexpr int kScrollMargin = 40;

} // namespace

GrafcetSelectionSync::GrafcetSelectionSync(GrafcetView* view, Selection* selection)
    : QObject(view)
    , m_view(view)
    , m_scene(view->grafcetScene())
    , m_selection(selection)
{
    connect(m_scene, &QGraphicsScene::selectionChanged, this, &GrafcetSelectionSync::onSceneSelectionChanged);
    connect(m_scene, &GrafcetScene::rebuilt, this, [this] { selectFromSelection(false); });
    connect(m_selection, &Selection::changed, this, [this] { selectFromSelection(true); });
    connect(m_selection, &Selection::elementsChanged, this, [this] { selectFromSelection(false); });
    selectFromSelection(true);
}

QGraphicsItem* GrafcetSelectionSync::itemFor(const ElementRef& element) const
{
    if (element.id != m_scene->stepId())
        return nullptr;
    switch (element.kind) {
    case ElementRef::Kind::GrafcetStep: return m_scene->stepItem(element.number);
    case ElementRef::Kind::GrafcetTransition: return m_scene->transitionItem(element.number);
    default: return nullptr;
    }
}

ElementRef GrafcetSelectionSync::elementOf(const QGraphicsItem* item) const
{
    if (auto* step = qgraphicsitem_cast<const GrafcetStepItem*>(item))
        return ElementRef::grafcetStep(m_scene->stepId(), step->number());
    if (auto* transition = qgraphicsitem_cast<const GrafcetTransitionItem*>(item))
        return ElementRef::grafcetTransition(m_scene->stepId(), transition->number());
    return {};
}

void GrafcetSelectionSync::onSceneSelectionChanged()
{
    // Items deleted by a rebuild are not the user choosing nothing.
    if (m_syncing || m_scene->isRebuilding() || !m_selection)
        return;
    QList<ElementRef> elements;
    for (const QGraphicsItem* item : m_scene->selectedItems()) {
        const ElementRef element = elementOf(item);
        if (!element.isNull())
            elements << element;
    }
    const ElementRef& current = m_selection->current();
    if (elements.isEmpty()) {
        // Only a selection of this GRAFCET is the drawing's to clear.
        if (current.isNested() && current.id == m_scene->stepId())
            m_selection->clear();
        return;
    }
    // The one just added (Ctrl+click) is shown in the docks, as on the chart.
    ElementRef shown = elements.contains(current) ? current : elements.first();
    for (const ElementRef& element : std::as_const(elements)) {
        if (!m_selection->elements().contains(element))
            shown = element;
    }
    m_selection->selectMany(elements, shown);
}

void GrafcetSelectionSync::selectFromSelection(bool scroll)
{
    if (!m_selection)
        return;
    QSet<QGraphicsItem*> wanted;
    for (const ElementRef& element : m_selection->elements()) {
        if (QGraphicsItem* item = itemFor(element))
            wanted.insert(item);
    }
    const QList<QGraphicsItem*> selected = m_scene->selectedItems();
    if (QSet<QGraphicsItem*>(selected.begin(), selected.end()) != wanted) {
        const QScopedValueRollback<bool> guard(m_syncing, true);
        m_scene->clearSelection();
        for (QGraphicsItem* item : std::as_const(wanted))
            item->setSelected(true);
    }
    if (!scroll)
        return;
    if (QGraphicsItem* item = itemFor(m_selection->current()))
        m_view->ensureVisible(item, kScrollMargin, kScrollMargin);
}

} // namespace editor
