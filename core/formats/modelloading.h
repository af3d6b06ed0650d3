#pragma once

// The checks every model file loader shares while it turns a file's data
// into a Model: exactly one initial step, per-source orders forming 1..m,
// unique variable names. Each failure throws JsonReadError (core/formats/jsonreader.h)
// at the JSON path of the offending value; loaders catch it.

#include "core/model/model.h"
#include "core/model/status.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace core {

// Turns a failed model operation into an error at the given path.
void require(const Status& status, const std::string& path);

// A step's initial flag as a file states it.
struct InitialFlag {
    std::string stepId;
    bool initial = false;
    std::string path;
};

// One flag set to true makes that step the initial one; two are an error;
// with none, the model's initial step stays unless the file cleared it.
void applyInitialFlags(Model& model, const std::vector<InitialFlag>& flags, const std::string& stepsPath);

// A transition's order as a file states it; the caller has checked 1..m.
struct OrderValue {
    std::string transitionId;
    int order = 1;
    std::string path;
};

// Transitions the file leaves out keep their order; together the orders of
// each source must be 1..m, each once.
void applyOrders(Model& model, const std::vector<OrderValue>& orders);

// Far above any real machine; keeps loading time linear-ish on hostile files
// (the model checks names one by one).
inline constexpr std::size_t kMaxFileVariables = 10000;

struct VariableEntry {
    Variable variable;
    std::string namePath;
};

// How a file format spells a variable entry, for reading and for messages.
struct VariableEntrySpelling {
    const char* noun;        // "variable", "signal"
    const char* typeExample; // "an IEC type such as \"BOOL\""
    const char* typeList;    // "BOOL, SINT, ..." as the format writes them
};

// The name and type of the variable entry at path (members "name" and
// "type"); the caller reads the members its format adds.
VariableEntry readVariableNameAndType(const nlohmann::ordered_json& object, const std::string& path,
                                      const VariableEntrySpelling& spelling);

// Appends the variables, refusing empty and case-insensitively duplicate
// names and more than kMaxFileVariables variables (listPath names the list).
void addVariables(Model& model, const std::vector<VariableEntry>& variables, const std::string& listPath);

// Where the file names the source of a transition, for messages:
// "F1", or "the F family frame".
std::string describeSource(std::string_view source);

} // namespace core
