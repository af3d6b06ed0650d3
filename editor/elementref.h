#pragma once

#include <QMetaType>
#include <QString>

namespace editor {

// What the user can select or point at: a step, a transition, a variable,
// or the model itself. Holds an id, never a pointer, so it stays valid
// across undo and reload.
struct ElementRef {
    enum class Kind { None, Model, Step, Transition, Variable };

    Kind kind = Kind::None;
    QString id; // step id, transition id or variable name

    bool isNull() const { return kind == Kind::None; }
    static ElementRef step(const QString& id) { return {Kind::Step, id}; }
    static ElementRef transition(const QString& id) { return {Kind::Transition, id}; }
    static ElementRef variable(const QString& name) { return {Kind::Variable, name}; }

    friend bool operator==(const ElementRef& a, const ElementRef& b) { return a.kind == b.kind && a.id == b.id; }
    friend bool operator!=(const ElementRef& a, const ElementRef& b) { return !(a == b); }
};

} // namespace editor

Q_DECLARE_METATYPE(editor::ElementRef)
