#pragma once

#include <QCoreApplication>

class QWidget;

namespace editor {

class Document;

// At start: offers the models autosave kept when a session ended without
// saving them (editor/app/autosave.h), newest first; never those of an instance
// still running, nor those another starting instance offers at the same
// time. The user recovers one into the document, discards it, or keeps it
// for the next start.
class RecoveryPrompt {
    Q_DECLARE_TR_FUNCTIONS(RecoveryPrompt)

public:
    // True when a model was recovered into the document.
    static bool offer(QWidget* parent, Document& document);
};

} // namespace editor
