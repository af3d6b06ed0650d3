#include "editor/severityicon.h"

#include <QIconEngine>
#include <QPainter>
#include <QPainterPath>

#include <array>

namespace editor {

namespace {

// Draws the mark in any size, so the icon is sharp at every device pixel ratio.
class SeverityIconEngine : public QIconEngine {
public:
    explicit SeverityIconEngine(core::Severity severity)
        : m_severity(severity)
    {
    }

    void paint(QPainter* painter, const QRect& rect, QIcon::Mode mode, QIcon::State) override
    {
        const qreal side = std::min(rect.width(), rect.height());
        if (side <= 0)
            return;
        painter->save();
        painter->setRenderHint(QPainter::Antialiasing);
        painter->translate(rect.center() - QPointF(side / 2.0, side / 2.0) + QPointF(0.5, 0.5));
        painter->scale(side / 16.0, side / 16.0); // drawn on a 16 x 16 grid
        if (mode == QIcon::Disabled)
            painter->setOpacity(0.45);
        switch (m_severity) {
        case core::Severity::Error:
            drawError(*painter);
            break;
        case core::Severity::Warning:
            drawWarning(*painter);
            break;
        case core::Severity::Info:
            drawInfo(*painter);
            break;
        }
        painter->restore();
    }

    // QIconEngine's own leaves the pixmap uninitialised around the drawing.
    // QIcon asks for device pixels here and sets the pixel ratio itself.
    QPixmap pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state) override
    {
        QPixmap pixmap(size);
        pixmap.fill(Qt::transparent);
        QPainter painter(&pixmap);
        paint(&painter, QRect(QPoint(0, 0), size), mode, state);
        return pixmap;
    }

    QIconEngine* clone() const override { return new SeverityIconEngine(m_severity); }
    QString key() const override { return QStringLiteral("ggstudio-severity"); }

private:
    static void drawError(QPainter& painter)
    {
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(0xd3, 0x2f, 0x2f));
        painter.drawEllipse(QRectF(0.5, 0.5, 14.0, 14.0));
        painter.setPen(QPen(Qt::white, 2.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(QPointF(5.0, 5.0), QPointF(10.0, 10.0));
        painter.drawLine(QPointF(10.0, 5.0), QPointF(5.0, 10.0));
    }

    static void drawWarning(QPainter& painter)
    {
        QPainterPath triangle;
        triangle.moveTo(7.5, 0.8);
        triangle.lineTo(14.7, 14.2);
        triangle.lineTo(0.3, 14.2);
        triangle.closeSubpath();
        painter.setPen(QPen(QColor(0xb2, 0x6a, 0x00), 1.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.setBrush(QColor(0xf9, 0xa8, 0x25));
        painter.drawPath(triangle);
        painter.setPen(QPen(QColor(0x33, 0x26, 0x00), 2.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(QPointF(7.5, 5.5), QPointF(7.5, 9.0));
        painter.drawPoint(QPointF(7.5, 11.8));
    }

    static void drawInfo(QPainter& painter)
    {
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(0x19, 0x76, 0xd2));
        painter.drawEllipse(QRectF(0.5, 0.5, 14.0, 14.0));
        painter.setPen(QPen(Qt::white, 2.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawPoint(QPointF(7.5, 4.2));
        painter.drawLine(QPointF(7.5, 7.0), QPointF(7.5, 11.0));
    }

    core::Severity m_severity;
};

} // namespace

QIcon severityIcon(core::Severity severity)
{
    // One icon of each, shared: QIcon is implicitly shared and caches its pixmaps.
    static const std::array<QIcon, 3> icons{
        QIcon(new SeverityIconEngine(core::Severity::Error)),
        QIcon(new SeverityIconEngine(core::Severity::Warning)),
        QIcon(new SeverityIconEngine(core::Severity::Info)),
    };
    switch (severity) {
    case core::Severity::Error:
        return icons[0];
    case core::Severity::Warning:
        return icons[1];
    case core::Severity::Info:
        return icons[2];
    }
    return {};
}

} // namespace editor
