#pragma once

// Reading and writing model files of every format GG Studio knows, chosen by
// content (and extension when writing). Each format has its own file pair;
// this is the single entry point the CLI and the editor use.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace core {

enum class ModelFormat { Native, GGGenerator, PlcOpen };

// Largest model file accepted; larger files are refused before being read.
inline constexpr std::uintmax_t kMaxModelFileBytes = 64ull * 1024 * 1024;

struct LoadedModel {
    std::unique_ptr<Model> model; // set on success
    ModelFormat format = ModelFormat::Native;
    LoadError error;              // set when model is null
    // What the model did not take over from the file, though it loaded (a
    // GG-Generator file's GG Studio keys, a PLCopen file's edited code): the
    // CLI prints them, the editor shows them on open.
    std::vector<LoadWarning> warnings;
    bool ok() const { return model != nullptr; }
};

// Detects the format from the content (native JSON, GG-Generator JSON, or a
// GG Studio PLCopen XML file carrying its model).
LoadedModel loadModelFile(const std::string& path);
LoadedModel loadModelText(std::string_view text, const std::string& displayName);

// Which templates a reader of model files handles: PackML support comes
// command by command (a PackML model is generated and simulated before the
// editor draws it).
enum class TemplateSupport { GemmaOnly, GemmaAndPackML };

// The message for a model this reader loads but cannot yet handle (a PackML
// model where only GEMMA is supported); empty for a model it supports.
std::string unsupportedModelMessage(const Model& model, TemplateSupport support = TemplateSupport::GemmaOnly);
// loadModelFile, refusing such a model with that message (and no model):
// what the editor and the command-line tool open.
LoadedModel loadSupportedModelFile(const std::string& path, TemplateSupport support = TemplateSupport::GemmaOnly);

// Writes the model as a Native or GGGenerator file, atomically: on failure
// the previous file is intact. PlcOpen files are written by the PLCopen
// export (core/codegen/plcopenwriter.h); asking for one here is a failure.
Status saveModelFile(const Model& model, const std::string& path, ModelFormat format);

} // namespace core
