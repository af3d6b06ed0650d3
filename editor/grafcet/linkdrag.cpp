#include "editor/grafcet/linkdrag.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"
#include "editor/commands/editgrafcetcommand.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/stdstring.h"

#include "core/model/model.h"

#include <QApplication>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <memory>

namespace editor {

namespace {

constexpr double kHandleRadius = 4.5;    // scene units, as the token
constexpr double kTransitionHandleGap = 9; // below the bar's centre, clear of its stroke
constexpr int kHandleReachPx = 8;        // how near the cursor must be to take a handle
constexpr int kTargetReachPx = 5;        // a thin transition bar is taken this near

using core::GrafcetLinkEnd;

QColor rubberLineColor()
{
    QColor color = chartstyle::haloColor();
    color.setAlpha(255);
    return color;
}

} // namespace

LinkDrag::LinkDrag(Document& document, GrafcetView& view)
    : GrafcetViewOverlay(&view)
    , m_document(document)
    , m_view(view)
{
    setObjectName(QStringLiteral("grafcetLinkDrag"));
    m_view.viewport()->installEventFilter(this);
    m_view.addOverlay(this);
}

QPointF LinkDrag::handlePosition(const QGraphicsItem& element)
{
    if (element.type() == GrafcetStepItem::Type) {
        const QRectF box = toQRectF(static_cast<const GrafcetStepItem&>(element).layout().box);
        return {box.center().x(), box.bottom()};
    }
    const QPointF bar = toQPointF(static_cast<const GrafcetTransitionItem&>(element).layout().barCenter);
    return {bar.x(), bar.y() + kTransitionHandleGap};
}

QString LinkDrag::refusalText(const core::Status& status, GrafcetLinkEnd from, GrafcetLinkEnd to)
{
    const int step = from.isStep() ? from.number : to.number;
    const int transition = from.isStep() ? to.number : from.number;
    if (status.code == core::kLinkTransitionToTransition)
        return tr("A transition cannot be linked to a transition: steps and transitions alternate");
    if (status.code == core::kLinkExists) {
        if (from.isStep() && to.isStep())
            return tr("Step %1 already leads to step %2").arg(from.number).arg(to.number);
        return from.isStep() ? tr("Step %1 already precedes T%2").arg(step).arg(transition)
                             : tr("Step %1 already follows T%2").arg(step).arg(transition);
    }
    if (status.code == core::kLinkStepToItself) {
        if (from.isStep() && to.isStep())
            return tr("Step %1 cannot be linked to itself through one transition").arg(step);
        return tr("Step %1 would be linked to itself through T%2").arg(step).arg(transition);
    }
    return fromStd(status.message);
}

bool LinkDrag::eventFilter(QObject*, QEvent* event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        return onPress(static_cast<const QMouseEvent&>(*event));
    case QEvent::MouseMove:
        return onMove(static_cast<const QMouseEvent&>(*event));
    case QEvent::MouseButtonRelease:
        return onRelease(static_cast<const QMouseEvent&>(*event));
    case QEvent::ToolTip:
        return explainHandle(static_cast<const QHelpEvent&>(*event));
    case QEvent::Leave:
        if (!m_source && m_handle) {
            m_handle.reset();
            m_view.viewport()->update();
        }
        return false;
    default:
        return false;
    }
}

bool LinkDrag::onPress(const QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton || !canEdit())
        return false;
    m_source = handleAt(event.position().toPoint());
    if (!m_source)
        return false;
    m_handle = m_source;
    m_pressPos = event.position().toPoint();
    m_view.viewport()->update();
    return true;
}

bool LinkDrag::onMove(const QMouseEvent& event)
{
    const QPoint pos = event.position().toPoint();
    if (!m_source) {
        if (!(event.buttons() & Qt::LeftButton))
            hover(pos);
        return false;
    }
    if (!m_dragging && (pos - m_pressPos).manhattanLength() >= QApplication::startDragDistance())
        m_dragging = true;
    if (m_dragging)
        dragTo(event);
    return true;
}

bool LinkDrag::onRelease(const QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton || !m_source)
        return false;
    if (m_dragging)
        drop(event);
    else
        clickElement(*m_source, event.modifiers());
    finish();
    return true;
}

