#pragma once

// The example models shipped with GG Studio (the repository's examples/
// folder, embedded as resources under :/examples), for File > Examples. An
// example opens as an untitled copy: saving it asks for a new file, so the
// shipped file is never changed.

#include "core/model/model.h"

#include <QString>

#include <memory>
#include <vector>

namespace editor {

struct ExampleModel {
    QString fileName;    // "drilling-cell.ggstudio.json", under :/examples
    QString title;       // translated, for the menu
    QString description; // translated, for the status tip
};

// In menu order; the texts follow the current UI language.
std::vector<ExampleModel> exampleModels();

// The example's model, or null with a message in *error.
std::unique_ptr<core::Model> loadExampleModel(const ExampleModel& example, QString* error);

} // namespace editor
