#include "editor/app/recoveryprompt.h"

#include "editor/app/autosave.h"
#include "editor/document.h"

#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

namespace editor {

namespace {

enum class Choice { Recover, Discard, NotNow };

QString modelName(const RecoveryFile& file)
{
    return file.originalPath.isEmpty() ? RecoveryPrompt::tr("an untitled model")
                                       : QDir::toNativeSeparators(file.originalPath);
}

// Deleting the copy loses the work for good, so it is asked twice and the
// safe answer is the default: Enter or Escape keep the copy.
bool confirmDiscard(QWidget* parent, const RecoveryFile& file)
{
    QMessageBox box(QMessageBox::Warning, RecoveryPrompt::tr("Discard Unsaved Changes"),
                    RecoveryPrompt::tr("Delete the autosaved copy of %1 for good?").arg(modelName(file)),
                    QMessageBox::NoButton, parent);
    box.setInformativeText(RecoveryPrompt::tr("The changes it holds cannot be recovered afterwards."));
    // No mnemonic: QMessageBox presses a button on its letter alone, without Alt.
    QPushButton* remove = box.addButton(RecoveryPrompt::tr("Delete Copy"), QMessageBox::DestructiveRole);
    QPushButton* keep = box.addButton(RecoveryPrompt::tr("&Keep Copy"), QMessageBox::RejectRole);
    box.setDefaultButton(keep);
    box.setEscapeButton(keep);
    box.exec();
    return box.clickedButton() == remove;
}

Choice ask(QWidget* parent, const RecoveryFile& file)
{
    for (;;) {
        QMessageBox box(QMessageBox::Question, RecoveryPrompt::tr("Recover Unsaved Changes"),
                        RecoveryPrompt::tr("GG Studio ended without saving %1.").arg(modelName(file)),
                        QMessageBox::NoButton, parent);
        QString details = RecoveryPrompt::tr("Autosave kept a copy on %1. Recover it? You can then save it or "
                                             "discard it.")
                              .arg(QLocale().toString(file.savedAt, QLocale::LongFormat));
        if (!file.originalPath.isEmpty() && Autosave::saveTarget(file).isEmpty())
            details += QStringLiteral("\n\n") +
                       RecoveryPrompt::tr("The original file can no longer be identified (moved, deleted or changed "
                                          "since, or named by an older version): saving the recovered model will ask "
                                          "for a file.");
        box.setInformativeText(details);
        QPushButton* recover = box.addButton(RecoveryPrompt::tr("&Recover"), QMessageBox::AcceptRole);
        // No mnemonic: QMessageBox presses a button on its letter alone, so
        // a user typing before the prompt shows up would choose it.
        QPushButton* discard = box.addButton(RecoveryPrompt::tr("Discard…"), QMessageBox::DestructiveRole);
        QPushButton* notNow = box.addButton(RecoveryPrompt::tr("&Not Now"), QMessageBox::RejectRole);
        box.setDefaultButton(recover);
        box.setEscapeButton(notNow);
        box.exec();

        if (box.clickedButton() == recover)
            return Choice::Recover;
        if (box.clickedButton() != discard)
            return Choice::NotNow;
        if (confirmDiscard(parent, file))
            return Choice::Discard;
        // Kept: the same question again.
    }
}

} // namespace

bool RecoveryPrompt::offer(QWidget* parent, Document& document)
{
    for (const RecoveryFile& file : Autosave::pendingRecoveries()) {
        const Choice choice = ask(parent, file);
        if (choice == Choice::Discard) {
            Autosave::discard(file);
            continue;
        }
        if (choice == Choice::NotNow)
            continue;
        QString error;
        if (Autosave::recover(file, document, &error))
            return true; // one document per window: the other copies wait for the next start
        QMessageBox::warning(parent, tr("Recover Unsaved Changes"),
                             tr("The autosaved copy could not be read.") + QStringLiteral("\n\n") + error);
    }
    return false;
}

} // namespace editor
