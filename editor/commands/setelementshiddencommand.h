#pragma once

#include "editor/commands/modelcommand.h"
#include "editor/elementref.h"

#include <QCoreApplication>
#include <QList>

#include <string>
#include <vector>

namespace editor {

// Hides or shows several steps and transitions as one undoable step
// ("Hide 3 elements"): the chart's multi-selection, Delete, the context
// menu. Elements already so are left alone and restored as they were; a
// command that changes nothing is dropped.
class SetElementsHiddenCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetElementsHiddenCommand)

public:
    SetElementsHiddenCommand(Document& document, const QList<ElementRef>& elements, bool hidden);

private:
    core::Status apply() override;
    core::Status revert() override;
    core::Status setHidden(const ElementRef& element, bool hidden);

    QList<ElementRef> m_elements;
    QList<ElementRef> m_changed; // those the first run changed
    bool m_hidden;
};

} // namespace editor
