// Autosave and recovery, in QStandardPaths' test locations.

#include "editor/app/autosave.h"
#include "editor/app/recoveryprompt.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/document.h"

#include "core/formats/modelfiles.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QStandardPaths>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <functional>
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

QString lockPathOf(const QString& copyPath)
{
    return copyPath.left(copyPath.lastIndexOf('.')) + ".lock";
}

QString sidecarPathOf(const QString& copyPath)
{
    return copyPath.left(copyPath.lastIndexOf('.')) + ".info";
}

// The PID of a process that has ended, as the owner of a crashed session's lock.
qint64 deadProcessId()
{
    QProcess process;
    process.start(QCoreApplication::applicationFilePath(), {"-functions"});
    if (!process.waitForStarted())
        return 0;
    const qint64 pid = process.processId();
    process.waitForFinished();
    return pid;
}

// A lock file as QLockFile writes it, for the process `pid` named `appName`.
bool writeLockFile(const QString& path, qint64 pid, const QString& appName)
{
    QFile lock(path);
    if (pid <= 0 || !lock.open(QIODevice::WriteOnly))
        return false;
    const QByteArray contents = QByteArray::number(pid) + '\n' + appName.toUtf8() + '\n' +
                                QSysInfo::machineHostName().toUtf8() + '\n' + QSysInfo::machineUniqueId() + '\n' +
                                QSysInfo::bootUniqueId() + '\n';
    return lock.write(contents) == contents.size();
}

// An edit of an untitled document, left as a session that crashed leaves it:
// the copy and its sidecar, and a lock whose owner is gone. Returns the copy.
QString leaveCrashedCopy(const char* condition)
{
    QString copyPath;
    {
        Document document;
        Autosave autosave(document);
        if (!document.push(new SetConditionCommand(document, "A1->F1", condition)) || !autosave.writeNow())
            return QString();
        copyPath = autosave.recoveryPath();
    } // the Autosave ends without removing its copy, releasing its lock
    if (!QFile::exists(copyPath) || QFile::exists(lockPathOf(copyPath)) ||
        !writeLockFile(lockPathOf(copyPath), deadProcessId(), "ggstudio"))
        return QString();
    return copyPath;
}

std::string conditionIn(const QString& copyPath)
{
    const core::LoadedModel loaded = core::loadModelFile(QFile::encodeName(copyPath).toStdString());
    return loaded.ok() ? loaded.model->transition("A1->F1")->condition : std::string("unreadable");
}

QStringList recoveryFolderFiles()
{
    return QDir(Autosave::recoveryDirectory()).entryList(QDir::Files, QDir::Name);
}

