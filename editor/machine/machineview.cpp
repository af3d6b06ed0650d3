#include "editor/machine/machineview.h"

#include "editor/machine/machinescene.h"

#include <QEvent>

#include <algorithm>

namespace editor {

MachineView::MachineView(Document* document, SimulationSession* session, QWidget* parent)
    : QGraphicsView(parent)
    , m_scene(new MachineScene(document, session, this))
{
    setObjectName(QStringLiteral("machineView"));
    setScene(m_scene);
    setRenderHint(QPainter::Antialiasing);
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
    // Each item repaints its own cell when its look changes: no full redraws.
    setViewportUpdateMode(QGraphicsView::MinimalViewportUpdate);
    connect(m_scene, &QGraphicsScene::sceneRectChanged, this, &MachineView::fit);
}

void MachineView::fit()
{
    const QRectF rect = m_scene->sceneRect();
    if (rect.isEmpty())
        return;
    const double scale = std::clamp(std::min(viewport()->width() / rect.width(), viewport()->height() / rect.height()),
                                    kMinScale, 1.0);
    setTransform(QTransform::fromScale(scale, scale));
}

void MachineView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    fit();
}

void MachineView::changeEvent(QEvent* event)
{
    QGraphicsView::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) {
        m_scene->update(); // the kinds and roles are words of the UI language
        emit languageChanged();
    }
}

} // namespace editor
