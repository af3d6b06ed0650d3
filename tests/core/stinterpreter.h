#pragma once

// A small interpreter of the GENERATED GEMMA program text (IEC dialect), for
// the test that shows the simulator agrees with the code the PLC runs. It
// knows only what the generator writes: VAR blocks, `CASE State OF` with
// integer labels, IF/ELSIF/ELSE/END_IF, assignments, calls
// `F1(Initialization := Entry);` and the token updates after END_CASE.
// Expressions are parsed by core::cond::parse and evaluated by
// core::cond::evaluate; `F1.Complete` reads the Complete output of the FB
// instance F1.
//
// The function blocks are modelled as the generated skeleton:
//   IF Initialization THEN Complete := FALSE; END_IF;
//   Complete := TRUE;           (or the manual value the test gives)

#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionsyntax.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sttest {

// An expression of the program text and its parse.
struct StExpression {
    std::string text;
    core::cond::Expression parsed;
};

class StInterpreter {
public:
    // programText: formatPou of the GEMMA POU (core::previewGemmaProgram);
    // globalsText: the VAR_GLOBAL block (core::formatGlobals) with the
    // globals' types and initial values. error() says what could not be read.
    StInterpreter(std::string_view programText, std::string_view globalsText);
    ~StInterpreter();

    const std::string& error() const { return m_error; }
    // The first problem met while running (an undeclared name), empty if none.
    const std::string& runtimeError() const { return m_runtimeError; }

    // A global's value for the following scans.
    void setInput(std::string_view name, const core::cond::Value& value);
    // nullopt: the skeleton FB (Complete := TRUE); otherwise the value its body writes.
    void setManualComplete(std::string_view instance, std::optional<bool> value);

    // Runs the program body once.
    void scan();

    core::cond::Value value(std::string_view name) const; // FALSE when unknown
    int state() const;
    bool entry() const;
    bool complete(std::string_view instance) const;
    // The BOOL locals named *_MEM, in declaration order.
    const std::vector<std::string>& tokenNames() const { return m_tokenNames; }
    // The FB instances, in declaration order.
    const std::vector<std::string>& instances() const { return m_instances; }

    struct Statement;

private:
    void execute(const std::vector<Statement>& statements);
    bool truth(const StExpression& expression) const;
    core::cond::Value evaluate(const StExpression& expression) const;

    std::map<std::string, core::cond::Value> m_values; // by upper-case name; FB outputs as "F1.COMPLETE"
    std::map<std::string, std::optional<bool>> m_manual;
    std::vector<Statement> m_body;
    std::vector<std::string> m_tokenNames;
    std::vector<std::string> m_instances;
    std::string m_error;
    mutable std::string m_runtimeError;
};

} // namespace sttest