QByteArray fileContents(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Saves the template with `condition` on A1->F1 at `path` (relative to the
// working directory, as the user may name it).
bool saveModelWith(const QString& path, const char* condition)
{
    Document document;
    return document.push(new SetConditionCommand(document, "A1->F1", condition)) && document.save(path, nullptr);
}

// The session that edits `path` and crashes: its copy stays, with the edit
// `condition` on A1->F1.
bool crashWhileEditing(const QString& path, const char* condition)
{
    Document document;
    if (!document.load(path, nullptr))
        return false;
    Autosave autosave(document);
    return document.push(new SetConditionCommand(document, "A1->F1", condition)) && autosave.writeNow();
}

// Rewrites a copy's sidecar as an older version wrote it: the path as the
// document had it, no digest.
bool writeOldSidecar(const QString& copyPath, const QString& originalPath)
{
    QJsonObject info;
    info.insert("originalPath", originalPath);
    info.insert("savedAt", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    QFile sidecar(sidecarPathOf(copyPath));
    return sidecar.open(QIODevice::WriteOnly | QIODevice::Truncate) && sidecar.write(QJsonDocument(info).toJson()) > 0;
}

QAbstractButton* buttonOf(QMessageBox* box, QMessageBox::ButtonRole role)
{
    for (QAbstractButton* button : box->buttons()) {
        if (box->buttonRole(button) == role)
            return button;
    }
    return nullptr;
}

// Answers the modal message boxes of a prompt as they come up: every tick,
// the next step acts on the box on top. The ticks are longer than the
// delay of QAbstractButton::animateClick(), which a mnemonic key starts, so
// a step sees the effect of the previous one. Once the steps are done, boxes
// still open are answered with Escape, so that a failing test ends.
class MessageBoxDriver : public QObject {
public:
    using Step = std::function<void(QMessageBox*)>;

    explicit MessageBoxDriver(std::vector<Step> steps)
        : m_steps(std::move(steps))
    {
        connect(&m_timer, &QTimer::timeout, this, &MessageBoxDriver::tick);
        m_timer.start(200);
    }
    std::size_t stepsDone() const { return m_done; }
    QStringList texts() const { return m_texts; } // of every box a step acted on

private:
    void tick()
    {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box)
            return;
        if (m_done < m_steps.size()) {
            m_texts << box->text() + '\n' + box->informativeText();
            m_steps[m_done++](box);
        } else {
            QTest::keyClick(box, Qt::Key_Escape);
        }
    }

    std::vector<Step> m_steps;
    std::size_t m_done = 0;
    QStringList m_texts;
    QTimer m_timer;
};

void pressKey(QMessageBox* box, Qt::Key key)
{
    QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : box, key);
}

} // namespace

class TestAutosave : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanupTestCase();

    void writesOnlyWhenModified();
    void twoInstancesKeepTwoCopies();
    void sameFileOpenTwiceKeepsTwoCopies();
    void crashedSessionIsOffered();
    void lockOfARunningProcessIsRespected();
    void offeredCopyIsNotOfferedTwice();
    void neverOverwritesAnotherSessionsCopy();
    void recoverRestoresUnsavedEdit();
    void recoveredUntitledDocument();
    void recoveryWithoutAutosaveKeepsTheCopy();
    void undoToSavedStateRemovesCopy();
    void saveAsMovesTheCopy();
    void discardRemovesCopy();
    void leftoversAreRemoved();
    void unreadableCopyIsReported();
    void relativePathIsRecoveredOntoItsOwnFile();
    void changedOriginalIsNotSavedOnto();
    void movedOriginalIsNotSavedOnto();
    void oldRecordHasAnUnknownOriginal();
    void promptRecoversOnEnter();
    void promptIgnoresAStrayD();
    void promptDiscardsOnlyWhenConfirmed();
    void promptSaysWhenTheOriginalIsUnknown();

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
    QVERIFY2(QRegularExpression("/recovery/untitled-[0-9a-f]{12}\\.json$").match(autosave.recoveryPath()).hasMatch(),
             qPrintable(autosave.recoveryPath()));

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(autosave.recoveryPath()), 5000);
    QVERIFY(QFile::exists(lockPathOf(autosave.recoveryPath())));
    QVERIFY(Autosave::pendingRecoveries().empty()); // this session is alive
}

void TestAutosave::twoInstancesKeepTwoCopies()
{
    Document first;
    Document second;
    auto firstAutosave = std::make_unique<Autosave>(first);
    Autosave secondAutosave(second);
    QVERIFY(first.push(new SetConditionCommand(first, "A1->F1", "TRUE")));
    QVERIFY(second.push(new SetConditionCommand(second, "A1->F1", "FALSE")));
    QVERIFY(firstAutosave->writeNow());
    QVERIFY(secondAutosave.writeNow());
    const QString firstCopy = firstAutosave->recoveryPath();
    QVERIFY(firstCopy != secondAutosave.recoveryPath());
    QCOMPARE(conditionIn(firstCopy), std::string("TRUE"));
    QCOMPARE(conditionIn(secondAutosave.recoveryPath()), std::string("FALSE"));
    QVERIFY(Autosave::pendingRecoveries().empty()); // both sessions are alive

    firstAutosave.reset(); // the first instance ends without saving
    QVERIFY(QFile::exists(firstCopy));
    QVERIFY(!QFile::exists(lockPathOf(firstCopy)));
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().recoveryPath, firstCopy);
    QVERIFY(pending.front().originalPath.isEmpty());
    QVERIFY(pending.front().savedAt.isValid());
}

