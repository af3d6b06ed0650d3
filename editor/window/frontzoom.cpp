#include "editor/window/frontzoom.h"

#include "editor/chart/gemma/chartview.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/chart/packml/packmlsheetview.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/window/statusindicators.h"

#include <QTabWidget>

#include <type_traits>

namespace editor {

FrontZoom::FrontZoom(QTabWidget& tabs, ZoomIndicator& indicator, QObject* parent)
    : QObject(parent)
    , m_tabs(tabs)
    , m_indicator(indicator)
{
    connect(&m_tabs, &QTabWidget::currentChanged, this, &FrontZoom::followFront);
    followFront();
}

template <typename Act>
void FrontZoom::onFront(Act act) const
{
    QWidget* front = m_tabs.currentWidget();
    if (auto* grafcet = qobject_cast<GrafcetView*>(front))
        act(*grafcet);
    else if (auto* chart = qobject_cast<ChartView*>(front))
        act(*chart);
    else if (auto* packml = qobject_cast<PackmlChartView*>(front))
        act(*packml->sheetView());
}

double FrontZoom::zoom() const
{
    double zoom = 1.0;
    onFront([&zoom](const auto& view) { zoom = view.zoom(); });
    return zoom;
}

void FrontZoom::zoomIn()
{
    onFront([](auto& view) { view.zoomIn(); });
}

void FrontZoom::zoomOut()
{
    onFront([](auto& view) { view.zoomOut(); });
}

void FrontZoom::zoomToFit()
{
    onFront([](auto& view) { view.zoomToFit(); });
}

void FrontZoom::zoomToActualSize()
{
    onFront([](auto& view) { view.zoomToActualSize(); });
}

// Only the front view's changes reach the indicator: the chart, refitted
// when the window is resized, would otherwise overwrite a GRAFCET's zoom.
void FrontZoom::followFront()
{
    disconnect(m_frontZoomChanged);
    onFront([this](auto& view) {
        using View = std::remove_reference_t<decltype(view)>;
        m_frontZoomChanged = connect(&view, &View::zoomChanged, &m_indicator, &ZoomIndicator::setZoom);
    });
    m_indicator.setZoom(zoom());
}

} // namespace editor
