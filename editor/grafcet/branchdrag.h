#pragma once

// Reordering branches with the mouse in a GRAFCET tab: a step dragged by
// its body (not by its connection handle, which links: LinkDrag) sideways
// moves the branch it stands on, among the branches of the innermost
// divergence holding it (core::moveBranch), to the place of the branch
// nearest to where it is dropped. While dragging, a dashed outline of the
// step follows the cursor and a green line marks the place the branch
// will take. One undoable command; a step on no branch of a divergence
// says so in the status bar. The press and release still reach the view,
// so that a click selects as before.

#include "editor/grafcet/grafcetview.h"

#include <QPoint>
#include <QPointF>

#include <optional>
#include <vector>

class QMouseEvent;

namespace editor {

class Document;
class GrafcetStepItem;

class BranchDrag : public GrafcetViewOverlay {
    Q_OBJECT

public:
    BranchDrag(Document& document, GrafcetView& view);

    bool isDragging() const { return m_dragging; }
    // While dragging: the places the branch would move (negative: left),
    // 0 when it stays or cannot move.
    int dropOffset() const { return m_offset; }

    void paintOverlay(QPainter* painter) const override;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onPress(const QMouseEvent& event);
    void onMove(const QMouseEvent& event);
    void onRelease();
    void finish();

    const GrafcetStepItem* stepItem() const;
    // The scene x of each branch of the step's divergence, left to right,
    // and the step's branch among them; empty when it is on none.
    std::vector<double> branchPlaces(int& index) const;
    void aimAt(double sceneX);
    void moveBranch();

    Document& m_document;
    GrafcetView& m_view;
    int m_step = 0; // pressed on its body
    QPoint m_pressPos;
    bool m_dragging = false;
    double m_cursorX = 0; // scene x, while dragging
    int m_offset = 0;
    double m_markX = 0;   // where the green line stands when m_offset is not 0
};

} // namespace editor
