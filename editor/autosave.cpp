#include "editor/autosave.h"

#include "editor/document.h"

#include "core/modelfiles.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>

namespace editor {

namespace {

const QString kCopySuffix = QStringLiteral(".json");
const QString kSidecarSuffix = QStringLiteral(".info");

QString sidecarPath(const QString& copyPath)
{
    return copyPath.chopped(kCopySuffix.size()) + kSidecarSuffix;
}

// Stable across sessions, so the next start finds the copy of a given file.
QString keyFor(const QString& filePath)
{
    if (filePath.isEmpty())
        return QStringLiteral("untitled");
    const QByteArray absolute = QFileInfo(filePath).absoluteFilePath().toUtf8();
    return QString::fromLatin1(QCryptographicHash::hash(absolute, QCryptographicHash::Sha1).toHex().left(16));
}

bool writeSidecar(const QString& path, const QString& originalPath, QString* errorMessage)
{
    QJsonObject info;
    info.insert(QStringLiteral("originalPath"), originalPath);
    info.insert(QStringLiteral("savedAt"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(QJsonDocument(info).toJson()) < 0 || !file.commit()) {
        *errorMessage = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

RecoveryFile readRecoveryFile(const QFileInfo& copy)
{
    RecoveryFile result;
    result.recoveryPath = copy.absoluteFilePath();
    result.savedAt = copy.lastModified();
    QFile sidecar(sidecarPath(result.recoveryPath));
    if (sidecar.size() < 64 * 1024 && sidecar.open(QIODevice::ReadOnly)) {
        const QJsonObject info = QJsonDocument::fromJson(sidecar.readAll()).object();
        result.originalPath = info.value(QStringLiteral("originalPath")).toString();
        const QDateTime savedAt =
            QDateTime::fromString(info.value(QStringLiteral("savedAt")).toString(), Qt::ISODateWithMs);
        if (savedAt.isValid())
            result.savedAt = savedAt;
    }
    return result;
}

} // namespace

Autosave::Autosave(Document& document, QObject* parent)
    : QObject(parent)
    , m_document(&document)
    , m_timer(new QTimer(this))
{
    m_timer->setInterval(kDefaultIntervalMs);
    connect(m_timer, &QTimer::timeout, this, &Autosave::writeNow);
    connect(&document, &Document::modifiedChanged, this, &Autosave::onModifiedChanged);
    connect(&document, &Document::filePathChanged, this, &Autosave::onFilePathChanged);
    // Destroyed while modified (a crash-like end): the copy stays for recovery.
    connect(&document, &QObject::destroyed, m_timer, &QTimer::stop);
    if (document.isModified())
        onModifiedChanged(true);
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
    return recoveryDirectory() + QLatin1Char('/') + keyFor(filePath) + kCopySuffix;
}

bool Autosave::writeNow()
{
    if (!m_document || !m_document->isModified())
        return true;
    const QString path = recoveryPath();
    const quint64 revision = m_document->model().revision();
    if (m_written && m_ownCopy == path && revision == m_writtenRevision && QFile::exists(path))
        return true; // the copy is up to date
    m_ownCopy = path;
    if (!QDir().mkpath(recoveryDirectory())) {
        m_lastError = tr("Cannot create the folder %1 for recovery copies").arg(recoveryDirectory());
        emit writeFailed(m_lastError);
        return false;
    }
    const core::Status status =
        core::saveModelFile(m_document->model(), QFile::encodeName(path).toStdString(), core::ModelFormat::Native);
    QString sidecarError;
    if (!status || !writeSidecar(sidecarPath(path), m_document->filePath(), &sidecarError)) {
        m_lastError = status ? sidecarError : QStringLiteral("%1: %2").arg(path, QString::fromStdString(status.message));
        m_lastError = tr("Cannot write the recovery copy: %1").arg(m_lastError);
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
        // From now on the copy under this document's key is this document's
        // (after a recovery, that is the copy just recovered).
        m_ownCopy = recoveryPath();
        m_written = false;
        m_timer->start();
    } else {
        m_timer->stop();
        removeOwnCopy();
    }
}

void Autosave::onFilePathChanged()
{
    if (m_ownCopy.isEmpty() || m_ownCopy == recoveryPath())
        return;
    removeOwnCopy();
    if (m_document && m_document->isModified())
        m_ownCopy = recoveryPath();
}

void Autosave::removeOwnCopy()
{
    if (m_ownCopy.isEmpty())
        return;
    QFile::remove(m_ownCopy);
    QFile::remove(sidecarPath(m_ownCopy));
    m_ownCopy.clear();
    m_written = false;
}

std::vector<RecoveryFile> Autosave::pendingRecoveries()
{
    std::vector<RecoveryFile> result;
    const QDir directory(recoveryDirectory());
    const QFileInfoList copies =
        directory.entryInfoList({QStringLiteral("*") + kCopySuffix}, QDir::Files | QDir::Readable, QDir::Name);
    for (const QFileInfo& copy : copies)
        result.push_back(readRecoveryFile(copy));
    std::stable_sort(result.begin(), result.end(),
                     [](const RecoveryFile& a, const RecoveryFile& b) { return a.savedAt > b.savedAt; });
    return result;
}

bool Autosave::recover(const RecoveryFile& file, Document& document, QString* errorMessage)
{
    core::LoadedModel loaded = core::loadModelFile(QFile::encodeName(file.recoveryPath).toStdString());
    if (!loaded.ok()) {
        if (errorMessage)
            *errorMessage = QString::fromStdString(loaded.error.toString());
        return false;
    }
    document.replaceModel(*loaded.model, file.originalPath, core::ModelFormat::Native);
    document.undoStack()->resetClean(); // modified until the user saves
    return true;
}

void Autosave::discard(const RecoveryFile& file)
{
    QFile::remove(file.recoveryPath);
    QFile::remove(sidecarPath(file.recoveryPath));
}

} // namespace editor
