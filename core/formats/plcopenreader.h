#pragma once

// Reopening a PLCopen XML file that GG Studio exported (core/codegen/plcopenwriter.h):
// the model is read from the native JSON the file carries in its project
// addData, in either dialect. The PLC code itself is not read back, but it is
// compared with the code the model generates: each difference (code edited
// outside GG Studio) is named in `warnings` when given, since the edits are
// not kept. A file with two embedded models is refused: GG Studio cannot tell
// which one the file means.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace core {

std::variant<std::unique_ptr<Model>, LoadError> readPlcOpenModel(std::string_view xmlText,
                                                                 const std::string& displayName,
                                                                 std::vector<LoadWarning>* warnings = nullptr);

} // namespace core
