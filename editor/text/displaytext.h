#pragma once

#include <QString>

namespace editor {

// The user's texts where they could mislead or overwhelm what shows them.

// `text` with its control characters (but line breaks and tabs) and its
// bidirectional formatting characters written as `<U+202E>`: unseen, they
// would reorder what follows (a right-to-left override turns a title
// around) or hide text. Line and paragraph separators become line breaks.
QString withVisibleControls(const QString& text);

// The characters of the user's text shown in a table cell or quoted in a
// message; of a tooltip. Enough for any text written to be read there; the
// editor it is edited in holds all of it.
constexpr qsizetype kShownTextLimit = 300;
constexpr qsizetype kToolTipTextLimit = 2000;

// `text` on one line, its line breaks and tabs as spaces, cut after
// `maxCharacters` characters with "…": a table cell or a tooltip lays out
// what it is given, and a text of megabytes would freeze the window before
// it could elide it to the cell. The cut never splits a surrogate pair.
QString elidedText(const QString& text, qsizetype maxCharacters = kShownTextLimit);

// A tooltip of `text`: at most `maxCharacters`, cut with "…", and its lines
// broken (at a space when there is one) every `lineLength` characters, so
// that it stays narrower than a screen.
QString boundedToolTip(const QString& text, qsizetype maxCharacters = kToolTipTextLimit, qsizetype lineLength = 100);

} // namespace editor
