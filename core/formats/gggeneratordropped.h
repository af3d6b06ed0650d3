#pragma once

// GG Studio's own keys in a GG-Generator file (a file put together by hand,
// or a GG Studio model that lost its "format"): the GG-Generator reader has no
// place for what they hold, so loading names each one, with its JSON path,
// instead of dropping it silently (docs/file-formats.md, "Import").

#include "core/formats/loaderror.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace core {

// One warning per key, in file order: the root's "name", "settings" (each of
// its members), "steps", "transitions", "variables", "grafcets" and
// "properties", and each signal's "kind" and "comment".
std::vector<LoadWarning> ggStudioKeysInGGGeneratorFile(const nlohmann::ordered_json& root,
                                                       const std::string& displayName);

} // namespace core
