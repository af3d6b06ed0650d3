#pragma once

// The PackML settings of a model (spec packml.md §5.1), each one undo step:
// the edition with the two options of §2.3, the initial state, the initial
// unit mode.

#include "editor/commands/modelcommand.h"

#include "core/templates/packml/packmltemplate.h"

#include <QCoreApplication>

namespace editor {

// "Change PackML edition and options". Moving a model to 2022 gives its
// Complete command what a new 2022 model has when it has nothing: the
// condition Cmd_Complete and that BOOL input declared if no variable has the
// name (an empty condition would be an error, GG202).
class SetPackmlOptionsCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetPackmlOptionsCommand)

public:
    SetPackmlOptionsCommand(Document& document, core::packml::Options options);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;
    void adoptCompleteCommand();

    core::packml::Options m_options;
    core::packml::Options m_previous;
    bool m_setCompleteCondition = false;
    bool m_declaredCompleteInput = false;
};

// "Set initial state to Idle".
class SetPackmlInitialStateCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetPackmlInitialStateCommand)

public:
    SetPackmlInitialStateCommand(Document& document, core::packml::State state);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    core::packml::State m_state;
    core::packml::State m_previous = core::packml::State::Stopped;
};

// "Set initial mode to 3 Manual". Refused for a mode the model does not have.
class SetPackmlInitialModeCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetPackmlInitialModeCommand)

public:
    SetPackmlInitialModeCommand(Document& document, int mode);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    int m_mode;
    int m_previous = 1;
};

} // namespace editor
