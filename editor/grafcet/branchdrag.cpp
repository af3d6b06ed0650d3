#include "editor/grafcet/branchdrag.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"
#include "editor/commands/editgrafcetcommand.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"

#include "core/model/branchorder.h"
#include "core/model/model.h"

#include <QApplication>
#include <QMouseEvent>
#include <QPainter>

#include <cmath>

namespace editor {

BranchDrag::BranchDrag(Document& document, GrafcetView& view)
    : GrafcetViewOverlay(&view)
    , m_document(document)
    , m_view(view)
{
    setObjectName(QStringLiteral("grafcetBranchDrag"));
    m_view.viewport()->installEventFilter(this);
    m_view.addOverlay(this);
}

// Never consumes an event: the view still selects on the press and release.
bool BranchDrag::eventFilter(QObject*, QEvent* event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        onPress(static_cast<const QMouseEvent&>(*event));
        break;
    case QEvent::MouseMove:
        onMove(static_cast<const QMouseEvent&>(*event));
        break;
    case QEvent::MouseButtonRelease:
        if (static_cast<const QMouseEvent*>(event)->button() == Qt::LeftButton)
            onRelease();
        break;
    default:
        break;
    }
    return false;
}

void BranchDrag::onPress(const QMouseEvent& event)
{
    finish();
    if (event.button() != Qt::LeftButton || m_document.isReadOnly())
        return;
    for (QGraphicsItem* item : m_view.items(event.position().toPoint())) {
        if (item->type() != GrafcetStepItem::Type)
            continue;
        const auto* step = static_cast<const GrafcetStepItem*>(item);
        // The box only: the action boxes beside it are no handle for the branch.
        if (toQRectF(step->layout().box).contains(m_view.mapToScene(event.position().toPoint()))) {
            m_step = step->number();
            m_pressPos = event.position().toPoint();
        }
        return;
    }
}

void BranchDrag::onMove(const QMouseEvent& event)
{
    if (!m_step || !(event.buttons() & Qt::LeftButton))
        return;
    const QPoint pos = event.position().toPoint();
    if (!m_dragging && (pos - m_pressPos).manhattanLength() < QApplication::startDragDistance())
        return;
    m_dragging = true;
    m_cursorX = m_view.mapToScene(pos).x();
    aimAt(m_cursorX);
    m_view.viewport()->update();
}

void BranchDrag::onRelease()
{
    if (m_dragging)
        moveBranch();
    finish();
}

void BranchDrag::finish()
{
    const bool wasDragging = m_dragging;
    m_step = 0;
    m_dragging = false;
    m_offset = 0;
    if (wasDragging)
        m_view.viewport()->update();
}

const GrafcetStepItem* BranchDrag::stepItem() const
{
    return m_view.grafcetScene()->stepItem(m_step);
}

std::vector<double> BranchDrag::branchPlaces(int& index) const
{
    const core::Grafcet* grafcet = m_document.model().grafcet(m_view.grafcetScene()->stepId().toStdString());
    core::BranchPlace place;
    if (!grafcet || !core::findBranch(*grafcet, m_step, place))
        return {};
    index = place.index;
    const GrafcetScene& scene = *m_view.grafcetScene();
    std::vector<double> places;
    // A selection's branch starts with a transition, a parallel one with a step.
    if (place.kind == core::BranchPlace::Kind::Selection) {
        for (const core::GrafcetTransition* t : grafcet->transitionsFrom(place.divergence))
            if (const GrafcetTransitionItem* item = scene.transitionItem(t->number))
                places.push_back(item->layout().barCenter.x);
    } else if (const core::GrafcetTransition* t = grafcet->transition(place.divergence)) {
        for (int step : t->downstream)
            if (const GrafcetStepItem* item = scene.stepItem(step))
                places.push_back(item->layout().box.x + item->layout().box.width / 2);
    }
    if (static_cast<int>(places.size()) != place.count)
        return {}; // a branch not drawn: no place to show
    return places;
}

// Aims at the branch whose place is nearest to sceneX.
void BranchDrag::aimAt(double sceneX)
{
    int index = 0;
    const std::vector<double> places = branchPlaces(index);
    int nearest = index;
    for (int i = 0; i < static_cast<int>(places.size()); ++i)
        if (std::abs(places[i] - sceneX) < std::abs(places[nearest] - sceneX))
            nearest = i;
    m_offset = nearest - index;
    m_markX = places.empty() ? 0 : places[nearest];
}

void BranchDrag::moveBranch()
{
    const QString& stepId = m_view.grafcetScene()->stepId();
    const core::Grafcet* grafcet = m_document.model().grafcet(stepId.toStdString());
    core::BranchPlace place;
    if (!grafcet || !core::findBranch(*grafcet, m_step, place)) {
        // The status bar shows what Document::editFailed reports.
        emit m_document.editFailed(
            tr("Step %1 is on no branch of a divergence: there is no branch to move").arg(m_step));
        return;
    }
    if (m_offset == 0)
        return; // dropped back at its own place
    const int step = m_step;
    const int offset = m_offset;
    const auto wording = [step, offset, stepId] {
        return offset < 0 ? tr("Move the branch of step %1 left in %2").arg(step).arg(stepId)
                          : tr("Move the branch of step %1 right in %2").arg(step).arg(stepId);
    };
    if (!m_document.push(new EditGrafcetCommand(
            m_document, stepId, [step, offset](core::Grafcet& g) { return core::moveBranch(g, step, offset); },
            wording)))
        return;
    // The moved step, selected as the press selected it.
    if (GrafcetStepItem* moved = m_view.grafcetScene()->stepItem(step)) {
        m_view.grafcetScene()->clearSelection();
        moved->setSelected(true);
    }
}

void BranchDrag::paintOverlay(QPainter* painter) const
{
    const GrafcetStepItem* step = m_dragging ? stepItem() : nullptr;
    if (!step)
        return;
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    QRectF ghost = toQRectF(step->layout().box);
    ghost.moveCenter(QPointF(m_cursorX, ghost.center().y()));
    QColor outline = chartstyle::haloColor();
    outline.setAlpha(255);
    painter->setPen(QPen(outline, 1.5, Qt::DashLine));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(ghost);
    if (m_offset != 0) {
        const QRectF box = toQRectF(step->layout().box);
        painter->setPen(QPen(chartstyle::firedColor(), 3, Qt::SolidLine, Qt::RoundCap));
        painter->drawLine(QPointF(m_markX, box.top() - 6), QPointF(m_markX, box.bottom() + 6));
    }
    painter->restore();
}

} // namespace editor
