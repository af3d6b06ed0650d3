#pragma once

// How the PackML undo commands name what they edit: "3 Manual" for a mode,
// read when the command is made (a later rename leaves the history as it was).

#include "core/model/model.h"

#include <QString>

namespace editor {

// "3 Manual"; the number alone for a mode the model does not have (yet).
QString modeTitleOf(const core::Model& model, int number);

// The number of a mode as a text field command's element, and back.
QString modeElement(int number);
int modeNumberOf(const std::string& element);

} // namespace editor
