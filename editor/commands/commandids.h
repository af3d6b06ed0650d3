#pragma once

namespace editor {

// QUndoCommand::id() of every model command. QUndoStack only offers two
// commands of the same id to mergeWith(); those that merge say so.
enum CommandId : int {
    SetStepTypeId = 1,
    SetInitialStepId,
    SetStepHiddenId,
    SetStepCommentId, // merges typing in the same step's comment
    SetTransitionHiddenId,
    SetPriorityId,
    SetConditionId, // merges typing in the same transition's condition
    SetNegatedId,
    SetTokensId,
    AddVariableId,
    RemoveVariableId,
    RenameVariableId,
    SetVariableTypeId,
    SetVariableDefaultId, // merges typing in the same variable's default
    SetVariableCommentId, // merges typing in the same variable's comment
    MoveVariableId,
    ResetModelId,
    SetModelNameId, // merges typing in the model name
    SetCycleTimeId, // merges spin box steps
    SetDialectId,
    PasteVariablesId,
    SetVariableKindId,
    SetEvolutionRuleId,
    EditGrafcetId,
    SetReceptivityId,         // merges typing in the same nested transition's receptivity
    SetGrafcetStepCommentId,  // merges typing in the same nested step's comment
    SetGrafcetStepInitialId,
    RenumberGrafcetStepId,
    SetGrafcetActionId,       // merges typing in the same action of the same nested step
    AddGrafcetActionId,
    RemoveGrafcetActionId,
    MoveGrafcetActionId,
    AddPropertyId,
    RemovePropertyId,
    MovePropertyId,
    SetPropertyTextId,    // merges typing in the same property
    SetPropertyCommentId, // merges typing in the same property's comment
    SetPackmlOptionsId,
    SetPackmlInitialStateId,
    SetPackmlInitialModeId,
    SetCommandConditionId, // merges typing in the same PackML command's condition
    SetCommandCommentId,   // merges typing in the same PackML command's comment
    AddModeId,
    RemoveModeId,
    RenameModeId,         // merges typing in the same unit mode's name
    SetModeCommentId,     // merges typing in the same unit mode's comment
    SetModeRequestId,     // merges typing in the same unit mode's request condition
    SetModeDisabledId,
    SetModeChangeStatesId,
    SetGrafcetChoiceId,
    AddMachineComponentId,
    RemoveMachineComponentId,
    EditMachineComponentId, // merges steps of the same time or count of the same component
};

} // namespace editor
