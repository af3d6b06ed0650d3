#include "editor/style/severityicon.h"

#include "editor/style/drawniconengine.h"

#include <QPainter>
#include <QPainterPath>

#include <array>

namespace editor {

namespace {

class SeverityIconEngine : public DrawnIconEngine {
public:
    explicit SeverityIconEngine(core::Severity severity)
        : m_severity(severity)
    {
    }

    QIconEngine* clone() const override { return new SeverityIconEngine(m_severity); }
    QString key() const override { return QStringLiteral("ggstudio-severity"); }

protected:
    void draw(QPainter& painter, QIcon::Mode mode) const override
    {
        if (mode == QIcon::Disabled)
            painter.setOpacity(0.45);
        switch (m_severity) {
        case core::Severity::Error:
            drawError(painter);
            break;
        case core::Severity::Warning:
            drawWarning(painter);
            break;
        case core::Severity::Info:
            drawInfo(painter);
            break;
        }
    }

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
