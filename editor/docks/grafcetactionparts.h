#pragma once

#include "core/model/grafcet.h"

#include <QString>

namespace editor {

// What a step's action table shows of one action (spec grafcet-layer.md §2),
// split from its text and put back together: when it acts, its qualifier
// (N, S, R or := for `V := <expr>`), its variable, and its condition (N ...
// IF <condition>) or value (:=). The split is by words, not by parsing, so
// that a text that does not parse yet keeps every character: what cannot be
// told apart stays in the variable.
struct GrafcetActionParts {
    enum class Qualifier { N, S, R, Assign };

    core::ActionTiming timing = core::ActionTiming::Continuous;
    Qualifier qualifier = Qualifier::N;
    bool qualifierWritten = true; // N only: false for a bare `V`
    QString variable;
    QString operand; // N: the condition after IF; :=: the value; S, R: empty

    static GrafcetActionParts of(const core::GrafcetAction& action);
    core::GrafcetAction action() const;

    // N acts while the step is active and S, R, := when it is activated or
    // deactivated: changing one of the two keeps the other consistent.
    void setTiming(core::ActionTiming newTiming);
    void setQualifier(Qualifier newQualifier);

    // "N", "S", "R", ":="; parseQualifier reads them (any case), false otherwise.
    static QString qualifierText(Qualifier qualifier);
    static bool parseQualifier(const QString& text, Qualifier* qualifier);
};

} // namespace editor
