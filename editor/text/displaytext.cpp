#include "editor/text/displaytext.h"

#include <QStringList>

#include <algorithm>

namespace editor {

namespace {

// The Unicode bidirectional formatting characters (UAX #9): marks, embeddings,
// overrides and isolates.
bool isBidiControl(char32_t c)
{
    return c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069);
}

bool isShownEscaped(char32_t c)
{
    if (c == u'\n' || c == u'\t')
        return false;
    return QChar::category(c) == QChar::Other_Control || isBidiControl(c);
}

} // namespace

QString withVisibleControls(const QString& text)
{
    QString shown;
    shown.reserve(text.size());
    for (qsizetype i = 0; i < text.size(); ++i) {
        char32_t c = text[i].unicode();
        const bool pair = text[i].isHighSurrogate() && i + 1 < text.size() && text[i + 1].isLowSurrogate();
        if (pair)
            c = QChar::surrogateToUcs4(text[i], text[i + 1]);
        if (c == 0x2028 || c == 0x2029)
            shown += QLatin1Char('\n');
        else if (isShownEscaped(c))
            shown += QStringLiteral("<U+%1>").arg(uint(c), 4, 16, QLatin1Char('0')).toUpper();
        else
            shown.append(text.constData() + i, pair ? 2 : 1);
        if (pair)
            ++i;
    }
    return shown;
}

QString elidedText(const QString& text, qsizetype maxCharacters)
{
    qsizetype kept = std::min(text.size(), maxCharacters);
    if (kept > 0 && kept < text.size() && text[kept - 1].isHighSurrogate())
        --kept;
    QString line = text.left(kept);
    for (QChar& c : line) {
        if (c == u'\n' || c == u'\r' || c == u'\t' || c == QChar::LineSeparator || c == QChar::ParagraphSeparator)
            c = u' ';
    }
    if (kept < text.size())
        line += QChar(0x2026);
    return line;
}

QString boundedToolTip(const QString& text, qsizetype maxCharacters, qsizetype lineLength)
{
    qsizetype kept = std::min(text.size(), maxCharacters);
    if (kept > 0 && kept < text.size() && text[kept - 1].isHighSurrogate())
        --kept;
    QStringList lines;
    for (QString rest : text.left(kept).split(QLatin1Char('\n'))) {
        while (rest.size() > lineLength) {
            qsizetype cut = rest.lastIndexOf(QLatin1Char(' '), lineLength);
            if (cut <= 0)
                cut = rest[lineLength - 1].isHighSurrogate() ? lineLength - 1 : lineLength;
            lines << rest.left(cut);
            rest = rest.mid(rest[cut] == u' ' ? cut + 1 : cut);
        }
        lines << rest;
    }
    QString bounded = lines.join(QLatin1Char('\n'));
    if (kept < text.size())
        bounded += QChar(0x2026);
    return bounded;
}

} // namespace editor