// What a first-time user needs to know of the circle under the cursor.
bool LinkDrag::explainHandle(const QHelpEvent& event)
{
    if (!canEdit() || !handleAt(event.pos()))
        return false;
    QToolTip::showText(event.globalPos(), tr("Drag onto a step or a transition to link them"), m_view.viewport());
    return true;
}

void LinkDrag::hover(QPoint pos)
{
    std::optional<GrafcetLinkEnd> handle;
    if (canEdit()) {
        handle = handleAt(pos);
        if (!handle)
            handle = elementAt(pos);
    }
    if (handle == m_handle)
        return;
    m_handle = handle;
    m_view.viewport()->update();
}

void LinkDrag::dragTo(const QMouseEvent& event)
{
    const QPoint pos = event.position().toPoint();
    m_cursor = m_view.mapToScene(pos);
    m_target = elementAt(pos);
    const core::Status status = m_target ? check(*m_target) : core::Status::success();
    m_targetValid = m_target && status.ok;
    if (m_target && !status.ok)
        QToolTip::showText(event.globalPosition().toPoint(), refusalText(status, *m_source, *m_target),
                           m_view.viewport());
    else
        QToolTip::hideText();
    m_view.viewport()->update();
}

void LinkDrag::drop(const QMouseEvent& event)
{
    const QPoint pos = event.position().toPoint();
    const std::optional<GrafcetLinkEnd> target = elementAt(pos);
    if (!target) { // dropped on the background: nothing meant
        QToolTip::hideText();
        return;
    }
    if (const core::Status status = check(*target); !status)
        refuse(refusalText(status, *m_source, *target), event.globalPosition().toPoint());
    else
        makeLink(*target);
}

void LinkDrag::finish()
{
    m_source.reset();
    m_target.reset();
    m_targetValid = false;
    m_dragging = false;
    m_handle.reset();
    m_view.viewport()->update();
}

bool LinkDrag::canEdit() const
{
    return !m_document.isReadOnly()
        && m_document.model().grafcet(m_view.grafcetScene()->stepId().toStdString()) != nullptr;
}

QGraphicsItem* LinkDrag::itemOf(GrafcetLinkEnd end) const
{
    const GrafcetScene& scene = *m_view.grafcetScene();
    if (end.isStep())
        return scene.stepItem(end.number);
    return scene.transitionItem(end.number);
}

std::optional<GrafcetLinkEnd> LinkDrag::elementAt(QPoint pos) const
{
    const QRect reach(pos - QPoint(kTargetReachPx, kTargetReachPx),
                      QSize(2 * kTargetReachPx + 1, 2 * kTargetReachPx + 1));
    const QList<QGraphicsItem*> under = m_view.items(pos) + m_view.items(reach);
    for (QGraphicsItem* item : under) {
        for (; item; item = item->parentItem()) {
            if (item->type() == GrafcetStepItem::Type)
                return GrafcetLinkEnd::step(static_cast<GrafcetStepItem*>(item)->number());
            if (item->type() == GrafcetTransitionItem::Type)
                return GrafcetLinkEnd::transition(static_cast<GrafcetTransitionItem*>(item)->number());
        }
    }
    return std::nullopt;
}

// The nearest handle within reach of `pos`.
std::optional<GrafcetLinkEnd> LinkDrag::handleAt(QPoint pos) const
{
    std::optional<GrafcetLinkEnd> nearest;
    int nearestDistance = kHandleReachPx + 1;
    const auto consider = [&](GrafcetLinkEnd end) {
        const QGraphicsItem* item = itemOf(end);
        if (!item)
            return;
        const int distance = (m_view.mapFromScene(handlePosition(*item)) - pos).manhattanLength();
        if (distance < nearestDistance) {
            nearestDistance = distance;
            nearest = end;
        }
    };
    const core::GrafcetLayout& layout = m_view.grafcetScene()->layout();
    for (const core::GrafcetStepLayout& step : layout.steps)
        consider(GrafcetLinkEnd::step(step.number));
    for (const core::GrafcetTransitionLayout& transition : layout.transitions)
        consider(GrafcetLinkEnd::transition(transition.number));
    return nearest;
}

