#include "editor/app/autosave.h"

#include "editor/document.h"

#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>
#include <QUuid>

#include <algorithm>

namespace editor {

namespace {

const QString kCopySuffix = QStringLiteral(".json");
const QString kSidecarSuffix = QStringLiteral(".info");
const QString kLockSuffix = QStringLiteral(".lock");

// A live owner's lock is safe from age: the system lock on the lock file
// (flock, or the open handle on Windows) keeps others from removing it, and
// a dead owner on this machine is seen at once (its PID is gone, or the
// machine rebooted). The age only settles what those cannot: an owner on
// another machine sharing the folder, or a PID taken by another GG Studio.
// Long, because it is all that protects a live owner where the folder's
// file system has no locks.
constexpr int kStaleLockMs = 60 * 60 * 1000;
// Random keys practically never clash; a few draws cover a clash anyway.
constexpr int kKeyDraws = 3;

// Every Autosave alive (GUI thread only, like the documents), so that
// recover() can have the document's own Autosave take the recovered edit over.
std::vector<Autosave*>& liveAutosaves()
{
    static std::vector<Autosave*> autosaves;
    return autosaves;
}

QString sidecarPath(const QString& copyPath)
{
    return copyPath.chopped(kCopySuffix.size()) + kSidecarSuffix;
}

QString lockPath(const QString& copyPath)
{
    return copyPath.chopped(kCopySuffix.size()) + kLockSuffix;
}

std::unique_ptr<QLockFile> makeLock(const QString& copyPath)
{
    auto lock = std::make_unique<QLockFile>(lockPath(copyPath));
    lock->setStaleLockTime(kStaleLockMs);
    return lock;
}

QString newInstanceKey()
{
    return QUuid::createUuid().toString(QUuid::Id128).left(12);
}

// Readable: which file the copy is of, and which session wrote it.
QString keyFor(const QString& filePath, const QString& instanceKey)
{
    if (filePath.isEmpty())
        return QStringLiteral("untitled-") + instanceKey;
    const QByteArray absolute = QFileInfo(filePath).absoluteFilePath().toUtf8();
    return QString::fromLatin1(QCryptographicHash::hash(absolute, QCryptographicHash::Sha1).toHex().left(16)) +
           QLatin1Char('-') + instanceKey;
}

const QString kOriginalPathKey = QStringLiteral("originalPath");
const QString kOriginalDigestKey = QStringLiteral("originalSha256");

// Hex SHA-256 of a file's contents; empty when it cannot be read.
QByteArray fileDigest(const QString& path)
{
    QFile file(path);
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!file.open(QIODevice::ReadOnly) || !hash.addData(&file))
        return {};
    return hash.result().toHex();
}

// The original as the sidecar records it: by a path that means the same
// file from any working directory, and by its contents, so that a recovery
// can tell whether the path still names the file the copy was edited from.
// Read at every write, as the copy itself is: a model file is small.
struct OriginalRecord {
    QString path;
    QByteArray digest;
};

OriginalRecord recordOriginal(const QString& filePath)
{
    if (filePath.isEmpty())
        return {};
    const QFileInfo info(filePath);
    const QString canonical = info.canonicalFilePath();
    if (canonical.isEmpty()) // gone meanwhile: named, but never to be saved onto unchecked
        return {info.absoluteFilePath(), {}};
    return {canonical, fileDigest(canonical)};
}

bool writeSidecar(const QString& path, const OriginalRecord& original, QString* errorMessage)
{
    QJsonObject info;
    info.insert(kOriginalPathKey, original.path);
    if (!original.digest.isEmpty())
        info.insert(kOriginalDigestKey, QString::fromLatin1(original.digest));
    info.insert(QStringLiteral("savedAt"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    // Through core's writer, like the copy: atomic, and never onto a FIFO or a device.
    const QByteArray json = QJsonDocument(info).toJson();
    const core::Status status = core::writeFileAtomically(QFile::encodeName(path).toStdString(),
                                                          std::string_view(json.constData(), json.size()));
    if (!status)
        *errorMessage = QString::fromStdString(status.message);
    return static_cast<bool>(status);
}

bool writeCopy(const core::Model& model, const QString& path, QString* errorMessage)
{
    const core::Status status =
        core::saveModelFile(model, QFile::encodeName(path).toStdString(), core::ModelFormat::Native);
    if (!status)
        *errorMessage = QStringLiteral("%1: %2").arg(path, QString::fromStdString(status.message));
    return static_cast<bool>(status);
}

// The copy first: a sidecar without a copy is a leftover to clean, a copy
// without a sidecar would no longer say which file it was.
void removeCopyFiles(const QString& copyPath)
{
    QFile::remove(copyPath);
    QFile::remove(sidecarPath(copyPath));
}

RecoveryFile readRecoveryFile(const QFileInfo& copy)
{
    RecoveryFile result;
    result.recoveryPath = copy.absoluteFilePath();
    result.savedAt = copy.lastModified();
    QFile sidecar(sidecarPath(result.recoveryPath));
    if (sidecar.size() < 64 * 1024 && sidecar.open(QIODevice::ReadOnly)) {
        const QJsonObject info = QJsonDocument::fromJson(sidecar.readAll()).object();
        result.originalPath = info.value(kOriginalPathKey).toString();
        result.originalDigest = info.value(kOriginalDigestKey).toString().toLatin1();
        const QDateTime savedAt =
            QDateTime::fromString(info.value(QStringLiteral("savedAt")).toString(), Qt::ISODateWithMs);
        if (savedAt.isValid())
            result.savedAt = savedAt;
    }
    return result;
}

// A session that crashed between taking its lock, writing its sidecar and
// writing its copy (or removing them) left a sidecar or a lock alone.
void removeLeftovers(const QDir& directory)
{
    const QFileInfoList files =
        directory.entryInfoList({QStringLiteral("*") + kSidecarSuffix, QStringLiteral("*") + kLockSuffix}, QDir::Files);
    for (const QFileInfo& file : files) {
        const QString copyPath = directory.filePath(file.completeBaseName() + kCopySuffix);
        if (QFile::exists(copyPath))
            continue;
        const std::unique_ptr<QLockFile> lock = makeLock(copyPath);
        if (lock->tryLock() && !QFile::exists(copyPath))
            QFile::remove(sidecarPath(copyPath)); // the lock goes with `lock`
    }
}

// The lock of a copy to recover or discard: the one pendingRecoveries() took,
// or a new one; null while a running instance holds the copy.
std::shared_ptr<QLockFile> claimCopy(const RecoveryFile& file)
{
    if (file.lock && file.lock->isLocked())
        return file.lock;
    std::shared_ptr<QLockFile> lock = makeLock(file.recoveryPath);
    if (!lock->tryLock())
        return nullptr;
    return lock;
}

} // namespace

Autosave::Autosave(Document& document, QObject* parent)
    : QObject(parent)
    , m_document(&document)
    , m_timer(new QTimer(this))
    , m_instanceKey(newInstanceKey())
{
    liveAutosaves().push_back(this);
    m_timer->setInterval(kDefaultIntervalMs);
    connect(m_timer, &QTimer::timeout, this, &Autosave::writeNow);
    connect(&document, &Document::modifiedChanged, this, &Autosave::onModifiedChanged);
    connect(&document, &Document::filePathChanged, this, &Autosave::onFilePathChanged);
    // Destroyed while modified (a crash-like end): the copy stays for recovery.
    connect(&document, &QObject::destroyed, m_timer, &QTimer::stop);
    if (document.isModified())
        onModifiedChanged(true);
}

Autosave::~Autosave()
{
    std::erase(liveAutosaves(), this);
}

int Autosave::interval() const
{
    return m_timer->interval();
}

void Autosave::setInterval(int milliseconds)
{
    m_timer->setInterval(milliseconds);
}

QString Autosave::recoveryDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/recovery");
}

QString Autosave::recoveryPath() const
{
    const QString filePath = m_document ? m_document->filePath() : QString();
    return recoveryDirectory() + QLatin1Char('/') + keyFor(filePath, m_instanceKey) + kCopySuffix;
}

bool Autosave::writeNow()
{
    if (!m_document || !m_document->isModified())
        return true;
    const quint64 revision = m_document->model().revision();
    if (m_written && m_ownCopy == recoveryPath() && revision == m_writtenRevision && QFile::exists(m_ownCopy))
        return true; // the copy is up to date
    if (!QDir().mkpath(recoveryDirectory())) {
        m_lastError = tr("Cannot create the folder %1 for recovery copies").arg(recoveryDirectory());
        emit writeFailed(m_lastError);
        return false;
    }
    if (!lockOwnCopy()) {
        m_lastError = tr("Cannot lock the recovery copy %1").arg(lockPath(recoveryPath()));
        emit writeFailed(m_lastError);
        return false;
    }
    QString error;
    if (!writeSidecar(sidecarPath(m_ownCopy), recordOriginal(m_document->filePath()), &error) ||
        !writeCopy(m_document->model(), m_ownCopy, &error)) {
        m_lastError = tr("Cannot write the recovery copy: %1").arg(error);
        emit writeFailed(m_lastError);
        return false;
    }
    m_written = true;
    m_writtenRevision = revision;
    m_lastError.clear();
    return true;
}

void Autosave::discard()
{
    removeOwnCopy();
}

void Autosave::onModifiedChanged(bool modified)
{
    if (modified) {
        m_written = false;
        m_timer->start();
    } else {
        m_timer->stop();
        removeOwnCopy();
    }
}

void Autosave::onFilePathChanged()
{
    // The next write starts the copy under the new file's key.
    if (!m_ownCopy.isEmpty() && m_ownCopy != recoveryPath())
        removeOwnCopy();
}

// Locks recoveryPath() for this Autosave's copy, drawing another key while
// that one is locked or already has files: those are another session's,
// never to be overwritten.
bool Autosave::lockOwnCopy()
{
    if (!m_ownCopy.isEmpty() && m_ownCopy == recoveryPath())
        return true;
    removeOwnCopy(); // the copy of the file the document had before
    for (int draw = 0; draw < kKeyDraws; ++draw) {
        const QString path = recoveryPath();
        std::unique_ptr<QLockFile> lock = makeLock(path);
        if (lock->tryLock() && !QFile::exists(path) && !QFile::exists(sidecarPath(path))) {
            m_lock = std::move(lock);
            m_ownCopy = path;
            return true;
        }
        m_instanceKey = newInstanceKey();
    }
    return false;
}

void Autosave::removeOwnCopy()
{
    if (m_ownCopy.isEmpty())
        return;
    removeCopyFiles(m_ownCopy);
    m_lock.reset(); // last: a copy is never left unlocked while this session runs
    m_ownCopy.clear();
    m_written = false;
}

std::vector<RecoveryFile> Autosave::pendingRecoveries()
{
    std::vector<RecoveryFile> result;
    const QDir directory(recoveryDirectory());
    removeLeftovers(directory);
    const QFileInfoList copies =
        directory.entryInfoList({QStringLiteral("*") + kCopySuffix}, QDir::Files | QDir::Readable, QDir::Name);
    for (const QFileInfo& copy : copies) {
        // Locked: a running session's copy, or one another instance offers.
        // Taken here when its lock is gone or stale (its owner crashed).
        std::unique_ptr<QLockFile> lock = makeLock(copy.absoluteFilePath());
        if (!lock->tryLock())
            continue;
        RecoveryFile file = readRecoveryFile(copy);
        file.lock = std::move(lock);
        result.push_back(std::move(file));
    }
    std::stable_sort(result.begin(), result.end(),
                     [](const RecoveryFile& a, const RecoveryFile& b) { return a.savedAt > b.savedAt; });
    return result;
}

QString Autosave::saveTarget(const RecoveryFile& file)
{
    // A relative path was relative to the crashed session's working
    // directory, which is not known: here it could name any file.
    if (file.originalPath.isEmpty() || !QDir::isAbsolutePath(file.originalPath) || file.originalDigest.isEmpty())
        return {};
    // Canonical when recorded: another canonical path now means a symbolic
    // link on the way changed, or the file is gone.
    if (QFileInfo(file.originalPath).canonicalFilePath() != file.originalPath)
        return {};
    if (fileDigest(file.originalPath) != file.originalDigest)
        return {}; // another file in its place, or changed since: not the one edited
    return file.originalPath;
}

bool Autosave::recover(const RecoveryFile& file, Document& document, QString* errorMessage)
{
    const std::shared_ptr<QLockFile> lock = claimCopy(file);
    if (!lock) {
        if (errorMessage)
            *errorMessage = tr("Another GG Studio is using the recovery copy %1.").arg(file.recoveryPath);
        return false;
    }
    core::LoadedModel loaded = core::loadSupportedModelFile(QFile::encodeName(file.recoveryPath).toStdString(),
                                                                 core::TemplateSupport::GemmaAndPackML);
    if (!loaded.ok()) {
        if (errorMessage)
            *errorMessage = QString::fromStdString(loaded.error.toString());
        return false;
    }
    document.replaceModel(*loaded.model, saveTarget(file), core::ModelFormat::Native);
    document.undoStack()->resetClean(); // modified until the user saves

    // The old copy goes only once the document's own copy holds the edit.
    bool taken = false;
    const std::vector<Autosave*> autosaves = liveAutosaves(); // writeNow() may create or end some
    for (Autosave* autosave : autosaves) {
        if (autosave->m_document == &document) {
            autosave->m_written = false;
            taken = autosave->writeNow() || taken;
        }
    }
    if (taken)
        removeCopyFiles(file.recoveryPath);
    lock->unlock();
    return true;
}

void Autosave::discard(const RecoveryFile& file)
{
    const std::shared_ptr<QLockFile> lock = claimCopy(file);
    if (!lock)
        return;
    removeCopyFiles(file.recoveryPath);
    lock->unlock();
}

} // namespace editor
