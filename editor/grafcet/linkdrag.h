#pragma once

// Linking with the mouse in a GRAFCET tab, as in the web GRAFCET editors:
// hovering a step shows a small circle, its connection handle, at the
// bottom of its box; hovering a transition, one under its bar; the
// handle's tooltip says what it is for. A drag that
// starts on a handle draws a rubber line to the cursor and highlights the
// step or transition under it (green when the link can be made, red with
// the reason as tooltip when not); dropping there makes the link as
// core::link() reads its direction, as one undoable command, and selects
// the transition of the link. A refused drop says why in the status bar
// (Document::editFailed) and in a tooltip at the drop point; a drop on the
// background cancels. A click on a handle selects its element as a click
// on the element does; a drag from anywhere else is the view's own
// (selection, scrolling, moving a branch).

#include "editor/grafcet/grafcetview.h"

#include "core/model/grafcetlinking.h"

#include <QObject>
#include <QPoint>
#include <QPointF>
#include <QString>

#include <optional>

class QGraphicsItem;
class QHelpEvent;
class QMouseEvent;

namespace editor {

class Document;

class LinkDrag : public GrafcetViewOverlay {
    Q_OBJECT

public:
    LinkDrag(Document& document, GrafcetView& view);

    // Where an element's handle is drawn, in scene coordinates.
    static QPointF handlePosition(const QGraphicsItem& element);
    // The element whose handle shows (hovered or dragged from); none without.
    std::optional<core::GrafcetLinkEnd> handleShown() const { return m_handle; }
    bool isDragging() const { return m_dragging; }
    // While dragging: the element under the cursor, highlighted, and
    // whether the link to it can be made.
    std::optional<core::GrafcetLinkEnd> dropTarget() const { return m_target; }
    bool isDropValid() const { return m_targetValid; }

    // The user's words for a refused link (status.code from core::checkLink).
    static QString refusalText(const core::Status& status, core::GrafcetLinkEnd from, core::GrafcetLinkEnd to);

    void paintOverlay(QPainter* painter) const override;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool onPress(const QMouseEvent& event);
    bool onMove(const QMouseEvent& event);
    bool onRelease(const QMouseEvent& event);
    bool explainHandle(const QHelpEvent& event);
    void hover(QPoint pos);
    void dragTo(const QMouseEvent& event);
    void drop(const QMouseEvent& event);
    void finish();

    bool canEdit() const;
    QGraphicsItem* itemOf(core::GrafcetLinkEnd end) const;
    std::optional<core::GrafcetLinkEnd> elementAt(QPoint pos) const;
    std::optional<core::GrafcetLinkEnd> handleAt(QPoint pos) const;
    core::Status check(core::GrafcetLinkEnd to) const;
    void makeLink(core::GrafcetLinkEnd to);
    void refuse(const QString& reason, QPoint pos);
    void clickElement(core::GrafcetLinkEnd end, Qt::KeyboardModifiers modifiers);
    void selectOnly(core::GrafcetLinkEnd end);
    // The link's undo text in the current UI language (worded again on a language switch).
    static QString commandText(core::GrafcetLinkEnd from, core::GrafcetLinkEnd to, const QString& stepId);

    Document& m_document;
    GrafcetView& m_view;
    std::optional<core::GrafcetLinkEnd> m_handle;  // hovered, or the drag's source
    std::optional<core::GrafcetLinkEnd> m_source;  // pressed on its handle
    std::optional<core::GrafcetLinkEnd> m_target;  // under the cursor while dragging
    bool m_targetValid = false;
    bool m_dragging = false;
    QPoint m_pressPos;
    QPointF m_cursor; // scene coordinates, while dragging
};

} // namespace editor
