#include "editor/recoveryprompt.h"

#include "editor/autosave.h"
#include "editor/document.h"

#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

namespace editor {

bool RecoveryPrompt::offer(QWidget* parent, Document& document)
{
    for (const RecoveryFile& file : Autosave::pendingRecoveries()) {
        const QString name = file.originalPath.isEmpty() ? tr("an untitled model")
                                                         : QDir::toNativeSeparators(file.originalPath);
        QMessageBox box(QMessageBox::Question, tr("Recover Unsaved Changes"),
                        tr("GG Studio ended without saving %1.").arg(name), QMessageBox::NoButton, parent);
        box.setInformativeText(tr("Autosave kept a copy on %1. Recover it? You can then save it or discard it.")
                                   .arg(QLocale().toString(file.savedAt, QLocale::LongFormat)));
        QPushButton* recover = box.addButton(tr("&Recover"), QMessageBox::AcceptRole);
        QPushButton* discard = box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
        box.addButton(tr("&Not Now"), QMessageBox::RejectRole);
        box.setDefaultButton(recover);
        box.exec();

        if (box.clickedButton() == discard) {
            Autosave::discard(file);
            continue;
        }
        if (box.clickedButton() != recover)
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
