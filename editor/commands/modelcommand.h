#pragma once

#include "core/model/status.h"

#include <QUndoCommand>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace core {
class Model;
}

namespace editor {

class Document;

// Base of every model edit: redo() runs a model operation by element id,
// undo() its inverse. Subclasses only say what to apply and how to revert.
//
// A command whose operation fails never enters the undo stack: push it with
// Document::push(), which applies it first and, on failure, reports the
// reason (Document::editFailed) and deletes it. A command whose first run
// changes nothing is dropped the same way, so the history holds no empty
// steps. Pushed straight onto a QUndoStack, such a command becomes obsolete
// and the stack drops it.
class ModelCommand : public QUndoCommand {
public:
    void redo() final;
    void undo() final;

    // For Document::push: the first redo(); false when the command must not
    // enter the stack (hasFailed() tells a failure from a change of nothing).
    bool applyBeforePush();
    bool hasFailed() const { return m_failed; }

    // Words text() again in the current UI language: the history made before
    // a language switch reads in the new language (rewordUndoHistory).
    void reword();

protected:
    // The text in the current UI language, from the command's own data.
    using Wording = std::function<QString()>;

    // The text, worded again when the UI language changes: every command
    // has one, so the whole history follows the language.
    ModelCommand(Document& document, Wording wording);

    // Called for every redo; firstRun() is true the first time, when a
    // command captures the previous values it will restore.
    virtual core::Status apply() = 0;
    virtual core::Status revert() = 0;
    bool firstRun() const { return m_runs == 1; }

    core::Model& model();
    const core::Model& model() const;

private:
    class EditScope;
    void fail(const core::Status& status);

    Document& m_document;
    Wording m_wording;
    int m_runs = 0;
    bool m_appliedBeforePush = false;
    bool m_failed = false;
};

// Conversions between the core's UTF-8 std::string and QString.
inline QString toQString(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}
inline std::string toStdString(const QString& text)
{
    return text.toStdString();
}

} // namespace editor
