#pragma once

// What the PackML docks share: the problems of a condition for its editor,
// a secondary-text hint label, the page a PackML dock shows on a GEMMA model.

#include "editor/docks/conditionedit.h"

#include "core/checks/diagnostic.h"

#include <QList>
#include <QString>

#include <vector>

class QLabel;
class QWidget;

namespace core {
class Model;
}

namespace editor {

// The diagnostics about the field "condition" that have a span, placed on
// `condition` as ConditionEdit underlines them (GG201-GG204, PM011, PM019...).
QList<ConditionEdit::Problem> conditionProblems(const QString& condition,
                                                const std::vector<core::Diagnostic>& diagnostics);

// A wrapping label in the secondary text colour, a little smaller.
QLabel* packmlHintLabel(QWidget* parent);

// The declared variables' names, for ConditionEdit's completion.
QStringList declaredVariableNames(const core::Model& model);

} // namespace editor