void TestAutosave::sameFileOpenTwiceKeepsTwoCopies()
{
    const QString path = m_files.filePath("twice.ggs.json");
    QVERIFY(Document().save(path, nullptr));
    Document first;
    Document second;
    QVERIFY(first.load(path, nullptr));
    QVERIFY(second.load(path, nullptr));
    std::vector<QString> copies;
    {
        Autosave firstAutosave(first);
        Autosave secondAutosave(second);
        QVERIFY(first.push(new SetConditionCommand(first, "A1->F1", "TRUE")));
        QVERIFY(second.push(new SetConditionCommand(second, "A1->F1", "FALSE")));
        QVERIFY(firstAutosave.writeNow());
        QVERIFY(secondAutosave.writeNow());
        copies = {firstAutosave.recoveryPath(), secondAutosave.recoveryPath()};
        QVERIFY(copies[0] != copies[1]);
    }
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(2));
    for (const RecoveryFile& file : pending) {
        QCOMPARE(file.originalPath, path);
        QVERIFY(std::find(copies.begin(), copies.end(), file.recoveryPath) != copies.end());
    }
    QCOMPARE(conditionIn(copies[0]), std::string("TRUE"));
    QCOMPARE(conditionIn(copies[1]), std::string("FALSE"));
}

void TestAutosave::crashedSessionIsOffered()
{
    const QString oldCopy = leaveCrashedCopy("TRUE");
    QVERIFY(!oldCopy.isEmpty());
    QVERIFY(QFile::exists(lockPathOf(oldCopy)));

    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().recoveryPath, oldCopy);

    Document document;
    Autosave autosave(document); // the next session's
    QString error;
    QVERIFY2(Autosave::recover(pending.front(), document, &error), qPrintable(error));
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("TRUE"));
    QVERIFY(document.isModified());
    // The old copy, its sidecar and its lock are gone; the document's own copy holds the edit.
    QVERIFY(!QFile::exists(oldCopy));
    QVERIFY(!QFile::exists(sidecarPathOf(oldCopy)));
    QVERIFY(!QFile::exists(lockPathOf(oldCopy)));
    QVERIFY(autosave.recoveryPath() != oldCopy);
    QCOMPARE(conditionIn(autosave.recoveryPath()), std::string("TRUE"));
    QVERIFY(QFile::exists(lockPathOf(autosave.recoveryPath())));
    QVERIFY(Autosave::pendingRecoveries().empty());

    // The recovered document goes on as any other.
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "FALSE")));
    QVERIFY(autosave.writeNow());
    QCOMPARE(conditionIn(autosave.recoveryPath()), std::string("FALSE"));
    autosave.discard();
    QVERIFY(recoveryFolderFiles().isEmpty());
}

void TestAutosave::lockOfARunningProcessIsRespected()
{
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    // Another instance running now (this process stands for it) holds the copy.
    QVERIFY(QFile::remove(lockPathOf(copyPath)));
    QVERIFY(writeLockFile(lockPathOf(copyPath), QCoreApplication::applicationPid(),
                          QFileInfo(QCoreApplication::applicationFilePath()).fileName()));
    QVERIFY(Autosave::pendingRecoveries().empty());

    RecoveryFile file;
    file.recoveryPath = copyPath;
    Autosave::discard(file);
    QVERIFY(QFile::exists(copyPath));
    Document document;
    QString error;
    QVERIFY(!Autosave::recover(file, document, &error));
    QVERIFY2(error.contains(QFileInfo(copyPath).fileName()), qPrintable(error));
    QVERIFY(!document.isModified());

    // Its process gone, the copy is offered.
    QVERIFY(QFile::remove(lockPathOf(copyPath)));
    QVERIFY(writeLockFile(lockPathOf(copyPath), deadProcessId(), "ggstudio"));
    QCOMPARE(Autosave::pendingRecoveries().size(), std::size_t(1));
}

