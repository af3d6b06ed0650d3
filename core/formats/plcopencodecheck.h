#pragma once

// A PLCopen file GG Studio exported is opened from the model it embeds, not
// from its code. When the code was edited outside GG Studio the two differ,
// and the edits would be lost without a word: this compares the file's code
// with what the embedded model generates (core/codegen) and names every
// difference, so that the loader can warn.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <string>
#include <string_view>
#include <vector>

namespace tinyxml2 {
class XMLElement;
}

namespace core {

// One warning per POU whose body, declarations or documentation differ, per
// POU that is missing or that the model does not generate, for the global
// variables and for the task (name, interval, priority); each with the line
// and column of its element. The dialect is the file's
// (the namespace tc6_0200 is CODESYS), not the model's setting, since the
// export may have chosen another one.
std::vector<LoadWarning> plcOpenCodeDifferences(std::string_view xmlText, const tinyxml2::XMLElement& project,
                                                const Model& model, const std::string& displayName);

} // namespace core
