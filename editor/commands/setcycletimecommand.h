#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Set cycle time to 10 ms": the PLC task period. Consecutive edits merge,
// so stepping a spin box undoes as a whole.
class SetCycleTimeCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetCycleTimeCommand)

public:
    SetCycleTimeCommand(Document& document, int cycleTimeMs);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    core::Status apply() override;
    core::Status revert() override;

    int m_cycleTimeMs;
    int m_previous = 0;
};

} // namespace editor