void TestAutosave::offeredCopyIsNotOfferedTwice()
{
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    std::vector<RecoveryFile> offered = Autosave::pendingRecoveries();
    QCOMPARE(offered.size(), std::size_t(1));

    // A second instance starting while the first one's prompt is open.
    QVERIFY(Autosave::pendingRecoveries().empty());
    RecoveryFile sameCopy;
    sameCopy.recoveryPath = copyPath;
    Document document;
    QVERIFY(!Autosave::recover(sameCopy, document, nullptr));

    offered.clear(); // the first prompt closed with Not Now
    QCOMPARE(Autosave::pendingRecoveries().size(), std::size_t(1));
    QVERIFY(QFile::exists(copyPath));
}

void TestAutosave::neverOverwritesAnotherSessionsCopy()
{
    Document document;
    Autosave autosave(document);
    const QString taken = autosave.recoveryPath();
    QVERIFY(QDir().mkpath(Autosave::recoveryDirectory()));
    QFile foreign(taken);
    QVERIFY(foreign.open(QIODevice::WriteOnly));
    foreign.write("another session's copy");
    foreign.close();

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(autosave.writeNow());
    QVERIFY(autosave.recoveryPath() != taken);
    QCOMPARE(conditionIn(autosave.recoveryPath()), std::string("TRUE"));
    QVERIFY(foreign.open(QIODevice::ReadOnly));
    QCOMPARE(foreign.readAll(), QByteArray("another session's copy"));
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
    // The document's own copy took over: a new key, the old copy gone.
    QVERIFY(autosave.recoveryPath() != copyPath);
    QVERIFY(QFile::exists(autosave.recoveryPath()));
    QVERIFY(!QFile::exists(copyPath));
    QVERIFY(!QFile::exists(lockPathOf(copyPath)));

    QVERIFY2(document.save(document.filePath(), &error), qPrintable(error));
    QVERIFY(!QFile::exists(autosave.recoveryPath()));
    QVERIFY(Autosave::pendingRecoveries().empty());
    QVERIFY(recoveryFolderFiles().isEmpty());

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

    QVERIFY(!QFile::exists(pending.front().recoveryPath));

    const QString path = m_files.filePath("untitled-recovered.ggs.json");
    QVERIFY(document.save(path, nullptr));
    QVERIFY(Autosave::pendingRecoveries().empty());
    QVERIFY(recoveryFolderFiles().isEmpty());
}

void TestAutosave::recoveryWithoutAutosaveKeepsTheCopy()
{
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    {
        const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
        QCOMPARE(pending.size(), std::size_t(1));
        Document document; // nothing would keep the edit should this session crash
        QVERIFY(Autosave::recover(pending.front(), document));
        QCOMPARE(document.model().transition("A1->F1")->condition, std::string("TRUE"));
    }
    QVERIFY(QFile::exists(copyPath));
    QVERIFY(!QFile::exists(lockPathOf(copyPath)));
    QCOMPARE(Autosave::pendingRecoveries().size(), std::size_t(1));
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
    QVERIFY(recoveryFolderFiles().isEmpty()); // the sidecar and the lock too
}

