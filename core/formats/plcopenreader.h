#pragma once

// Reopening a PLCopen XML file that GG Studio exported (core/codegen/plcopenwriter.h):
// the model is read from the native JSON the file carries in its project
// addData, in either dialect. The PLC code itself is not read back.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <memory>
#include <string>
#include <string_view>
#include <variant>

namespace core {

std::variant<std::unique_ptr<Model>, LoadError> readPlcOpenModel(std::string_view xmlText,
                                                                 const std::string& displayName);

} // namespace core
