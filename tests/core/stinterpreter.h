#pragma once

// A small interpreter of the GENERATED Structured Text (IEC dialect), for the
// tests that show the simulator agrees with the code the PLC runs. It knows
// only what the generator writes:
// - declarations: VAR_GLOBAL, and in each POU VAR_INPUT, VAR_OUTPUT,
//   VAR_EXTERNAL and VAR blocks of `name : TYPE [:= value];` (elementary
//   types, the FB types S_FB, TON, and R_TRIG in the program);
// - statements: assignments, IF/ELSIF/ELSE/END_IF, `CASE State OF` with
//   integer labels, REPEAT ... UNTIL ... END_REPEAT, calls with named
//   arguments: `F1(Initialization := Entry);`, `GG_T5_2000ms(IN := X5, PT := T#2s);`,
//   `Trig_Reset(CLK := Cmd_Reset);` (`Trig_Reset.Q` reads its output);
// - expressions: parsed by core::cond::parse (GEMMA context: X3 is a name)
//   and evaluated by core::cond::evaluate; `F1.Complete` reads an output of
//   the FB instance F1, `GG_T5_2000ms.Q` / `.ET` a TON's outputs.
// Every name is resolved when the text is read, by IEC scoping: an FB body
// sees its own variables and the globals it declares VAR_EXTERNAL, the
// program the same; another POU's variables only as `instance.output`.
// What it cannot read (a statement form, a name, a type) is an error(), so a
// change of the generator is noticed instead of silently mis-run.
//
// Values are stored by their declared IEC type: integers wrap around, REAL
// rounds to 32 bits. A TON is the IEC 61131-3 TON as matiec implements it
// (the start time is taken in the call in which IN rises; Q := start + PT <=
// now; IN := FALSE resets ET and Q), with the time the test gives (advanceTime).
//
// An FB instance whose FUNCTION_BLOCK text is not given is modelled as the
// generated skeleton:
//   IF Initialization THEN Complete := FALSE; END_IF;
//   Complete := TRUE;           (or the manual value the test gives)

#include "core/templates/gemma/gemmacodegen.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionsyntax.h"
#include "core/model/iectypes.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sttest {

// What an identifier of an expression or an assignment target denotes.
struct StReference {
    enum class Kind { Global, Local, TonQ, TonEt, Member };
    Kind kind = Kind::Global;
    int index = 0;  // Global: global slot; Local: slot of the running instance; Ton*: its TON; Member: instance
    int member = 0; // Member: slot in that instance
};

// An expression of the program text, its parse and its names resolved.
struct StExpression {
    std::string text;
    core::cond::Expression parsed;
    std::vector<StReference> references; // by node index (meaningful for Variable nodes)
    std::optional<std::int64_t> durationMs; // a TIME literal T#...: its value, `parsed` empty
};

class StInterpreter {
public:
    // programText: formatPou of the GEMMA POU (core::previewGemmaProgram);
    // globalsText: the VAR_GLOBAL block (core::formatGlobals) with the
    // globals' types and initial values; functionBlockTexts: formatPou of
    // FUNCTION_BLOCKs whose bodies are run (the others are skeletons).
    // error() says what could not be read.
    StInterpreter(std::string_view programText, std::string_view globalsText,
                  const std::vector<std::string>& functionBlockTexts = {});
    ~StInterpreter();
    StInterpreter(StInterpreter&&) noexcept;
    StInterpreter& operator=(StInterpreter&&) noexcept;

    const std::string& error() const { return m_error; }
    // The first problem met while running, empty if none.
    const std::string& runtimeError() const { return m_runtimeError; }

    // A global's value for the following scans.
    void setInput(std::string_view name, const core::cond::Value& value);
    // For a skeleton instance: nullopt is the skeleton (Complete := TRUE);
    // otherwise the value its body writes.
    void setManualComplete(std::string_view instance, std::optional<bool> value);

    // The PLC clock the TONs read (ms), advanced between scans by the test.
    void advanceTime(std::int64_t milliseconds) { m_nowMs += milliseconds; }
    std::int64_t nowMs() const { return m_nowMs; }

    // Runs the program body once.
    void scan();

    core::cond::Value value(std::string_view name) const; // a global or a program variable; FALSE when unknown
    int state() const;
    bool entry() const;
    bool complete(std::string_view instance) const;
    // The FB instances, in declaration order.
    const std::vector<std::string>& instances() const { return m_instanceNames; }
    // The instance runs its FUNCTION_BLOCK text (not the skeleton).
    bool runsBody(std::string_view instance) const;
    // A variable of an FB instance (input, output or local): X3, Unstable,
    // Complete, a continuous output. nullopt when it has none of that name.
    std::optional<core::cond::Value> member(std::string_view instance, std::string_view name) const;
    // The same by index, for tight loops: -1 when unknown.
    int globalIndex(std::string_view name) const;
    const core::cond::Value& globalAt(int index) const { return m_globals[static_cast<std::size_t>(index)]; }
    int instanceIndex(std::string_view name) const;
    int memberIndex(int instance, std::string_view name) const;
    const core::cond::Value& memberAt(int instance, int member) const;
    // A TON of an FB instance: its Q and ET (ms). nullopt when it has none of that name.
    struct TonOutputs {
        bool q = false;
        std::int64_t etMs = 0;
    };
    std::optional<TonOutputs> timer(std::string_view instance, std::string_view name) const;
    // The BOOL locals of the program named *_MEM, in declaration order.
    const std::vector<std::string>& tokenNames() const { return m_tokenNames; }
    // Statements run since construction (a guard against a silent no-op).
    std::int64_t statementsRun() const { return m_statementsRun; }

    struct Statement;
    struct Pou;
    struct Instance;

private:
    void execute(const std::vector<Statement>& statements);
    void call(const Statement& statement);
    bool truth(const StExpression& expression);
    core::cond::Value evaluate(const StExpression& expression);
    core::cond::Value read(const StReference& reference) const;
    void assign(const StReference& reference, const core::cond::Value& value);

    std::vector<core::cond::Value> m_globals;    // the VAR_GLOBALs, then the program's own variables
    std::vector<core::IecType> m_globalTypes;
    std::map<std::string, int> m_globalSlot;     // by upper-case name
    std::vector<std::unique_ptr<Pou>> m_pous;    // the FUNCTION_BLOCK types given
    std::vector<Instance> m_instances;
    std::vector<std::string> m_instanceNames;
    std::vector<Statement> m_body;
    std::vector<std::string> m_tokenNames;
    Instance* m_running = nullptr;               // the instance whose body runs, nullptr for the program
    std::int64_t m_nowMs = 0;
    std::int64_t m_statementsRun = 0;
    std::string m_error;
    std::string m_runtimeError;
};

} // namespace sttest