void TestAutosave::saveAsMovesTheCopy()
{
    Document document;
    auto autosave = std::make_unique<Autosave>(document);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(autosave->writeNow());
    const QString untitledCopy = autosave->recoveryPath();
    QVERIFY(QFile::exists(untitledCopy));

    QVERIFY(document.save(m_files.filePath("saved-as.ggs.json"), nullptr));
    QVERIFY(!QFile::exists(untitledCopy));
    QVERIFY(!QFile::exists(lockPathOf(untitledCopy)));
    QVERIFY(autosave->recoveryPath() != untitledCopy);

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "FALSE")));
    QVERIFY(autosave->writeNow());
    autosave.reset(); // ends without saving
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().originalPath, m_files.filePath("saved-as.ggs.json"));
}

void TestAutosave::discardRemovesCopy()
{
    Document document;
    auto autosave = std::make_unique<Autosave>(document);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(autosave->writeNow());
    autosave->discard(); // the user closed without saving, on purpose
    QVERIFY(recoveryFolderFiles().isEmpty());

    QVERIFY(autosave->writeNow()); // still modified: a new copy
    autosave.reset();
    std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    Autosave::discard(pending.front()); // the user declined to recover it
    pending.clear();
    QVERIFY(Autosave::pendingRecoveries().empty());
    QVERIFY2(recoveryFolderFiles().isEmpty(), qPrintable(recoveryFolderFiles().join(' ')));

    // A crashed session's copy, discarded as named (no prompt took its lock).
    RecoveryFile crashed;
    crashed.recoveryPath = leaveCrashedCopy("FALSE");
    QVERIFY(!crashed.recoveryPath.isEmpty());
    QVERIFY(QFile::exists(lockPathOf(crashed.recoveryPath)));
    Autosave::discard(crashed);
    QVERIFY2(recoveryFolderFiles().isEmpty(), qPrintable(recoveryFolderFiles().join(' ')));
}

void TestAutosave::leftoversAreRemoved()
{
    // A session crashed after taking its lock and writing its sidecar.
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    QVERIFY(QFile::remove(copyPath));
    // And a live session that has just taken its lock keeps it.
    const QString liveCopy = Autosave::recoveryDirectory() + "/untitled-live.json";
    QLockFile liveLock(lockPathOf(liveCopy));
    QVERIFY(liveLock.tryLock());

    QVERIFY(Autosave::pendingRecoveries().empty());
    QCOMPARE(recoveryFolderFiles(), QStringList{"untitled-live.lock"});
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

void TestAutosave::relativePathIsRecoveredOntoItsOwnFile()
{
    // Two working directories, each with a gui/cs.json of its own.
    QTemporaryDir firstFolder;
    QTemporaryDir otherFolder;
    QVERIFY(QDir(firstFolder.path()).mkpath("gui"));
    QVERIFY(QDir(otherFolder.path()).mkpath("gui"));
    const QString previousFolder = QDir::currentPath();
    const auto restoreFolder = qScopeGuard([&] { QDir::setCurrent(previousFolder); });
    QVERIFY(saveModelWith(otherFolder.filePath("gui/cs.json"), "FALSE"));
    const QByteArray unrelated = fileContents(otherFolder.filePath("gui/cs.json"));

    QVERIFY(QDir::setCurrent(firstFolder.path()));
    QVERIFY(saveModelWith("gui/cs.json", "FALSE"));
    QVERIFY(crashWhileEditing("gui/cs.json", "TRUE")); // opened by a relative path

    QVERIFY(QDir::setCurrent(otherFolder.path())); // the next session starts elsewhere
    const QString original = QFileInfo(firstFolder.filePath("gui/cs.json")).canonicalFilePath();
    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().originalPath, original);
    QCOMPARE(Autosave::saveTarget(pending.front()), original);

    Document document;
    Autosave autosave(document);
    QVERIFY(Autosave::recover(pending.front(), document));
    QCOMPARE(document.filePath(), original);
    QVERIFY(document.save(document.filePath(), nullptr)); // what Save does
    QCOMPARE(fileContents(otherFolder.filePath("gui/cs.json")), unrelated);
    Document saved;
    QVERIFY(saved.load(original, nullptr));
    QCOMPARE(saved.model().transition("A1->F1")->condition, std::string("TRUE"));
}

