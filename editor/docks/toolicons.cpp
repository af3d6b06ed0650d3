#include "editor/docks/toolicons.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QWidget>

namespace editor {

namespace {

QString themeName(ToolIcon icon)
{
    switch (icon) {
    case ToolIcon::Add:
        return QStringLiteral("list-add");
    case ToolIcon::Remove:
        return QStringLiteral("list-remove");
    case ToolIcon::Duplicate:
        return QStringLiteral("edit-copy");
    case ToolIcon::MoveUp:
        return QStringLiteral("go-up");
    case ToolIcon::MoveDown:
        return QStringLiteral("go-down");
    case ToolIcon::SortByName:
        return QStringLiteral("view-sort-ascending");
    }
    return {};
}

// Draws on a 16 x 16 grid, scaled to the pixmap.
void draw(QPainter& painter, ToolIcon icon)
{
    switch (icon) {
    case ToolIcon::Add:
        painter.drawLine(QPointF(8, 3), QPointF(8, 13));
        painter.drawLine(QPointF(3, 8), QPointF(13, 8));
        break;
    case ToolIcon::Remove:
        painter.drawLine(QPointF(3, 8), QPointF(13, 8));
        break;
    case ToolIcon::Duplicate:
        painter.drawRect(QRectF(2.5, 2.5, 7, 8));
        painter.drawRect(QRectF(6.5, 5.5, 7, 8));
        break;
    case ToolIcon::MoveUp:
    case ToolIcon::MoveDown: {
        painter.save();
        if (icon == ToolIcon::MoveDown) {
            painter.translate(16, 16);
            painter.rotate(180);
        }
        painter.drawLine(QPointF(8, 3.5), QPointF(8, 13));
        painter.drawPolyline(QPolygonF({ QPointF(4, 7.5), QPointF(8, 3.5), QPointF(12, 7.5) }));
        painter.restore();
        break;
    }
    case ToolIcon::SortByName: {
        // Three bars growing downwards and an arrow: ascending.
        painter.drawLine(QPointF(2, 4), QPointF(6, 4));
        painter.drawLine(QPointF(2, 8), QPointF(8, 8));
        painter.drawLine(QPointF(2, 12), QPointF(10, 12));
        painter.drawLine(QPointF(13, 3), QPointF(13, 13));
        painter.drawPolyline(QPolygonF({ QPointF(11, 11), QPointF(13, 13), QPointF(15, 11) }));
        break;
    }
    }
}

QPixmap pixmap(ToolIcon icon, const QColor& color, int size)
{
    QPixmap result(size, size);
    result.fill(Qt::transparent);
    QPainter painter(&result);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.scale(size / 16.0, size / 16.0);
    QPen pen(color, 1.6);
    pen.setCapStyle(Qt::RoundCap);
    pen.setJoinStyle(Qt::RoundJoin);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    draw(painter, icon);
    return result;
}

// "hicolor" is the fallback every system has, and by the icon theme
// specification holds application icons only: a lookup there always fails,
// after scanning its folders for the name and each shorter form of it
// (about a millisecond per icon, as the docks are first built).
bool hasActionIconTheme()
{
    const QString theme = QIcon::themeName();
    return !theme.isEmpty() && theme != QLatin1String("hicolor");
}

} // namespace

QIcon toolIcon(ToolIcon icon, const QWidget* widget)
{
    const QString name = themeName(icon);
    if (hasActionIconTheme() && QIcon::hasThemeIcon(name))
        return QIcon::fromTheme(name);
    const QPalette& palette = widget->palette();
    QIcon result;
    for (int size : { 16, 24, 32 }) {
        result.addPixmap(pixmap(icon, palette.color(QPalette::Active, QPalette::ButtonText), size), QIcon::Normal);
        result.addPixmap(pixmap(icon, palette.color(QPalette::Disabled, QPalette::ButtonText), size), QIcon::Disabled);
    }
    return result;
}

} // namespace editor
