#pragma once

#include "core/templates/gemma/gemmachartlayout.h"

#include <QCoreApplication>
#include <QGraphicsItem>

namespace editor {

// The tinted rectangle of a GEMMA family (A, F or D) with its title.
// Not selectable: a click on it clears the selection.
class FrameItem : public QGraphicsItem {
    Q_DECLARE_TR_FUNCTIONS(editor::FrameItem)

public:
    enum { Type = QGraphicsItem::UserType + 3 };

    explicit FrameItem(const core::FrameLayout& layout, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    core::Family family() const { return m_family; }
    // "A — Stop procedures", in the UI language.
    QString title() const;
    // title() as last painted, elided to its place; null before the first paint.
    const QString& displayedTitle() const { return m_shownTitle; }
    // After a change of language: the title is elided anew on the next paint.
    void retranslate();

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    core::Family m_family;
    QRectF m_rect;
    QRectF m_titleRect;
    QString m_shownTitle; // title(), elided to m_titleRect; null until painted
};

} // namespace editor
