#pragma once

#include <QString>

#include <functional>

class QUndoStack;

namespace editor {

// The undo history follows the UI language: an entry made in English reads
// in French once the user switches. A ModelCommand keeps how to word its
// text; a macro begun with beginWordedMacro is remembered with its wording.

// QUndoStack::beginMacro, with a text that rewordUndoHistory words again.
void beginWordedMacro(QUndoStack* stack, std::function<QString()> wording);

// Words every entry of the stack that knows how again, in the current UI language.
void rewordUndoHistory(QUndoStack* stack);

} // namespace editor
