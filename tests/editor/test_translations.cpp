// The translations are complete and current: every .ts file in
// translations/ has a finished translation for each text of the editor and
// application sources, and no entry for a text that no longer exists.
//
// Running lupdate on a copy of each file shows both: a text the sources
// gained comes in unfinished, a text they lost becomes "vanished". When this
// fails, run the update_translations target, then translate what it marks
// unfinished (Qt Linguist) and drop what it marks vanished.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

namespace {

struct TsContents {
    QSet<QString> active;   // "context|source|comment" of every current entry
    QStringList unfinished; // the source texts still to translate
    QStringList stale;      // vanished or obsolete: the sources no longer have them
    QString error;
};

TsContents readTs(const QString& path)
{
    TsContents contents;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        contents.error = path + QStringLiteral(": ") + file.errorString();
        return contents;
    }
    QXmlStreamReader xml(&file);
    QString context;
    QString source;
    QString comment;
    QString type;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            if (xml.name() == QLatin1String("name") && source.isNull())
                context = xml.readElementText();
            else if (xml.name() == QLatin1String("message"))
                source = comment = type = QString();
            else if (xml.name() == QLatin1String("source"))
                source = xml.readElementText();
            else if (xml.name() == QLatin1String("comment"))
                comment = xml.readElementText();
            else if (xml.name() == QLatin1String("translation"))
                type = xml.attributes().value(QLatin1String("type")).toString();
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            const QString label = context + QStringLiteral(": ") + source;
            if (type == QLatin1String("vanished") || type == QLatin1String("obsolete"))
                contents.stale << label;
            else
                contents.active.insert(context + '|' + source + '|' + comment);
            if (type == QLatin1String("unfinished"))
                contents.unfinished << label;
            source = QString();
        }
    }
    if (xml.hasError())
        contents.error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return contents;
}

// The first few lines of a list, for a failure message that stays readable.
QString sample(const QStringList& lines)
{
    constexpr int kShown = 8;
    QString text = lines.mid(0, kShown).join(QStringLiteral("\n    "));
    if (lines.size() > kShown)
        text += QStringLiteral("\n    ... and %1 more").arg(lines.size() - kShown);
    return text;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void everyLanguageHasAFile();
    void complete_data();
    void complete();
    void current_data();
    void current();
};

void TestTranslations::everyLanguageHasAFile()
{
    const QDir dir(QStringLiteral(GGSTUDIO_TRANSLATIONS_DIR));
    for (const char* code : {"de", "en", "es", "fr", "it"}) {
        const QString name = QStringLiteral("ggstudio_%1.ts").arg(QLatin1String(code));
        QVERIFY2(dir.exists(name), qPrintable(name));
    }
}

static void addTsRows()
{
    QTest::addColumn<QString>("path");
    const QDir dir(QStringLiteral(GGSTUDIO_TRANSLATIONS_DIR));
    for (const QString& name : dir.entryList({QStringLiteral("ggstudio_*.ts")}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(name)) << dir.filePath(name);
}

void TestTranslations::complete_data()
{
    addTsRows();
}

// No entry left unfinished, none for a text the sources no longer have.
void TestTranslations::complete()
{
    QFETCH(QString, path);
    const TsContents contents = readTs(path);
    QVERIFY2(contents.error.isEmpty(), qPrintable(contents.error));
    QVERIFY2(contents.unfinished.isEmpty(),
             qPrintable(QStringLiteral("%1 of %2 entries are unfinished:\n    %3")
                            .arg(contents.unfinished.size())
                            .arg(contents.active.size())
                            .arg(sample(contents.unfinished))));
    QVERIFY2(contents.stale.isEmpty(), qPrintable(QStringLiteral("%1 entries are vanished or obsolete:\n    %2")
                                                      .arg(contents.stale.size())
                                                      .arg(sample(contents.stale))));
}

void TestTranslations::current_data()
{
    addTsRows();
}

// lupdate on the sources would add nothing and retire nothing.
void TestTranslations::current()
{
    QFETCH(QString, path);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString copy = dir.filePath(QFileInfo(path).fileName());
    QVERIFY(QFile::copy(path, copy));
    QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);

    // The options of the update_translations target (app/gui/CMakeLists.txt),
    // except -no-obsolete: here retired texts must show.
    QStringList arguments{QStringLiteral("-locations"), QStringLiteral("none"), QStringLiteral("-silent")};
    if (path.endsWith(QLatin1String("_en.ts")))
        arguments << QStringLiteral("-pluralonly"); // English is the source language
    arguments << QStringLiteral("@" GGSTUDIO_LUPDATE_LIST) << QStringLiteral("-ts") << copy;
    QProcess lupdate;
    lupdate.start(QStringLiteral(GGSTUDIO_LUPDATE), arguments);
    QVERIFY2(lupdate.waitForStarted(), GGSTUDIO_LUPDATE " does not start");
    QVERIFY(lupdate.waitForFinished(120000));
    QVERIFY2(lupdate.exitStatus() == QProcess::NormalExit && lupdate.exitCode() == 0,
             lupdate.readAllStandardError().constData());

    const TsContents before = readTs(path);
    const TsContents after = readTs(copy);
    QVERIFY2(after.error.isEmpty(), qPrintable(after.error));
    QStringList missing;
    for (const QString& key : after.active) {
        if (!before.active.contains(key))
            missing << key.section('|', 0, 1).replace('|', QStringLiteral(": "));
    }
    missing.sort();
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("%1 source texts are not in the file (run the "
                                                          "update_translations target):\n    %2")
                                               .arg(missing.size())
                                               .arg(sample(missing))));
    QStringList retired;
    for (const QString& key : before.active) {
        if (!after.active.contains(key))
            retired << key.section('|', 0, 1).replace('|', QStringLiteral(": "));
    }
    retired.sort();
    QVERIFY2(retired.isEmpty(), qPrintable(QStringLiteral("%1 entries are for texts the sources no longer have "
                                                          "(run the update_translations target):\n    %2")
                                               .arg(retired.size())
                                               .arg(sample(retired))));
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "test_translations.moc"
