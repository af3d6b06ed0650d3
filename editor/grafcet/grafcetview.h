#pragma once

#include <QGraphicsView>

namespace editor {

class GrafcetScene;

// A nested GRAFCET in a tab beside the GEMMA chart, at its actual size (its
// text at the chart's label size) and scrolled when taller than the tab:
// fitted, a long sequence would shrink to unreadable. Ctrl+wheel zooms.
class GrafcetView : public QGraphicsView {
    Q_OBJECT

public:
    explicit GrafcetView(GrafcetScene* scene, QWidget* parent = nullptr);

    GrafcetScene* grafcetScene() const { return m_scene; }
    double zoom() const;

protected:
    void wheelEvent(QWheelEvent* event) override;
    // The first time: at the top of the drawing, where its initial step is.
    void showEvent(QShowEvent* event) override;

private:
    GrafcetScene* m_scene;
    bool m_shown = false;
    // Scrolled to the top: stays there when the scene grows upwards (the
    // simulation's caption above the drawing).
    bool m_atTop = true;
};

} // namespace editor