void TestAutosave::changedOriginalIsNotSavedOnto()
{
    const QString path = m_files.filePath("changed.json");
    QVERIFY(saveModelWith(path, "FALSE"));
    QVERIFY(crashWhileEditing(path, "TRUE"));
    QVERIFY(saveModelWith(path, "NOT FALSE")); // another file there now, or edited elsewhere
    const QByteArray now = fileContents(path);

    const std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().originalPath, QFileInfo(path).canonicalFilePath()); // still named, for the prompt
    QVERIFY(Autosave::saveTarget(pending.front()).isEmpty());
    Document document;
    QVERIFY(Autosave::recover(pending.front(), document));
    QVERIFY(document.filePath().isEmpty()); // Save asks for a file
    QVERIFY(document.isModified());
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("TRUE"));
    QCOMPARE(fileContents(path), now);
}

void TestAutosave::movedOriginalIsNotSavedOnto()
{
    const QString path = m_files.filePath("moved.json");
    QVERIFY(saveModelWith(path, "FALSE"));
    QVERIFY(crashWhileEditing(path, "TRUE"));
    QVERIFY(QFile::rename(path, m_files.filePath("moved-away.json")));

    std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QVERIFY(Autosave::saveTarget(pending.front()).isEmpty());
    Document document;
    QVERIFY(Autosave::recover(pending.front(), document));
    QVERIFY(document.filePath().isEmpty());
    QVERIFY(!QFile::exists(path));
}

void TestAutosave::oldRecordHasAnUnknownOriginal()
{
    QTemporaryDir folder;
    QVERIFY(QDir(folder.path()).mkpath("gui"));
    const QString previousFolder = QDir::currentPath();
    const auto restoreFolder = qScopeGuard([&] { QDir::setCurrent(previousFolder); });
    QVERIFY(QDir::setCurrent(folder.path()));
    QVERIFY(saveModelWith("gui/cs.json", "FALSE"));
    const QByteArray before = fileContents("gui/cs.json");
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    QVERIFY(writeOldSidecar(copyPath, "gui/cs.json"));

    std::vector<RecoveryFile> pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QCOMPARE(pending.front().originalPath, QString("gui/cs.json")); // readable
    QVERIFY(pending.front().originalDigest.isEmpty());
    QVERIFY(Autosave::saveTarget(pending.front()).isEmpty()); // relative to who knows where
    Document document;
    Autosave autosave(document); // takes the copy over
    QVERIFY(Autosave::recover(pending.front(), document));
    QVERIFY(document.filePath().isEmpty());
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("TRUE"));
    QCOMPARE(fileContents("gui/cs.json"), before);

    // Absolute, but with nothing to tell it is still the same file.
    const QString copyWithAbsolutePath = leaveCrashedCopy("TRUE");
    QVERIFY(writeOldSidecar(copyWithAbsolutePath, QFileInfo("gui/cs.json").canonicalFilePath()));
    pending = Autosave::pendingRecoveries();
    QCOMPARE(pending.size(), std::size_t(1));
    QVERIFY(Autosave::saveTarget(pending.front()).isEmpty());
}

void TestAutosave::promptRecoversOnEnter()
{
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    Document document;
    MessageBoxDriver driver({[](QMessageBox* box) {
        QVERIFY(box->defaultButton());
        QCOMPARE(box->buttonRole(box->defaultButton()), QMessageBox::AcceptRole);
        pressKey(box, Qt::Key_Return);
    }});
    QVERIFY(RecoveryPrompt::offer(nullptr, document));
    QCOMPARE(driver.stepsDone(), std::size_t(1));
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("TRUE"));
    QVERIFY(document.isModified());
}