core::Status LinkDrag::check(GrafcetLinkEnd to) const
{
    const core::Grafcet* grafcet = m_document.model().grafcet(m_view.grafcetScene()->stepId().toStdString());
    if (!grafcet)
        return core::Status::failure(std::string(core::kLinkUnknownElement), "no GRAFCET");
    return core::checkLink(*grafcet, *m_source, to);
}

void LinkDrag::makeLink(GrafcetLinkEnd to)
{
    const GrafcetLinkEnd from = *m_source;
    auto created = std::make_shared<core::GrafcetCreated>();
    auto* command = new EditGrafcetCommand(
        m_document, m_view.grafcetScene()->stepId(),
        [from, to, created](core::Grafcet& g) { return core::link(g, from, to, created.get()); },
        [from, to, stepId = m_view.grafcetScene()->stepId()] { return commandText(from, to, stepId); });
    if (!m_document.push(command))
        return;
    // The transition of the link, ready for its receptivity.
    if (!created->transitions.empty())
        selectOnly(GrafcetLinkEnd::transition(created->transitions.front()));
    else
        selectOnly(from.isStep() ? to : from);
}

void LinkDrag::refuse(const QString& reason, QPoint globalPos)
{
    // The status bar shows what Document::editFailed reports.
    emit m_document.editFailed(reason);
    QToolTip::showText(globalPos, reason, m_view.viewport());
}

// A click on the handle is a click on its element: Ctrl+click adds or removes it.
void LinkDrag::clickElement(GrafcetLinkEnd end, Qt::KeyboardModifiers modifiers)
{
    QGraphicsItem* item = itemOf(end);
    if (item && (modifiers & Qt::ControlModifier))
        item->setSelected(!item->isSelected());
    else
        selectOnly(end);
}

void LinkDrag::selectOnly(GrafcetLinkEnd end)
{
    QGraphicsItem* item = itemOf(end);
    GrafcetScene& scene = *m_view.grafcetScene();
    if (!item || scene.selectedItems() == QList<QGraphicsItem*>{item})
        return;
    // One change of selection, not a clear then a select: each one refreshes
    // the docks that follow the selection.
    QPainterPath area;
    area.addRect(item->sceneBoundingRect().adjusted(-1, -1, 1, 1));
    scene.setSelectionArea(area, Qt::ReplaceSelection, Qt::ContainsItemBoundingRect);
}

QString LinkDrag::commandText(GrafcetLinkEnd from, GrafcetLinkEnd to, const QString& stepId)
{
    if (from.isStep() && to.isStep())
        return tr("Link step %1 to step %2 in %3").arg(from.number).arg(to.number).arg(stepId);
    if (from.isStep())
        return tr("Link step %1 to T%2 in %3").arg(from.number).arg(to.number).arg(stepId);
    return tr("Link T%1 to step %2 in %3").arg(from.number).arg(to.number).arg(stepId);
}

void LinkDrag::paintOverlay(QPainter* painter) const
{
    const QGraphicsItem* handleItem = m_handle ? itemOf(*m_handle) : nullptr;
    if (!handleItem)
        return;
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    const QPointF handle = handlePosition(*handleItem);
    if (m_dragging) {
        painter->setPen(QPen(rubberLineColor(), 1.5, Qt::DashLine));
        painter->drawLine(handle, m_cursor);
        if (const QGraphicsItem* target = m_target ? itemOf(*m_target) : nullptr) {
            QRectF outline;
            if (target->type() == GrafcetStepItem::Type) {
                outline = toQRectF(static_cast<const GrafcetStepItem*>(target)->layout().box).adjusted(-3, -3, 3, 3);
            } else {
                const QPointF bar = toQPointF(static_cast<const GrafcetTransitionItem*>(target)->layout().barCenter);
                const double half = core::kGrafcetBarLength / 2 + 3;
                outline = QRectF(bar.x() - half, bar.y() - 5, 2 * half, 10);
            }
            painter->setPen(QPen(m_targetValid ? chartstyle::firedColor() : chartstyle::problemColor(), 2.5));
            painter->setBrush(Qt::NoBrush);
            painter->drawRoundedRect(outline, 3, 3);
        }
    }
    painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kRouteWidth));
    painter->setBrush(m_source ? rubberLineColor() : chartstyle::stepFillColor());
    painter->drawEllipse(handle, kHandleRadius, kHandleRadius);
    painter->restore();
}

} // namespace editor
