#pragma once

#include "core/templates/packml/packmlchartlayout.h"

#include <QGraphicsItem>
#include <QString>

namespace editor {

// The Stop or the Abort frame: a tinted rectangle around the states that
// accept its command, titled with the command's PackTags name. Its arrow is
// a PackmlArrowItem of its own. Not selectable: a click on it clears the
// selection, as on a GEMMA family frame.
class PackmlFrameItem : public QGraphicsItem {
public:
    enum { Type = QGraphicsItem::UserType + 23 };

    explicit PackmlFrameItem(const core::packml::ChartFrame& frame, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    core::packml::Command command() const { return m_command; }
    const QString& title() const { return m_title; }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    core::packml::Command m_command;
    QRectF m_rect;
    QRectF m_titleRect;
    QString m_title;
};

} // namespace editor
