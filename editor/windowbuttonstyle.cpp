#include "editor/windowbuttonstyle.h"

#include "editor/drawniconengine.h"

#include <QApplication>
#include <QPainter>
#include <QStyleFactory>
#include <QStyleOption>

namespace editor {

namespace {

enum class Glyph {
    Close, Float, ArrowRight, ArrowLeft, ArrowDown, ClearText,
    // Media controls (the Simulation dock): filled shapes.
    Play, Pause, SkipForward, SkipBackward, Stop,
};

bool isMediaGlyph(Glyph glyph)
{
    return glyph == Glyph::Play || glyph == Glyph::Pause || glyph == Glyph::SkipForward
        || glyph == Glyph::SkipBackward || glyph == Glyph::Stop;
}

// A glyph in the palette's text colour.
class WindowButtonIconEngine : public DrawnIconEngine {
public:
    explicit WindowButtonIconEngine(Glyph glyph)
        : m_glyph(glyph)
    {
    }

    QIconEngine* clone() const override { return new WindowButtonIconEngine(m_glyph); }

    QString key() const override { return QStringLiteral("ggstudio-window-button"); }

protected:
    void draw(QPainter& painter, QIcon::Mode mode) const override
    {
        const QPalette::ColorGroup group = mode == QIcon::Disabled ? QPalette::Disabled : QPalette::Active;
        const QColor ink = QGuiApplication::palette().color(group, QPalette::WindowText);
        if (m_glyph == Glyph::ClearText) {
            drawClearText(painter, ink, QGuiApplication::palette().color(group, QPalette::Base));
            return;
        }
        if (isMediaGlyph(m_glyph)) {
            painter.setPen(Qt::NoPen);
            painter.setBrush(ink);
            drawMediaGlyph(painter);
            return;
        }
        painter.setPen(QPen(ink, 1.3, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.setBrush(Qt::NoBrush);
        drawGlyph(painter);
    }

private:
    void drawGlyph(QPainter& painter) const
    {
        switch (m_glyph) {
        case Glyph::Close:
            painter.drawLine(QPointF(4.5, 4.5), QPointF(10.5, 10.5));
            painter.drawLine(QPointF(10.5, 4.5), QPointF(4.5, 10.5));
            return;
        case Glyph::Float:
            // A window in front of another: the one behind shows its top and right.
            painter.drawPolyline(QPolygonF({QPointF(5.5, 5.0), QPointF(5.5, 3.0), QPointF(12.0, 3.0),
                                            QPointF(12.0, 9.5), QPointF(10.0, 9.5)}));
            painter.drawRect(QRectF(3.0, 5.5, 6.5, 6.5));
            return;
        case Glyph::ClearText:
        case Glyph::Play:
        case Glyph::Pause:
        case Glyph::SkipForward:
        case Glyph::SkipBackward:
        case Glyph::Stop:
            return; // drawClearText(), drawMediaGlyph()
        case Glyph::ArrowRight:
        case Glyph::ArrowLeft:
        case Glyph::ArrowDown:
            painter.translate(7.5, 7.5);
            painter.rotate(m_glyph == Glyph::ArrowLeft ? 180 : m_glyph == Glyph::ArrowDown ? 90 : 0);
            for (const qreal x : {-3.5, 0.5}) // a double chevron, as overflow arrows are drawn
                painter.drawPolyline(QPolygonF({QPointF(x, -3.5), QPointF(x + 3.0, 0.0), QPointF(x, 3.5)}));
            return;
        }
    }

    // A line edit's clear button: a cross cut out of a soft disc, as the
    // styles' own image shows it.
    static void drawClearText(QPainter& painter, QColor ink, QColor cut)
    {
        ink.setAlphaF(0.55);
        painter.setPen(Qt::NoPen);
        painter.setBrush(ink);
        painter.drawEllipse(QPointF(7.5, 7.5), 6.0, 6.0);
        painter.setPen(QPen(cut, 1.4, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(QPointF(5.0, 5.0), QPointF(10.0, 10.0));
        painter.drawLine(QPointF(10.0, 5.0), QPointF(5.0, 10.0));
    }

    void drawMediaGlyph(QPainter& painter) const
    {
        const QPolygonF playTriangle({QPointF(4.0, 2.5), QPointF(12.5, 7.5), QPointF(4.0, 12.5)});
        switch (m_glyph) {
        case Glyph::Play:
            painter.drawPolygon(playTriangle);
            return;
        case Glyph::Pause:
            painter.drawRect(QRectF(4.0, 3.0, 2.5, 9.0));
            painter.drawRect(QRectF(8.5, 3.0, 2.5, 9.0));
            return;
        case Glyph::SkipForward:
        case Glyph::SkipBackward:
            // A triangle against a bar; mirrored for backward.
            if (m_glyph == Glyph::SkipBackward) {
                painter.translate(15.0, 0.0);
                painter.scale(-1.0, 1.0);
            }
            painter.drawPolygon(QPolygonF({QPointF(3.0, 3.0), QPointF(10.0, 7.5), QPointF(3.0, 12.0)}));
            painter.drawRect(QRectF(10.5, 3.0, 2.0, 9.0));
            return;
        case Glyph::Stop:
            painter.drawRect(QRectF(3.5, 3.5, 8.0, 8.0));
            return;
        default:
            return;
        }
    }

    Glyph m_glyph;
};

bool rightToLeft(const QStyleOption* option)
{
    return option ? option->direction == Qt::RightToLeft : QGuiApplication::isRightToLeft();
}

} // namespace

WindowButtonStyle::WindowButtonStyle(QStyle* base)
    : QProxyStyle(base)
{
}

QIcon WindowButtonStyle::standardIcon(StandardPixmap standardIcon, const QStyleOption* option,
                                      const QWidget* widget) const
{
    switch (standardIcon) {
    case SP_TitleBarCloseButton:
    case SP_DockWidgetCloseButton:
        return QIcon(new WindowButtonIconEngine(Glyph::Close));
    case SP_TitleBarNormalButton:
        return QIcon(new WindowButtonIconEngine(Glyph::Float));
    case SP_ToolBarHorizontalExtensionButton:
        return QIcon(new WindowButtonIconEngine(rightToLeft(option) ? Glyph::ArrowLeft : Glyph::ArrowRight));
    case SP_ToolBarVerticalExtensionButton:
        return QIcon(new WindowButtonIconEngine(Glyph::ArrowDown));
    case SP_LineEditClearButton:
        return QIcon(new WindowButtonIconEngine(Glyph::ClearText));
    case SP_MediaPlay:
        return QIcon(new WindowButtonIconEngine(Glyph::Play));
    case SP_MediaPause:
        return QIcon(new WindowButtonIconEngine(Glyph::Pause));
    case SP_MediaSkipForward:
        return QIcon(new WindowButtonIconEngine(Glyph::SkipForward));
    case SP_MediaSkipBackward:
        return QIcon(new WindowButtonIconEngine(Glyph::SkipBackward));
    case SP_MediaStop:
        return QIcon(new WindowButtonIconEngine(Glyph::Stop));
    default:
        return QProxyStyle::standardIcon(standardIcon, option, widget);
    }
}

bool WindowButtonStyle::appliesTo(const QString& styleName)
{
    return styleName.compare(QLatin1String("fusion"), Qt::CaseInsensitive) == 0
        || styleName.compare(QLatin1String("windows"), Qt::CaseInsensitive) == 0;
}

void WindowButtonStyle::install()
{
    const QString name = QApplication::style()->name();
    if (!appliesTo(name))
        return;
    // A new instance of the style chosen (by -style, QT_STYLE_OVERRIDE or the
    // desktop), so that the application's own one is replaced, not shared.
    if (QStyle* base = QStyleFactory::create(name))
        QApplication::setStyle(new WindowButtonStyle(base));
}

} // namespace editor
