#pragma once

#include <QIconEngine>

namespace editor {

// An icon drawn rather than loaded: subclasses draw on a 16 x 16 grid,
// scaled to whatever size is asked, so the icon is sharp at every device
// pixel ratio and costs no image reading.
class DrawnIconEngine : public QIconEngine {
public:
    void paint(QPainter* painter, const QRect& rect, QIcon::Mode mode, QIcon::State state) override;

    // QIconEngine's own leaves the pixmap uninitialised around the drawing.
    // QIcon asks for device pixels here and sets the pixel ratio itself.
    QPixmap pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state) override;

protected:
    // Draws on the 16 x 16 grid; the painter is antialiased and saved around the call.
    virtual void draw(QPainter& painter, QIcon::Mode mode) const = 0;
};

} // namespace editor
