#pragma once

// Satisfiability over the receptivities of a nested GRAFCET, for the checks
// that compare them (core/checks/grafcetchecks.cpp,
// core/checks/grafcetsequencechecks.cpp).

#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionsyntax.h"
#include "core/model/model.h"

#include <optional>
#include <string>
#include <vector>

namespace core {

// The satisfiability of core/verification knows declared variables only: the
// atoms of the nested layer (X3, 5s/X3, RE a, Complete) become free BOOL
// variables of their own. Treating them as free only adds valuations, so a
// conjunction found unsatisfiable really is.
class FreeAtomSpace {
public:
    explicit FreeAtomSpace(const std::vector<Variable>& declared);

    const std::vector<Variable>& variables() const { return m_variables; }

    // The expression with each nested atom replaced by a variable node.
    cond::Expression substitute(const cond::Expression& expression);

    // True when the expression reads a nested atom (it would be substituted).
    static bool readsNestedAtom(const cond::Expression& expression);

private:
    static std::optional<std::string> atomName(const cond::Expression& expression, const cond::Node& node);
    void declare(const std::string& name);

    std::vector<Variable> m_variables;
};

// a AND b, in one arena.
cond::Expression conjunction(const cond::Expression& a, const cond::Expression& b);

// NOT a.
cond::Expression negation(const cond::Expression& a);

// "A = TRUE, Level = 3": the values of the variables the expression reads,
// in the order it first reads them.
std::string describeValuation(const cond::Expression& expression, const std::vector<Variable>& variables,
                              const std::vector<cond::Value>& values);

} // namespace core
