#include "editor/grafcet/grafcetkeyboard.h"

#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/selection.h"

#include <QKeyEvent>
#include <QMouseEvent>

#include <algorithm>
#include <tuple>
#include <vector>

namespace editor {

namespace {

// What Enter or F2 asks of the docks: the element's main field.
const QString kMainField = QStringLiteral("main");

struct Placed {
    double y = 0;
    double x = 0;
    ElementRef element;
};

} // namespace

GrafcetKeyboard::GrafcetKeyboard(GrafcetView* view, Selection* selection)
    : QObject(view)
    , m_view(view)
    , m_viewport(view->viewport())
    , m_scene(view->grafcetScene())
    , m_selection(selection)
{
    setObjectName(QStringLiteral("grafcetKeyboard"));
    view->installEventFilter(this);
    m_viewport->installEventFilter(this);
}

QList<ElementRef> GrafcetKeyboard::drawingOrder() const
{
    const core::GrafcetLayout& layout = m_scene->layout();
    std::vector<Placed> placed;
    for (const core::GrafcetStepLayout& step : layout.steps) {
        placed.push_back({step.box.y + step.box.height / 2, step.box.x + step.box.width / 2,
                          ElementRef::grafcetStep(m_scene->stepId(), step.number)});
    }
    for (const core::GrafcetTransitionLayout& transition : layout.transitions) {
        placed.push_back({transition.barCenter.y, transition.barCenter.x,
                          ElementRef::grafcetTransition(m_scene->stepId(), transition.number)});
    }
    std::stable_sort(placed.begin(), placed.end(),
                     [](const Placed& a, const Placed& b) { return std::tie(a.y, a.x) < std::tie(b.y, b.x); });
    QList<ElementRef> order;
    for (const Placed& element : placed)
        order << element.element;
    return order;
}

bool GrafcetKeyboard::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::KeyPress && watched == m_view)
        return onKeyPress(static_cast<QKeyEvent*>(event));
    if (event->type() == QEvent::MouseButtonDblClick && watched == m_viewport)
        return onDoubleClick(static_cast<QMouseEvent*>(event));
    return QObject::eventFilter(watched, event);
}

bool GrafcetKeyboard::onKeyPress(QKeyEvent* event)
{
    if (!m_selection)
        return false;
    const Qt::KeyboardModifiers modifiers = event->modifiers() & ~Qt::KeypadModifier;
    switch (event->key()) {
    case Qt::Key_Tab:
    case Qt::Key_Backtab:
        if (modifiers & ~Qt::ShiftModifier)
            return false;
        return walk(event->key() == Qt::Key_Tab && modifiers == Qt::NoModifier);
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_F2:
        if (modifiers != Qt::NoModifier || current().isNull())
            return false;
        // The docks reveal themselves and focus the field.
        m_selection->select(current(), kMainField);
        return true;
    case Qt::Key_Escape:
        if (modifiers != Qt::NoModifier || m_scene->selectedItems().isEmpty())
            return false;
        m_scene->clearSelection();
        return true;
    default:
        return false;
    }
}

bool GrafcetKeyboard::onDoubleClick(QMouseEvent* event)
{
    if (!m_selection || event->button() != Qt::LeftButton)
        return false;
    const ElementRef element = elementAt(event->position().toPoint());
    if (element.isNull())
        return false;
    m_selection->select(element, kMainField);
    return true;
}

bool GrafcetKeyboard::walk(bool next)
{
    const QList<ElementRef> order = drawingOrder();
    if (order.isEmpty())
        return false;
    const qsizetype at = order.indexOf(current());
    const qsizetype count = order.size();
    const qsizetype wanted = at < 0 ? (next ? 0 : count - 1) : (at + (next ? 1 : count - 1)) % count;
    // The Selection scrolls the view to it (GrafcetSelectionSync).
    m_selection->select(order[wanted]);
    return true;
}

ElementRef GrafcetKeyboard::current() const
{
    const ElementRef& element = m_selection->current();
    return element.isNested() && element.id == m_scene->stepId() ? element : ElementRef();
}

ElementRef GrafcetKeyboard::elementAt(const QPoint& viewportPosition) const
{
    for (QGraphicsItem* item : m_view->items(viewportPosition)) {
        for (QGraphicsItem* candidate = item; candidate; candidate = candidate->parentItem()) {
            if (auto* step = qgraphicsitem_cast<GrafcetStepItem*>(candidate))
                return ElementRef::grafcetStep(m_scene->stepId(), step->number());
            if (auto* transition = qgraphicsitem_cast<GrafcetTransitionItem*>(candidate))
                return ElementRef::grafcetTransition(m_scene->stepId(), transition->number());
        }
    }
    return {};
}

} // namespace editor