void TestAutosave::promptIgnoresAStrayD()
{
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    Document document;
    bool stillAsked = false;
    // Typing on, as one who did not see the prompt come up.
    MessageBoxDriver driver({[](QMessageBox* box) { pressKey(box, Qt::Key_D); },
                             [](QMessageBox* box) { pressKey(box, Qt::Key_D); },
                             [&](QMessageBox* box) {
                                 stillAsked = box->text().contains("ended without saving");
                                 pressKey(box, Qt::Key_Escape); // Not Now
                             }});
    QVERIFY(!RecoveryPrompt::offer(nullptr, document));
    QCOMPARE(driver.stepsDone(), std::size_t(3));
    QVERIFY(stillAsked);
    QVERIFY(QFile::exists(copyPath));
    QCOMPARE(Autosave::pendingRecoveries().size(), std::size_t(1));
}

void TestAutosave::promptDiscardsOnlyWhenConfirmed()
{
    const QString copyPath = leaveCrashedCopy("TRUE");
    QVERIFY(!copyPath.isEmpty());
    Document document;
    const auto clickDiscard = [](QMessageBox* box) {
        QAbstractButton* discard = buttonOf(box, QMessageBox::DestructiveRole);
        QVERIFY(discard);
        QVERIFY(discard != box->defaultButton());
        discard->click();
    };
    {
        MessageBoxDriver keep({clickDiscard,
                               [](QMessageBox* confirmation) {
                                   QVERIFY(confirmation->defaultButton());
                                   QVERIFY(confirmation->buttonRole(confirmation->defaultButton()) !=
                                           QMessageBox::DestructiveRole);
                                   pressKey(confirmation, Qt::Key_Return); // a stray Enter keeps the copy
                               },
                               [](QMessageBox* prompt) { pressKey(prompt, Qt::Key_Escape); }});
        QVERIFY(!RecoveryPrompt::offer(nullptr, document));
        QCOMPARE(keep.stepsDone(), std::size_t(3));
        QVERIFY2(keep.texts().at(1).contains("for good"), qPrintable(keep.texts().join('|')));
        // Kept: the prompt asks again.
        QVERIFY2(keep.texts().at(2).contains("ended without saving"), qPrintable(keep.texts().join('|')));
        QVERIFY(QFile::exists(copyPath));
    } // one driver at a time: the one done answers every box with Escape

    MessageBoxDriver discard({clickDiscard, [](QMessageBox* confirmation) {
                                  buttonOf(confirmation, QMessageBox::DestructiveRole)->click();
                              }});
    QVERIFY(!RecoveryPrompt::offer(nullptr, document));
    QCOMPARE(discard.stepsDone(), std::size_t(2));
    QVERIFY(!QFile::exists(copyPath));
    QVERIFY(Autosave::pendingRecoveries().empty());
}

void TestAutosave::promptSaysWhenTheOriginalIsUnknown()
{
    const QString path = m_files.filePath("prompt-moved.json");
    QVERIFY(saveModelWith(path, "FALSE"));
    QVERIFY(crashWhileEditing(path, "TRUE"));
    Document document;
    {
        MessageBoxDriver known({[](QMessageBox* box) { pressKey(box, Qt::Key_Escape); }});
        QVERIFY(!RecoveryPrompt::offer(nullptr, document));
        QVERIFY(known.texts().at(0).contains(QDir::toNativeSeparators(QFileInfo(path).canonicalFilePath())));
        QVERIFY(!known.texts().at(0).contains("can no longer be identified"));
    }

    QVERIFY(QFile::remove(path));
    MessageBoxDriver lost({[](QMessageBox* box) { pressKey(box, Qt::Key_Return); }});
    QVERIFY(RecoveryPrompt::offer(nullptr, document));
    QVERIFY2(lost.texts().at(0).contains("can no longer be identified"), qPrintable(lost.texts().join('|')));
    QVERIFY(document.filePath().isEmpty());
}

QTEST_MAIN(TestAutosave)
#include "test_autosave.moc"
