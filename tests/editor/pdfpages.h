#pragma once

// Reading back a PDF the specification export wrote, with poppler-utils
// (pdfinfo, pdftotext, pdftoppm; installed by .ci/install-deps, the tests
// skip when they are missing): its pages' texts, its words and their boxes,
// and the layout checks both templates' specifications pass.

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRectF>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QStringList>
#include <QTest>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>

namespace pdfpages {

inline QString tool(const char* name)
{
    return QStandardPaths::findExecutable(QString::fromLatin1(name));
}

inline bool havePoppler()
{
    return !tool("pdfinfo").isEmpty() && !tool("pdftotext").isEmpty();
}

inline QByteArray run(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.start(program, arguments);
    if (!process.waitForFinished(60000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0)
        return {};
    return process.readAllStandardOutput();
}

// pdfinfo's page count; 0 when it cannot read the file.
inline int pdfinfoPages(const QString& path)
{
    static const QRegularExpression pages(QStringLiteral(R"(^Pages:\s+(\d+)\s*$)"),
                                          QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = pages.match(QString::fromUtf8(run(tool("pdfinfo"), {path})));
    return match.hasMatch() ? match.captured(1).toInt() : 0;
}

// The text of each page (pdftotext pages end in a form feed): "-layout" as
// the page shows it, "-raw" in the order it is drawn (a table cell's lines
// together).
inline QStringList pageTexts(const QString& path, const QString& mode)
{
    QStringList pages = QString::fromUtf8(run(tool("pdftotext"), {mode, path, QStringLiteral("-")}))
                            .split(QLatin1Char('\f'));
    if (!pages.isEmpty() && pages.back().trimmed().isEmpty())
        pages.removeLast();
    return pages;
}

inline QString flat(const QStringList& pages)
{
    return pages.join(QLatin1Char(' ')).simplified();
}

inline QStringList trimmedLines(const QString& page)
{
    QStringList lines;
    for (const QString& line : page.split(QLatin1Char('\n'))) {
        if (!line.trimmed().isEmpty())
            lines << line.trimmed();
    }
    return lines;
}

struct Word {
    QRectF box;
    QString text;
};

struct PageWords {
    QSizeF size;
    QList<Word> words;
};

// Every word with its box, as pdftotext -bbox finds them.
inline QList<PageWords> pageWords(const QString& path)
{
    QList<PageWords> pages;
    QXmlStreamReader xml(run(tool("pdftotext"), {QStringLiteral("-bbox"), path, QStringLiteral("-")}));
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const QXmlStreamAttributes a = xml.attributes();
        if (xml.name() == QLatin1String("page")) {
            pages.append({QSizeF(a.value("width").toDouble(), a.value("height").toDouble()), {}});
        } else if (xml.name() == QLatin1String("word") && !pages.isEmpty()) {
            const QRectF box(QPointF(a.value("xMin").toDouble(), a.value("yMin").toDouble()),
                             QPointF(a.value("xMax").toDouble(), a.value("yMax").toDouble()));
            pages.back().words.append({box, xml.readElementText()});
        }
    }
    return pages;
}

// The numbers of the words "<prefix><n>" in the order they come.
inline QList<int> numberedWords(const QString& text, const QString& prefix)
{
    QList<int> numbers;
    const QRegularExpression word(QStringLiteral("\\b%1(\\d+)\\b").arg(prefix));
    for (auto it = word.globalMatch(text); it.hasNext();)
        numbers << it.next().captured(1).toInt();
    return numbers;
}

inline QList<int> oneTo(int last)
{
    QList<int> numbers;
    for (int n = 1; n <= last; ++n)
        numbers << n;
    return numbers;
}

// A page as pdftoppm renders it, in grey at 72 dpi: a pixel is a point.
inline QImage renderPage(const QString& path, int page)
{
    const QByteArray pgm = run(tool("pdftoppm"), {QStringLiteral("-r"), QStringLiteral("72"), QStringLiteral("-gray"),
                                                  QStringLiteral("-f"), QString::number(page), QStringLiteral("-l"),
                                                  QString::number(page), path});
    return QImage::fromData(pgm, "PGM");
}

// Whether `area` (points from the page's top left) of the rendered page
// has ink: no fill drawn later covers what is drawn there.
inline bool hasInk(const QImage& image, const QRectF& area)
{
    const QRect pixels = area.toAlignedRect().intersected(image.rect());
    for (int y = pixels.top(); y <= pixels.bottom(); ++y) {
        for (int x = pixels.left(); x <= pixels.right(); ++x) {
            if (qGray(image.pixel(x, y)) < 160)
                return true;
        }
    }
    return false;
}

inline QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// No two words of a page overlap, none leaves its page, and the running
// header and the foot keep their ink (no fill of the body covers them).
// With `oneLineHeader`, the running header is the page's first line and
// the foot its last, and nothing of the body reaches into them.
inline void checkLayout(const QString& path, bool oneLineHeader = true)
{
    const QList<PageWords> pages = pageWords(path);
    QCOMPARE(int(pages.size()), pdfinfoPages(path));
    constexpr double kMargin = 10 / 25.4 * 72;
    for (int p = 0; p < pages.size(); ++p) {
        const QRectF sheet(QPointF(0, 0), pages[p].size);
        const QRectF body = sheet.adjusted(kMargin, kMargin + 22, -kMargin, -kMargin - 18);
        const QList<Word>& words = pages[p].words;
        QVERIFY(!words.isEmpty());
        double headerTop = sheet.height();
        double footTop = sheet.height();
        for (const Word& word : words) {
            headerTop = std::min(headerTop, word.box.top());
            if (word.text == QLatin1String("Page"))
                footTop = word.box.top();
        }
        QVERIFY(headerTop < body.top());
        QVERIFY(footTop > body.bottom());
        const auto inChrome = [&](const QRectF& box) {
            return std::abs(box.top() - footTop) < 1
                   || (oneLineHeader ? std::abs(box.top() - headerTop) < 1 : box.bottom() < body.top());
        };
        if (!tool("pdftoppm").isEmpty()) {
            const QImage image = renderPage(path, p + 1);
            QVERIFY(!image.isNull());
            for (const Word& word : words) {
                if (inChrome(word.box))
                    QVERIFY2(hasInk(image, word.box), qPrintable(QStringLiteral("page %1: %2 is covered")
                                                                     .arg(p + 1)
                                                                     .arg(word.text)));
            }
        }
        for (int i = 0; i < words.size(); ++i) {
            const QRectF box = words[i].box;
            const QString where = QStringLiteral("page %1: %2").arg(p + 1).arg(words[i].text);
            QVERIFY2(sheet.contains(box), qPrintable(where));
            if (oneLineHeader)
                QVERIFY2(inChrome(box) || body.adjusted(-1, -2, 1, 2).contains(box), qPrintable(where));
            // Glyph boxes of neighbouring lines touch; a real overlap is more.
            const QRectF inner = words[i].box.adjusted(0.5, 1, -0.5, -1);
            for (int j = i + 1; j < words.size(); ++j) {
                QVERIFY2(!inner.intersects(words[j].box.adjusted(0.5, 1, -0.5, -1)),
                         qPrintable(QStringLiteral("page %1: \"%2\" and \"%3\"")
                                        .arg(p + 1)
                                        .arg(words[i].text, words[j].text)));
            }
        }
    }
}

} // namespace pdfpages
