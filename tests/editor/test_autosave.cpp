// Autosave and recovery, in QStandardPaths' test locations.

#include "editor/autosave.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/document.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>

using namespace editor;

namespace {

const RecoveryFile* findFor(const std::vector<RecoveryFile>& files, const QString& originalPath)
{
    for (const RecoveryFile& file : files) {
        if (file.originalPath == originalPath)
            return &file;
    }
    return nullptr;
}

} // namespace

class TestAutosave : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanupTestCase();

    void writesOnlyWhenModified();
    void recoverRestoresUnsavedEdit();
    void recoveredUntitledDocument();
    void undoToSavedStateRemovesCopy();
    void saveAsMovesTheCopy();
    void discardRemovesCopy();
    void unreadableCopyIsReported();

private:
    QTemporaryDir m_files;
};

void TestAutosave::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setApplicationName("ggstudio-editor-tests");
    QVERIFY(m_files.isValid());
    QVERIFY(Autosave::recoveryDirectory().contains(".qttest"));
}

void TestAutosave::init()
{
    QDir(Autosave::recoveryDirectory()).removeRecursively();
}

void TestAutosave::cleanupTestCase()
{
    // Test mode: this is a folder of the tests' own, under ~/.qttest.
    QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).removeRecursively();
}

void TestAutosave::writesOnlyWhenModified()
{
    Document document;
    Autosave autosave(document);
    QCOMPARE(autosave.interval(), Autosave::kDefaultIntervalMs);
    autosave.setInterval(20);
    QTest::qWait(100);
    QVERIFY(!QFile::exists(autosave.recoveryPath()));
    QVERIFY(autosave.recoveryPath().endsWith("/recovery/untitled.json"));

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(autosave.recoveryPath()), 5000);

    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().recoveryPath, autosave.recoveryPath());
    QVERIFY(pending.front().originalPath.isEmpty());
    QVERIFY(pending.front().savedAt.isValid());
}

void TestAutosave::recoverRestoresUnsavedEdit()
{
    const QString path = m_files.filePath("press.ggs.json");
    std::unique_ptr<core::Model> edited;
    QString copyPath;
    {
        Document document;
        QString error;
        QVERIFY2(document.save(path, &error), qPrintable(error));
        Autosave autosave(document);
        QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
        QVERIFY(document.push(new SetStepHiddenCommand(document, "D3", true)));
        QVERIFY(autosave.writeNow());
        copyPath = autosave.recoveryPath();
        QVERIFY(!copyPath.endsWith("untitled.json"));
        edited = std::make_unique<core::Model>(document.model());
        // The editor dies here: no save, no discard.
    }
    QVERIFY(QFile::exists(copyPath));

    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    const RecoveryFile* file = findFor(pending, path);
    QVERIFY(file);
    QCOMPARE(file->recoveryPath, copyPath);

    Document document;
    Autosave autosave(document); // as the next session binds it
    QString error;
    QVERIFY2(Autosave::recover(*file, document, &error), qPrintable(error));
    QVERIFY(document.model().sameContent(*edited));
    QVERIFY(document.isModified()); // the user must save
    QCOMPARE(document.filePath(), path);
    QCOMPARE(autosave.recoveryPath(), copyPath);
    QVERIFY(QFile::exists(copyPath)); // until it is saved

    QVERIFY2(document.save(document.filePath(), &error), qPrintable(error));
    QVERIFY(!QFile::exists(copyPath));
    QVERIFY(Autosave::pendingRecoveries().empty());

    Document reopened;
    QVERIFY(reopened.load(path, &error));
    QVERIFY(reopened.model().sameContent(*edited));
}

void TestAutosave::recoveredUntitledDocument()
{
    {
        Document document;
        Autosave autosave(document);
        QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "FALSE")));
        QVERIFY(autosave.writeNow());
    }
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));

    Document document;
    Autosave autosave(document);
    QVERIFY(Autosave::recover(pending.front(), document));
    QVERIFY(document.filePath().isEmpty());
    QVERIFY(document.isModified());
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("FALSE"));

    const QString path = m_files.filePath("untitled-recovered.ggs.json");
    QVERIFY(document.save(path, nullptr));
    QVERIFY(Autosave::pendingRecoveries().empty());
}

void TestAutosave::undoToSavedStateRemovesCopy()
{
    Document document;
    Autosave autosave(document);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(autosave.writeNow());
    QVERIFY(QFile::exists(autosave.recoveryPath()));
    document.undoStack()->undo();
    QVERIFY(!document.isModified());
    QVERIFY(!QFile::exists(autosave.recoveryPath()));
    QVERIFY(Autosave::pendingRecoveries().empty());
}

void TestAutosave::saveAsMovesTheCopy()
{
    Document document;
    Autosave autosave(document);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(autosave.writeNow());
    const QString untitledCopy = autosave.recoveryPath();
    QVERIFY(QFile::exists(untitledCopy));

    QVERIFY(document.save(m_files.filePath("saved-as.ggs.json"), nullptr));
    QVERIFY(!QFile::exists(untitledCopy));
    QVERIFY(autosave.recoveryPath() != untitledCopy);

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "FALSE")));
    QVERIFY(autosave.writeNow());
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().originalPath, m_files.filePath("saved-as.ggs.json"));
}

void TestAutosave::discardRemovesCopy()
{
    Document document;
    Autosave autosave(document);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(autosave.writeNow());
    autosave.discard(); // the user closed without saving, on purpose
    QVERIFY(Autosave::pendingRecoveries().empty());

    QVERIFY(autosave.writeNow()); // still modified: a new copy
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    Autosave::discard(pending.front()); // the user declined to recover it
    QVERIFY(Autosave::pendingRecoveries().empty());
    QVERIFY(QDir(Autosave::recoveryDirectory()).isEmpty());
}

void TestAutosave::unreadableCopyIsReported()
{
    QVERIFY(QDir().mkpath(Autosave::recoveryDirectory()));
    const QString copyPath = Autosave::recoveryDirectory() + "/broken.json";
    QFile copy(copyPath);
    QVERIFY(copy.open(QIODevice::WriteOnly));
    copy.write("not json");
    copy.close();

    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    Document document;
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QString error;
    QVERIFY(!Autosave::recover(pending.front(), document, &error));
    QVERIFY2(error.contains("broken.json"), qPrintable(error));
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("TRUE"));
    QVERIFY(document.undoStack()->canUndo());
}

QTEST_MAIN(TestAutosave)
#include "test_autosave.moc"
