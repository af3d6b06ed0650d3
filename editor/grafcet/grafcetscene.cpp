#include "editor/grafcet/grafcetscene.h"

#include "editor/chart/chartstyle.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetwiringitem.h"

#include "core/model/model.h"

#include <QFontMetricsF>

namespace editor {

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
    m_rebuilding = true;
    clear();
    m_steps.clear();
    m_transitions.clear();
    const core::Grafcet* grafcet = m_document->model().grafcet(m_stepId.toStdString());
    m_layout = grafcet ? core::layoutGrafcet(*grafcet, &GrafcetScene::textWidth) : core::GrafcetLayout{};
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
    m_rebuilding = false;
    emit rebuilt();
}

QRectF GrafcetScene::drawingRect() const
{
    const core::Rect& bounds = m_layout.boundingRect;
    return QRectF(bounds.x, bounds.y, std::max(bounds.width, 1.0), std::max(bounds.height, 1.0));
}

} // namespace editor
