#pragma once

// The pieces the PackML Promela export (packmlpromela.h) writes its text
// with: lines with their numbers, the names of the program's variables and
// instances in the model, and conditions as Promela expressions.

#include "core/codegen/nestedprogram.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionsyntax.h"
#include "core/templates/packml/packmlprogram.h"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace core::packml::promela {

// Thrown where the program uses what the export cannot write exactly.
struct Unsupported : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Lines {
public:
    // Appends one line; returns its 1-based number.
    int line(const std::string& text);
    void in() { ++m_indent; }
    void out() { --m_indent; }
    const std::string& text() const { return m_text; }

private:
    std::string m_text;
    int m_lines = 0;
    int m_indent = 0;
};

// Text safe inside a Promela comment.
std::string comment(std::string_view text);
// A BOOL or integer value as Promela writes it; throws Unsupported for a REAL.
std::string valueText(const cond::Value& value);
void addOnce(std::vector<int>& list, int value);

// Where a condition is evaluated: the PackML layer (no instance), or a call
// of an instance's GRAFCET (its steps, TONs, Complete and own outputs).
struct Place {
    int instance = -1;
    const NestedGrafcet* grafcet = nullptr;
    bool firstEvolution = false;           // edges are TRUE only in the first evolution of a call
    const std::map<int, int>* timers = nullptr; // StepDuration node -> timer, receptivities only
};

class Names {
public:
    explicit Names(const PackmlProgram& program, int cycleTimeMs);

    // The variable of a slot as the scan reads it: the chosen input or the stored value.
    std::string read(int slot) const;
    static std::string stored(int slot) { return "v" + std::to_string(slot); }
    static std::string input(int slot) { return "i" + std::to_string(slot); }
    static std::string previous(int slot) { return "p" + std::to_string(slot); }
    static std::string step(int instance, int number);
    static std::string output(int instance, std::size_t index); // index among the non-Complete outputs
    static std::string complete(int instance) { return "c" + std::to_string(instance); }
    static std::string timer(int instance, std::size_t index);
    // Runs with IN TRUE after which timer `index` of the GRAFCET has elapsed.
    std::int64_t runsToElapse(const NestedGrafcet& grafcet, std::size_t index) const;
    // The index of a non-Complete continuous output named `variable`, -1 when none.
    static int ownOutput(const NestedGrafcet& grafcet, std::string_view variable);

    // A usable condition, receptivity or action expression in Promela; an
    // empty one is `empty`. Throws Unsupported.
    std::string expression(const cond::Expression& expression, const Place& place, const char* empty = "1") const;
    // The Promela type of a variable; throws Unsupported for one it cannot hold.
    std::string type(const Variable& variable) const;
    bool holds(const Variable& variable) const;

private:
    std::string node(const cond::Expression& expression, int index, const Place& place) const;
    std::string variableRead(const std::string& name, const Place& place) const;
    void requireArithmetic(const cond::Expression& expression, int index) const;

    const PackmlProgram& m_program;
    int m_cycleTimeMs;
};

} // namespace core::packml::promela
