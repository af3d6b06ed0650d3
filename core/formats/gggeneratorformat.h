#pragma once

// The JSON file of GG-Generator, the published GEMMA-GRAFCET web tool (spec
// §8; docs/file-formats.md): {graph, nodes, connections}, nodes found by
// name, connections by node key.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace core {

// Deterministic: fixed node keys derived from the step ids, geometry from
// templateLayout(). What GG-Generator has no place for (model name,
// settings, comments) is not written.
std::string saveGGGeneratorJson(const Model& model);

// One part of the model saveGGGeneratorJson leaves out, as data: the editor
// words it in the UI language, toText() gives the English the command line
// prints. Exporting says so; nothing is silently lost.
struct GGGeneratorLoss {
    enum class Kind {
        NestedGrafcets,  // steps: the GEMMA steps whose GRAFCET is left out
        VariableKinds,   // output and internal kinds: GG-Generator reads every variable as an input
        UntilStableRule, // the model's evolution rule
        Properties,      // the engineer's verification properties
    };
    Kind kind = Kind::NestedGrafcets;
    std::vector<std::string> steps;

    friend bool operator==(const GGGeneratorLoss&, const GGGeneratorLoss&) = default;
};

// In the order of the Kind enumeration; empty when the file keeps everything.
std::vector<GGGeneratorLoss> ggGeneratorLosses(const Model& model);
std::string toText(const GGGeneratorLoss& loss);

// Either a whole model or an error naming the JSON path. Tokens come from
// data.savedSignalsWithMemory entries with withMemory true that name a
// declared BOOL variable occurring in the condition; other entries are the
// web tool's remembered settings and are ignored. GG Studio's own keys, which
// the format has no place for, are not loaded: each is named in `warnings`
// (core/formats/gggeneratordropped.h) when given.
std::variant<std::unique_ptr<Model>, LoadError> loadGGGeneratorJson(std::string_view text, const std::string& displayName,
                                                                    std::vector<LoadWarning>* warnings = nullptr);

// True when the text looks like a GG-Generator file (for format detection).
bool looksLikeGGGeneratorJson(std::string_view text);

} // namespace core
