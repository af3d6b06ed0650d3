#include "editor/style/windowbuttonstyle.h"

#include "editor/style/drawniconengine.h"

#include <QApplication>
#include <QPainter>
#include <QStyleFactory>
#include <QStyleOption>

#include <optional>

namespace editor {

namespace {

enum class Glyph {
    Close, Float, ArrowRight, ArrowLeft, ArrowDown, ClearText,
    // Media controls (the Simulation dock).
    Play, Pause, SkipForward, SkipBackward, Stop,
};

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
        const QPalette& palette = QGuiApplication::palette();
        drawGlyph(painter, palette.color(group, QPalette::WindowText), palette.color(group, QPalette::Base));
    }

private:
    // Window buttons and arrows are outlines; media controls are filled.
    static void outline(QPainter& painter, const QColor& ink)
    {
        painter.setPen(QPen(ink, 1.3, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.setBrush(Qt::NoBrush);
    }

    static void fill(QPainter& painter, const QColor& ink)
    {
        painter.setPen(Qt::NoPen);
        painter.setBrush(ink);
    }

    // `ink` draws the glyph; `base`, the field's background, cuts into it.
    void drawGlyph(QPainter& painter, QColor ink, const QColor& base) const
    {
        switch (m_glyph) {
        case Glyph::Close:
            outline(painter, ink);
            painter.drawLine(QPointF(4.5, 4.5), QPointF(10.5, 10.5));
            painter.drawLine(QPointF(10.5, 4.5), QPointF(4.5, 10.5));
            return;
        case Glyph::Float:
            // A window in front of another: the one behind shows its top and right.
            outline(painter, ink);
            painter.drawPolyline(QPolygonF({QPointF(5.5, 5.0), QPointF(5.5, 3.0), QPointF(12.0, 3.0),
                                            QPointF(12.0, 9.5), QPointF(10.0, 9.5)}));
            painter.drawRect(QRectF(3.0, 5.5, 6.5, 6.5));
            return;
        case Glyph::ArrowRight:
        case Glyph::ArrowLeft:
        case Glyph::ArrowDown:
            outline(painter, ink);
            painter.translate(7.5, 7.5);
            painter.rotate(m_glyph == Glyph::ArrowLeft ? 180 : m_glyph == Glyph::ArrowDown ? 90 : 0);
            for (const qreal x : {-3.5, 0.5}) // a double chevron, as overflow arrows are drawn
                painter.drawPolyline(QPolygonF({QPointF(x, -3.5), QPointF(x + 3.0, 0.0), QPointF(x, 3.5)}));
            return;
        case Glyph::ClearText:
            // A cross cut out of a soft disc, as the styles' own image shows it.
            ink.setAlphaF(0.55);
            fill(painter, ink);
            painter.drawEllipse(QPointF(7.5, 7.5), 6.0, 6.0);
            painter.setPen(QPen(base, 1.4, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(QPointF(5.0, 5.0), QPointF(10.0, 10.0));
            painter.drawLine(QPointF(10.0, 5.0), QPointF(5.0, 10.0));
            return;
        case Glyph::Play:
            fill(painter, ink);
            painter.drawPolygon(QPolygonF({QPointF(4.0, 2.5), QPointF(12.5, 7.5), QPointF(4.0, 12.5)}));
            return;
        case Glyph::Pause:
            fill(painter, ink);
            painter.drawRect(QRectF(4.0, 3.0, 2.5, 9.0));
            painter.drawRect(QRectF(8.5, 3.0, 2.5, 9.0));
            return;
        case Glyph::SkipForward:
        case Glyph::SkipBackward:
            // A triangle against a bar; mirrored for backward.
            fill(painter, ink);
            if (m_glyph == Glyph::SkipBackward) {
                painter.translate(15.0, 0.0);
                painter.scale(-1.0, 1.0);
            }
            painter.drawPolygon(QPolygonF({QPointF(3.0, 3.0), QPointF(10.0, 7.5), QPointF(3.0, 12.0)}));
            painter.drawRect(QRectF(10.5, 3.0, 2.0, 9.0));
            return;
        case Glyph::Stop:
            fill(painter, ink);
            painter.drawRect(QRectF(3.5, 3.5, 8.0, 8.0));
            return;
        }
    }

    Glyph m_glyph;
};

bool rightToLeft(const QStyleOption* option)
{
    return option ? option->direction == Qt::RightToLeft : QGuiApplication::isRightToLeft();
}

// The glyph drawn for `pixmap`, if it is one of those this style draws.
std::optional<Glyph> drawnGlyph(QStyle::StandardPixmap pixmap, const QStyleOption* option)
{
    switch (pixmap) {
    case QStyle::SP_TitleBarCloseButton:
    case QStyle::SP_DockWidgetCloseButton: return Glyph::Close;
    case QStyle::SP_TitleBarNormalButton: return Glyph::Float;
    case QStyle::SP_ToolBarHorizontalExtensionButton: return rightToLeft(option) ? Glyph::ArrowLeft : Glyph::ArrowRight;
    case QStyle::SP_ToolBarVerticalExtensionButton: return Glyph::ArrowDown;
    case QStyle::SP_LineEditClearButton: return Glyph::ClearText;
    case QStyle::SP_MediaPlay: return Glyph::Play;
    case QStyle::SP_MediaPause: return Glyph::Pause;
    case QStyle::SP_MediaSkipForward: return Glyph::SkipForward;
    case QStyle::SP_MediaSkipBackward: return Glyph::SkipBackward;
    case QStyle::SP_MediaStop: return Glyph::Stop;
    default: return std::nullopt;
    }
}

} // namespace

WindowButtonStyle::WindowButtonStyle(QStyle* base)
    : QProxyStyle(base)
{
}

int WindowButtonStyle::styleHint(StyleHint hint, const QStyleOption* option, const QWidget* widget,
                                 QStyleHintReturn* returnData) const
{
    // A widget whose window is hidden: QMainWindow's layout places it at once.
    if (hint == SH_Widget_Animation_Duration && widget && !widget->window()->isVisible())
        return 0;
    return QProxyStyle::styleHint(hint, option, widget, returnData);
}

QIcon WindowButtonStyle::standardIcon(StandardPixmap standardIcon, const QStyleOption* option,
                                      const QWidget* widget) const
{
    if (const std::optional<Glyph> glyph = drawnGlyph(standardIcon, option))
        return QIcon(new WindowButtonIconEngine(*glyph));
    return QProxyStyle::standardIcon(standardIcon, option, widget);
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
