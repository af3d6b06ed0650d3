#pragma once

#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace editor {

// Structured Text colouring for the code preview: keywords and type names
// bold blue, comments grey italic ((* *) across lines, and //), numbers,
// duration literals (T#20ms) and strings. The colours follow the palette:
// lighter ones on a dark background.
class StHighlighter : public QSyntaxHighlighter {
    Q_OBJECT

public:
    explicit StHighlighter(QTextDocument* document);

    const QTextCharFormat& keywordFormat() const { return m_keyword; }
    const QTextCharFormat& commentFormat() const { return m_comment; }
    const QTextCharFormat& numberFormat() const { return m_number; }
    const QTextCharFormat& durationFormat() const { return m_duration; }

protected:
    void highlightBlock(const QString& text) override;

private:
    // Each returns the position after what it coloured.
    int highlightComment(const QString& text, int start, int contentStart);
    int highlightWord(const QString& text, int start);
    int highlightNumber(const QString& text, int start);
    int highlightString(const QString& text, int start);

    QTextCharFormat m_keyword;
    QTextCharFormat m_comment;
    QTextCharFormat m_number;
    QTextCharFormat m_duration;
    QTextCharFormat m_string;
};

} // namespace editor
