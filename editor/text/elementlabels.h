#pragma once

#include "core/templates/gemma/gemmatemplate.h"

#include <QString>

namespace core {
class Model;
struct Transition;
} // namespace core

namespace editor {

// How the docks name model elements in the UI language.

// "A1 → F4"; the family transition reads "F (family) → D1".
QString transitionLabel(const core::Transition& transition);
// The same from an id ("F1->A2"); the id itself when it is not one.
QString transitionLabel(const QString& transitionId);

// "Simple step", "Macro-step", "Enclosing step".
QString stepTypeText(core::StepType type);

// Why a transition generates no code ("hidden", "target F2 hidden"...);
// empty when it is effective.
QString ineffectiveReason(const core::Model& model, const core::Transition& transition);

} // namespace editor
