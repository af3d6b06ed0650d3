#pragma once

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QString>

#include <vector>

class QTimer;

namespace editor {

class Document;

// A model kept by autosave after the editor ended without saving it.
struct RecoveryFile {
    QString recoveryPath; // the autosaved model (native JSON)
    QString originalPath; // the file the user was editing; empty when untitled
    QDateTime savedAt;    // when autosave wrote it
};

// Keeps a recovery copy of a modified document, so a crash loses at most
// one interval of work. While the document is modified it writes the model
// every interval (native JSON, atomically) to
// <AppLocalDataLocation>/recovery/<key>.json, where the key is a hash of the
// file path or "untitled", with a sidecar <key>.info naming the original
// file. The copy goes away when the document becomes unmodified (saved, or
// undone back to its saved state), when the document moves to another file,
// and on discard(). A crash leaves it for pendingRecoveries() at the next start.
class Autosave : public QObject {
    Q_OBJECT

public:
    static constexpr int kDefaultIntervalMs = 30'000;

    // Usually a child of the document; it stops when the document is destroyed.
    explicit Autosave(Document& document, QObject* parent = nullptr);

    int interval() const;
    void setInterval(int milliseconds);

    // Writes the recovery copy now if the document is modified and changed
    // since the last copy. False when writing failed (see lastError()).
    bool writeNow();
    QString lastError() const { return m_lastError; }

    // Removes this document's recovery copy: call it when the user closes the
    // document on purpose (saved, or chose to discard the changes).
    void discard();

    // Where this document's recovery copy is written.
    QString recoveryPath() const;

    static QString recoveryDirectory();
    // Copies left by an earlier session, newest first.
    static std::vector<RecoveryFile> pendingRecoveries();
    // Loads a copy into the document as an unsaved edit of its original file
    // (the user must save). The copy stays until that document is saved or
    // discarded. False, with the reason, when the copy cannot be read.
    static bool recover(const RecoveryFile& file, Document& document, QString* errorMessage = nullptr);
    // Deletes a copy the user chose not to recover.
    static void discard(const RecoveryFile& file);

signals:
    // A recovery copy could not be written (disk full, no permission...).
    void writeFailed(const QString& message);

private:
    void onModifiedChanged(bool modified);
    void onFilePathChanged();
    void removeOwnCopy();

    QPointer<Document> m_document; // null once the document is gone
    QTimer* m_timer;
    QString m_ownCopy;                  // the copy this document is responsible for; empty when none
    quint64 m_writtenRevision = 0;      // model revision of the last copy
    bool m_written = false;
    QString m_lastError;
};

} // namespace editor
