#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>
#include <vector>

class QLockFile;
class QTimer;

namespace editor {

class Document;

// A model kept by autosave after the editor ended without saving it.
struct RecoveryFile {
    QString recoveryPath; // the autosaved model (native JSON)
    // The file the user was editing, absolute and canonical; empty when
    // untitled. Records of older versions may hold a relative path, which
    // says nothing of the folder it was relative to: see saveTarget().
    QString originalPath;
    // SHA-256 (hex) of the original file's contents when the copy was
    // written; empty when it was not readable, and in older records.
    QByteArray originalDigest;
    QDateTime savedAt;    // when autosave wrote it
    // Held from pendingRecoveries() until recover() or discard() is done with
    // the copy, or the last RecoveryFile sharing it goes: while a prompt
    // offers the copy, another GG Studio starting up does not offer it too.
    std::shared_ptr<QLockFile> lock;
};

// Keeps a recovery copy of a modified document, so a crash loses at most
// one interval of work. While the document is modified it writes the model
// every interval (native JSON, atomically) to
// <AppLocalDataLocation>/recovery/<key>.json, where the key is a hash of the
// file path, or "untitled", followed by a random part drawn for this
// Autosave: two running instances, or one file open twice, never share a
// copy. A sidecar <key>.info names the original file (absolute and
// canonical) and the digest of its contents. For as long as the
// copy exists, this Autosave holds the lock file <key>.lock (QLockFile), so
// pendingRecoveries() of another instance skips the copy of a live session.
// The copy goes away, then its lock, when the document becomes unmodified
// (saved, or undone back to its saved state), when the document moves to
// another file, and on discard(). A crash, or the Autosave ending with its
// document still modified, leaves the copy (and after a crash a lock whose
// owner is gone) for pendingRecoveries() at the next start.
class Autosave : public QObject {
    Q_OBJECT

public:
    static constexpr int kDefaultIntervalMs = 30'000;

    // Usually a child of the document; it stops when the document is destroyed.
    explicit Autosave(Document& document, QObject* parent = nullptr);
    // Releases the lock but keeps a copy still there: ending with the
    // document modified is a crash as far as the next start is concerned.
    ~Autosave() override;

    int interval() const;
    void setInterval(int milliseconds);

    // Writes the recovery copy now if the document is modified and changed
    // since the last copy. False when writing failed (see lastError()).
    bool writeNow();
    QString lastError() const { return m_lastError; }

    // Removes this document's recovery copy: call it when the user closes the
    // document on purpose (saved, or chose to discard the changes).
    void discard();

    // Where this document's recovery copy is written (the key changes with
    // the document's file, and when another copy already holds it).
    QString recoveryPath() const;

    static QString recoveryDirectory();
    // Copies whose session is gone (crashed, or ended without saving), newest
    // first; never the copy of a running instance, nor one that another
    // instance is offering. Also removes the files left by a session that
    // crashed between writing its lock, sidecar and copy.
    static std::vector<RecoveryFile> pendingRecoveries();
    // The file a recovered copy may be saved onto: its original file while
    // that is still the one the copy was edited from (the record names it by
    // an absolute path, and a file is there with the contents it had then).
    // Empty when untitled, or when the original can no longer be identified
    // (moved, deleted, changed since, or a record of an older version with a
    // relative path): then Save asks where to save, as for a new model.
    static QString saveTarget(const RecoveryFile& file);
    // Loads a copy into the document as an unsaved edit of saveTarget()
    // (the user must save). The document's Autosave writes its own copy at
    // once; then the old copy and its lock go (the old copy stays when the
    // document has no Autosave or its copy cannot be written). False, with
    // the reason, when the copy cannot be read or another instance uses it.
    static bool recover(const RecoveryFile& file, Document& document, QString* errorMessage = nullptr);
    // Deletes a copy the user chose not to recover, with its sidecar and
    // lock; does nothing when another running instance holds the copy.
    static void discard(const RecoveryFile& file);

signals:
    // A recovery copy could not be written (disk full, no permission...).
    void writeFailed(const QString& message);

private:
    void onModifiedChanged(bool modified);
    void onFilePathChanged();
    bool lockOwnCopy();
    void removeOwnCopy();

    QPointer<Document> m_document; // null once the document is gone
    QTimer* m_timer;
    QString m_instanceKey;              // the random part of the key, drawn again on a clash
    QString m_ownCopy;                  // the copy this document is responsible for; empty when none
    std::unique_ptr<QLockFile> m_lock;  // m_ownCopy's lock, held while m_ownCopy is set
    quint64 m_writtenRevision = 0;      // model revision of the last copy
    bool m_written = false;
    QString m_lastError;
};

} // namespace editor
