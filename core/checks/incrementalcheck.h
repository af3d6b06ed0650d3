#pragma once

// checkModel after an edit, recomputing only what the edit can affect
// (issue #36: re-check after one receptivity edit within 1 ms on the nested
// stress model). The result is always checkModel's, in its order.
//
// It keeps the diagnostics of a GEMMA model by what they depend on: the GEMMA
// steps and transitions, each nested GRAFCET (its own checks and the
// problems the code generator finds in its texts, with the variables its
// texts name and those it reads under an edge), the stored writes refused
// across GRAFCETs (GG415) and the machine. An edit inside the transitions of
// nested GRAFCETs (a receptivity, an upstream or downstream set: what a
// GrafcetChange::Kind::Transition reports) recomputes those GRAFCETs' parts,
// then the model-wide checks that read what every GRAFCET uses, which are
// cheap: GG420 (a variable named like an edge memory) and the variables
// (GG305 unused). Any other change, a PackML model, or a model other than
// the one of the last call: the whole check, from which the parts are kept.
// A GEMMA transition's change (ModelChange::Kind::Transition) whose only
// difference from the transition as last checked is its condition recomputes
// the GEMMA steps and transitions, and the variables; none of the nested
// checks reads a GEMMA condition.

#include "core/checks/diagnostic.h"
#include "core/codegen/nestedprogram.h"
#include "core/model/model.h"

#include <optional>
#include <string>
#include <vector>

namespace core {

class IncrementalCheck {
public:
    // checkModel(model), keeping its parts.
    const std::vector<Diagnostic>& checkAll(const Model& model);

    // checkModel(model) after `changes`, every change the model reported
    // since the last call on this model, in order.
    const std::vector<Diagnostic>& update(const Model& model, const std::vector<ModelChange>& changes);

    const std::vector<Diagnostic>& diagnostics() const { return m_result; }
    // True when the last call recomputed only some parts.
    bool lastWasIncremental() const { return m_lastIncremental; }

private:
    struct GrafcetPart {
        std::string stepId;
        std::vector<Diagnostic> checks;        // checkStepGrafcet
        bool built = false;                    // visible, with an effective GRAFCET
        std::vector<Diagnostic> problems;      // the code generator's, without GG415
        std::vector<std::string> edgeVariables;
        std::vector<bool> used;                // by declaration index
    };

    // What the changes affect: `parts` (indices into m_parts), `gemma` (the
    // GEMMA steps and transitions); false when they are not handled precisely.
    bool handledPrecisely(const Model& model, const std::vector<ModelChange>& changes,
                          std::vector<std::size_t>& parts, bool& gemma) const;
    bool onlyConditionChanged(const Model& model, const std::string& transitionId) const;
    static std::optional<NestedGrafcet> computePart(const Model& model, GrafcetPart& part);
    void assemble(const Model& model);

    const Model* m_model = nullptr;
    std::vector<Diagnostic> m_gemma;     // steps and transitions
    std::vector<bool> m_conditionUses;   // by declaration index
    std::vector<Transition> m_transitions; // the GEMMA transitions as last checked
    std::vector<GrafcetPart> m_parts;    // GEMMA steps with a GRAFCET, in state order
    std::vector<Diagnostic> m_storedWrites; // GG415
    std::vector<Diagnostic> m_machine;
    std::vector<Diagnostic> m_result;
    bool m_lastIncremental = false;
};

} // namespace core
