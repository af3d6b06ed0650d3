#include "editor/docks/sthighlighter.h"

#include "core/model/iectypes.h"

#include <QGuiApplication>
#include <QPalette>

namespace editor {

namespace {

enum BlockState { Code = 0, InComment = 1 };

bool isWordStart(QChar c)
{
    return (c.unicode() < 128 && c.isLetter()) || c == u'_';
}

bool isWordCharacter(QChar c)
{
    return c.unicode() < 128 && (c.isLetterOrNumber() || c == u'_');
}

bool isDurationPrefix(const QString& word)
{
    return word.compare(QLatin1String("T"), Qt::CaseInsensitive) == 0
        || word.compare(QLatin1String("TIME"), Qt::CaseInsensitive) == 0
        || word.compare(QLatin1String("LT"), Qt::CaseInsensitive) == 0
        || word.compare(QLatin1String("LTIME"), Qt::CaseInsensitive) == 0;
}

QTextCharFormat colored(const QColor& color)
{
    QTextCharFormat format;
    format.setForeground(color);
    return format;
}

} // namespace

StHighlighter::StHighlighter(QTextDocument* document)
    : QSyntaxHighlighter(document)
{
    const bool dark = QGuiApplication::palette().color(QPalette::Base).lightness() < 128;
    m_keyword = colored(dark ? QColor(0x6c, 0xb6, 0xff) : QColor(0x00, 0x00, 0xc0));
    m_keyword.setFontWeight(QFont::Bold);
    m_comment = colored(dark ? QColor(0x9a, 0x9a, 0x9a) : QColor(0x80, 0x80, 0x80));
    m_comment.setFontItalic(true);
    m_number = colored(dark ? QColor(0xb5, 0xce, 0xa8) : QColor(0x09, 0x86, 0x58));
    m_duration = colored(dark ? QColor(0xd7, 0xba, 0x7d) : QColor(0xa0, 0x52, 0x2d));
    m_string = colored(dark ? QColor(0xce, 0x91, 0x78) : QColor(0xa3, 0x15, 0x15));
}

void StHighlighter::highlightBlock(const QString& text)
{
    setCurrentBlockState(Code);
    int i = 0;
    if (previousBlockState() == InComment)
        i = highlightComment(text, 0, 0);
    const int length = static_cast<int>(text.size());
    while (i < length) {
        const QChar c = text.at(i);
        const QChar next = i + 1 < length ? text.at(i + 1) : QChar();
        if (c == u'(' && next == u'*') {
            i = highlightComment(text, i, i + 2);
        } else if (c == u'/' && next == u'/') {
            setFormat(i, length - i, m_comment);
            i = length;
        } else if (isWordStart(c)) {
            i = highlightWord(text, i);
        } else if (c.isDigit()) {
            i = highlightNumber(text, i);
        } else if (c == u'\'' || c == u'"') {
            i = highlightString(text, i);
        } else {
            ++i;
        }
    }
}

int StHighlighter::highlightComment(const QString& text, int start, int contentStart)
{
    const int end = static_cast<int>(text.indexOf(QLatin1String("*)"), contentStart));
    if (end < 0) {
        setFormat(start, static_cast<int>(text.size()) - start, m_comment);
        setCurrentBlockState(InComment);
        return static_cast<int>(text.size());
    }
    setFormat(start, end + 2 - start, m_comment);
    return end + 2;
}

int StHighlighter::highlightWord(const QString& text, int start)
{
    const int length = static_cast<int>(text.size());
    int end = start;
    while (end < length && isWordCharacter(text.at(end)))
        ++end;
    const QString word = text.mid(start, end - start);
    if (end < length && text.at(end) == u'#' && isDurationPrefix(word)) {
        ++end; // T#1m30s500ms, TIME#20ms
        while (end < length && (isWordCharacter(text.at(end)) || text.at(end) == u'.'))
            ++end;
        setFormat(start, end - start, m_duration);
        return end;
    }
    if (core::isIecKeyword(word.toStdString()))
        setFormat(start, end - start, m_keyword);
    return end;
}

int StHighlighter::highlightNumber(const QString& text, int start)
{
    const int length = static_cast<int>(text.size());
    int end = start;
    while (end < length && (text.at(end).isDigit() || text.at(end) == u'_' || text.at(end) == u'.'))
        ++end;
    if (end < length && (text.at(end) == u'e' || text.at(end) == u'E')) {
        int exponent = end + 1;
        if (exponent < length && (text.at(exponent) == u'+' || text.at(exponent) == u'-'))
            ++exponent;
        if (exponent < length && text.at(exponent).isDigit()) {
            end = exponent;
            while (end < length && text.at(end).isDigit())
                ++end;
        }
    }
    setFormat(start, end - start, m_number);
    return end;
}

int StHighlighter::highlightString(const QString& text, int start)
{
    const QChar quote = text.at(start);
    int end = static_cast<int>(text.indexOf(quote, start + 1));
    end = end < 0 ? static_cast<int>(text.size()) : end + 1;
    setFormat(start, end - start, m_string);
    return end;
}

} // namespace editor
