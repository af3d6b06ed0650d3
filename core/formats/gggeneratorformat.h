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

// What saveGGGeneratorJson leaves out of the nested layer, one English
// sentence each (empty when nothing): the nested GRAFCETs, the variable
// kinds, the until-stable rule. Exporting says so; nothing is silently lost.
std::vector<std::string> ggGeneratorLosses(const Model& model);

// Either a whole model or an error naming the JSON path. Tokens come from
// data.savedSignalsWithMemory entries with withMemory true that name a
// declared BOOL variable occurring in the condition; other entries are the
// web tool's remembered settings and are ignored.
std::variant<std::unique_ptr<Model>, LoadError> loadGGGeneratorJson(std::string_view text, const std::string& displayName);

// True when the text looks like a GG-Generator file (for format detection).
bool looksLikeGGGeneratorJson(std::string_view text);

} // namespace core
