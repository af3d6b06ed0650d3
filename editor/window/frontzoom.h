#pragma once

// The View menu's zoom entries and the status bar's zoom act on the central
// tab in front: the GEMMA chart or a nested GRAFCET. Each view keeps its own
// zoom; switching tabs shows the new front view's.

#include <QMetaObject>
#include <QObject>

class QTabWidget;

namespace editor {

class ZoomIndicator;

class FrontZoom : public QObject {
    Q_OBJECT

public:
    FrontZoom(QTabWidget& tabs, ZoomIndicator& indicator, QObject* parent = nullptr);

    double zoom() const; // of the front view; 1.0 without one

public slots:
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    void zoomToActualSize();

private:
    // Calls `act` with the front ChartView or GrafcetView, if there is one.
    template <typename Act>
    void onFront(Act act) const;
    void followFront();

    QTabWidget& m_tabs;
    ZoomIndicator& m_indicator;
    QMetaObject::Connection m_frontZoomChanged;
};

} // namespace editor
