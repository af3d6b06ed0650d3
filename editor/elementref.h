#pragma once

#include <QMetaType>
#include <QString>

namespace editor {

// What the user can select or point at: a step, a transition, a variable,
// the model itself, or a step or transition of a nested GRAFCET. Holds ids
// and numbers, never a pointer, so it stays valid across undo and reload.
struct ElementRef {
    // GrafcetStep, GrafcetTransition: `id` is the GEMMA step whose nested
    // GRAFCET holds the element, `number` its step or transition number.
    enum class Kind { None, Model, Step, Transition, Variable, GrafcetStep, GrafcetTransition };

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

    friend bool operator==(const ElementRef& a, const ElementRef& b)
    {
        return a.kind == b.kind && a.id == b.id && a.number == b.number;
    }
    friend bool operator!=(const ElementRef& a, const ElementRef& b) { return !(a == b); }
};

} // namespace editor

Q_DECLARE_METATYPE(editor::ElementRef)
