#pragma once

#include <QMetaType>
#include <QString>

namespace editor {

// What the user can select or point at: a step, a transition, a variable,
// the model itself, or a step or transition of a nested GRAFCET; in a PackML
// model a state, a transition, a command or a unit mode. Holds ids and
// numbers, never a pointer, so it stays valid across undo and reload.
struct ElementRef {
    // GrafcetStep, GrafcetTransition: `id` is the GEMMA step whose nested
    // GRAFCET holds the element, `number` its step or transition number.
    // PackmlState: `id` the PackTags state name ("Execute"), `number` the
    // unit mode the chart showed it in, or 0. PackmlTransition: `id`
    // "Source->Target" with the template's target (before skipping),
    // `number` as for a state. PackmlCommand: `id` the command's name
    // ("Reset"). PackmlMode: `number` the mode's number.
    enum class Kind {
        None,
        Model,
        Step,
        Transition,
        Variable,
        GrafcetStep,
        GrafcetTransition,
        PackmlState,
        PackmlTransition,
        PackmlCommand,
        PackmlMode,
    };

    Kind kind = Kind::None;
    QString id; // step id, transition id or variable name
    int number = 0; // nested kinds only

    bool isNull() const { return kind == Kind::None; }
    bool isNested() const { return kind == Kind::GrafcetStep || kind == Kind::GrafcetTransition; }
    static ElementRef step(const QString& id) { return {Kind::Step, id}; }
    static ElementRef transition(const QString& id) { return {Kind::Transition, id}; }
    static ElementRef variable(const QString& name) { return {Kind::Variable, name}; }
    static ElementRef grafcetStep(const QString& stepId, int number) { return {Kind::GrafcetStep, stepId, number}; }
    static ElementRef grafcetTransition(const QString& stepId, int number)
    {
        return {Kind::GrafcetTransition, stepId, number};
    }

    static ElementRef packmlState(const QString& state, int mode = 0) { return {Kind::PackmlState, state, mode}; }
    static ElementRef packmlTransition(const QString& source, const QString& target, int mode = 0)
    {
        return {Kind::PackmlTransition, source + QStringLiteral("->") + target, mode};
    }
    static ElementRef packmlCommand(const QString& command) { return {Kind::PackmlCommand, command}; }
    static ElementRef packmlMode(int mode) { return {Kind::PackmlMode, QString(), mode}; }

    friend bool operator==(const ElementRef& a, const ElementRef& b)
    {
        return a.kind == b.kind && a.id == b.id && a.number == b.number;
    }
    friend bool operator!=(const ElementRef& a, const ElementRef& b) { return !(a == b); }
};

} // namespace editor

Q_DECLARE_METATYPE(editor::ElementRef)
