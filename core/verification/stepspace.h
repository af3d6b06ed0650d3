#pragma once

// The verifier's view of one visible step (internal to core/verification/verification.cpp,
// separate for size): its transitions as formulas over atoms, its tokens
// grouped by literal, and, symbolically, every configuration the step can be
// in and what each configuration can do in its next scan.
//
// Configurations of a step S: its entry configuration E (Entry = TRUE, the
// tokens about to be cleared) and, for a step with a nested behaviour, the
// configurations (Entry = FALSE, t) where t is the value of each token group.
// In every formula below the entry configuration reads as t = 0: the entry
// block clears the tokens before the step reads them. Diagram variables: the
// atoms of the step's conditions (inputs), Complete, and per token group t
// (now) and t' (after the scan).

#include "core/verification/decisiondiagram.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/verification/satisfiability.h"

#include <functional>
#include <map>
#include <string>
#include <memory>
#include <utility>
#include <vector>

namespace core::verify {

struct TokenGroup {
    int variable = -1;   // BOOL variable index
    bool negated = false; // normally closed: captures variable = FALSE
    std::vector<std::string> tokens; // token variable names
};

struct CompiledTransition {
    const GemmaTransition* transition = nullptr;
    sat::Formula formula; // FALSE when the condition is unusable
};

struct CompiledStep {
    const GemmaStep* step = nullptr;
    int index = 0; // in GemmaProgram::steps
    std::vector<CompiledTransition> transitions; // evaluation order
    std::vector<TokenGroup> groups;
    // (transition index, literal node) -> token group
    std::map<std::pair<int, int>, int> leafGroup;
    bool freeComplete = true; // meaningful for nested steps only
};

class StepSpace {
public:
    // Builds the formulas and explores the step's token configurations.
    // Its diagrams spend `budget` (throwing bdd::BudgetExceeded when it runs
    // out); the budget and the atoms must outlive it.
    StepSpace(const CompiledStep& step, const sat::AtomTable& atoms, bdd::Budget& budget,
              const std::function<bool()>& cancelled);

    bdd::Manager& manager() { return *m_manager; }
    const CompiledStep& step() const { return m_step; }
    bool nested() const { return m_step.step->hasNestedBehaviour(); }

    // Over inputs and tokens.
    bdd::Ref theory() const { return m_theory; }
    bdd::Ref gated(std::size_t i) const { return m_gated[i]; } // condition AND Complete where it waits
    bdd::Ref fires(std::size_t i) const { return m_fires[i]; } // theory, gated(i), no earlier one
    bdd::Ref noFire() const { return m_noFire; }
    bdd::Ref update() const { return m_update; } // over tokens, inputs and primed tokens

    // Sets of token values (over the token variables).
    bdd::Ref zero() const { return m_zero; }               // t = 0: how the entry configuration reads
    const std::vector<bdd::Ref>& layers() const { return m_layers; } // layers()[m-1]: first reached m scans after entry
    bdd::Ref reached() const { return m_reached; }         // every (Entry = FALSE) configuration
    bdd::Ref anyConfiguration() const { return m_any; }    // zero() or reached(): the token values S is seen with

    // Token values from which the scan can satisfy `f` (over inputs and tokens).
    bdd::Ref possible(bdd::Ref f);
    // Token values from which some path staying in S reaches `target` (token values).
    bdd::Ref canReach(bdd::Ref target);
    // The successors of a set of token values in scans where nothing fires.
    bdd::Ref image(bdd::Ref set);
    // Token values from which a no-fire scan leads into `set`.
    bdd::Ref preimage(bdd::Ref set);

    // A cube fixing every token (now or primed) to the given values.
    bdd::Ref tokenCube(const std::vector<bool>& values, bool primed);
    std::vector<bool> tokensOf(const std::vector<bool>& assignment) const; // token values in a full assignment

    long double configurationCount(); // entry configuration included
    int completeVariable() const { return m_completeVar; }
    int atomVariable(int atom) const; // Boolean and opaque atoms; -1 for comparisons (region bits)
    const std::vector<int>& usedAtoms() const { return m_usedAtoms; }
    // The truth of an atom of the step under a full assignment.
    bool atomHolds(int atom, const std::vector<bool>& assignment);
    // Per diagram variable: 1 where the inputs as they are (values by
    // variable index) make it TRUE, for bdd::Manager::pick.
    std::vector<int> preferredAssignment(const std::vector<cond::Value>& values);
    const std::vector<bool>& inputMask() const { return m_inputMask; }
    const std::vector<bool>& tokenMask() const { return m_tokenMask; }

private:
    void assignVariables(const sat::AtomTable& atoms);
    void buildFormulas(const sat::AtomTable& atoms);
    void explore();
    void checkCancelled() const;

    const CompiledStep& m_step;
    const sat::AtomTable& m_atoms;
    std::function<bool()> m_cancelled;
    bdd::Budget& m_budget;
    std::unique_ptr<bdd::Manager> m_manager;
    std::unique_ptr<sat::Encoder> m_encoder;
    int m_completeVar = -1;
    std::vector<int> m_tokenVar;
    std::vector<int> m_primedVar;
    std::vector<int> m_atomVar; // per atom of the table; -1 when unused here
    std::vector<int> m_usedAtoms;
    std::vector<int> m_toPrimed;
    std::vector<int> m_fromPrimed;
    std::vector<bool> m_inputMask;
    std::vector<bool> m_tokenMask;
    std::vector<bool> m_imageMask;    // inputs and tokens
    std::vector<bool> m_preimageMask; // inputs and primed tokens
    bdd::Ref m_theory = bdd::kTrue;
    std::vector<bdd::Ref> m_gated;
    std::vector<bdd::Ref> m_fires;
    bdd::Ref m_noFire = bdd::kFalse;
    bdd::Ref m_update = bdd::kTrue;
    bdd::Ref m_zero = bdd::kTrue;
    std::vector<bdd::Ref> m_layers;
    bdd::Ref m_reached = bdd::kFalse;
    bdd::Ref m_any = bdd::kFalse;
};

struct Cancelled {};

} // namespace core::verify
