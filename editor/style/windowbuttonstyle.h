#pragma once

#include <QProxyStyle>

namespace editor {

// Qt's own styles (Fusion, Windows) with the small glyphs GG Studio uses
// drawn instead of loaded: the close and float buttons of dock title bars,
// the overflow arrow of menu bars and tool bars, the clear button of line
// edits and the media controls of the Simulation dock. The styles look
// those up in the icon theme first, and the first lookup sets up Qt's icon
// loader: about a third of the instructions of building the docks after
// the first frame.
//
// Those styles load the glyphs from PNG files, and the first PNG read goes
// through QImageReader, which loads every installed image-format plugin
// (GIF, JPEG, SVG, TIFF, WebP... and with KDE's image formats a dozen more,
// each with its libraries) to ask whether it reads PNG. The dock title
// bars are in the first frame, so that cost was paid before the chart
// showed. Drawn glyphs also stay sharp at any scale. Platform styles
// (Breeze, ...) draw their own buttons and are left as they are.
//
// It also tells QMainWindow not to animate the docks of a window that is
// not on screen yet: for every layout pass Qt creates a geometry animation
// of no length for each dock, separator and tab bar whenever the style has
// an animation duration, 67 of them before the first frame (1 M
// instructions). Docks moved in a shown window animate as before.
class WindowButtonStyle : public QProxyStyle {
    Q_OBJECT

public:
    // `base`: the style to follow; the proxy takes it over.
    explicit WindowButtonStyle(QStyle* base);

    int styleHint(StyleHint hint, const QStyleOption* option = nullptr, const QWidget* widget = nullptr,
                  QStyleHintReturn* returnData = nullptr) const override;
    QIcon standardIcon(StandardPixmap standardIcon, const QStyleOption* option = nullptr,
                       const QWidget* widget = nullptr) const override;

    // Whether the style named `styleName` ("fusion", "Windows") is one of Qt's own.
    static bool appliesTo(const QString& styleName);

    // Wraps the application's style when it is one of Qt's own; once, at start-up.
    static void install();
};

} // namespace editor
