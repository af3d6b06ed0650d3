#pragma once

#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QList>
#include <QSignalBlocker>

namespace editor {

// Unselects a scene's items for the time of a rendering (a picture, a
// print), without telling the shared Selection (the scene's signals are
// blocked), and selects them again.
class HiddenSelection {
public:
    explicit HiddenSelection(QGraphicsScene& scene)
        : m_blocker(&scene)
        , m_selected(scene.selectedItems())
    {
        for (QGraphicsItem* item : m_selected)
            item->setSelected(false);
    }
    ~HiddenSelection()
    {
        for (QGraphicsItem* item : m_selected)
            item->setSelected(true);
    }
    HiddenSelection(const HiddenSelection&) = delete;
    HiddenSelection& operator=(const HiddenSelection&) = delete;

private:
    QSignalBlocker m_blocker;
    QList<QGraphicsItem*> m_selected;
};

} // namespace editor
