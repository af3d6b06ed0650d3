#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/model.h"

#include <QCoreApplication>

#include <vector>

namespace editor {

// "Paste 3 variables": inserts copies at a position of the variable list
// (-1: at the end), all in one undo step. A name already taken gets a free
// suffix (Start -> Start_2), chosen once, on the first run; the paste is
// all or nothing.
class PasteVariablesCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(PasteVariablesCommand)

public:
    PasteVariablesCommand(Document& document, std::vector<core::Variable> variables, int index = -1);
    int id() const override;

    // "Start" if free, else "Start_2", "Start_3"... (an existing "_<n>" suffix is replaced).
    static std::string freeName(const core::Model& model, const std::string& name);

private:
    core::Status apply() override;
    core::Status revert() override;
    void removeFirst(std::size_t count);

    std::vector<core::Variable> m_variables;
    int m_index;
};

} // namespace editor
