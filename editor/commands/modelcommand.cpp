#include "editor/commands/modelcommand.h"

#include "editor/document.h"

#include <QCoreApplication>

#include <utility>

namespace editor {

// Holds the Document's signals back until the operation is complete.
class ModelCommand::EditScope {
public:
    explicit EditScope(Document& document)
        : m_document(document)
    {
        m_document.beginEdit();
    }
    ~EditScope() { m_document.endEdit(); }
    EditScope(const EditScope&) = delete;
    EditScope& operator=(const EditScope&) = delete;

private:
    Document& m_document;
};

ModelCommand::ModelCommand(Document& document, Wording wording)
    : QUndoCommand(wording())
    , m_document(document)
    , m_wording(std::move(wording))
{
}

void ModelCommand::reword()
{
    setText(m_wording());
}

core::Model& ModelCommand::model()
{
    return m_document.modelForCommands();
}

const core::Model& ModelCommand::model() const
{
    return m_document.model();
}

bool ModelCommand::applyBeforePush()
{
    redo();
    if (isObsolete())
        return false;
    m_appliedBeforePush = true; // the stack's own first redo() must not apply it twice
    return true;
}

void ModelCommand::redo()
{
    if (m_appliedBeforePush) {
        m_appliedBeforePush = false;
        return;
    }
    ++m_runs;
    const std::uint64_t before = model().revision();
    core::Status status;
    {
        EditScope scope(m_document);
        status = apply();
    }
    if (!status)
        fail(status);
    else if (m_runs == 1 && model().revision() == before)
        setObsolete(true);
}

void ModelCommand::undo()
{
    core::Status status;
    {
        EditScope scope(m_document);
        status = revert();
    }
    if (!status)
        fail(status);
}

void ModelCommand::fail(const core::Status& status)
{
    m_failed = true;
    setObsolete(true);
    //: %1 is the edit ("Rename variable Stop to Halt"), %2 why the model refused it
    m_document.reportEditFailure(QCoreApplication::translate("editor::ModelCommand", "%1: %2")
                                     .arg(text(), toQString(status.message)));
}

} // namespace editor
