#include "core/formats/modelfiles.h"

#include "core/formats/fileio.h"
#include "core/formats/gggeneratorformat.h"
#include "core/formats/jsonreader.h"
#include "core/formats/nativeformat.h"
#include "core/formats/plcopenreader.h"

namespace core {

namespace {

LoadedModel fromResult(std::variant<std::unique_ptr<Model>, LoadError> result, ModelFormat format,
                       std::vector<LoadWarning> warnings = {})
{
    LoadedModel loaded;
    loaded.format = format;
    if (auto* model = std::get_if<std::unique_ptr<Model>>(&result)) {
        loaded.model = std::move(*model);
        loaded.warnings = std::move(warnings);
    } else
        loaded.error = std::get<LoadError>(std::move(result));
    return loaded;
}

LoadedModel failure(const std::string& displayName, std::string message)
{
    LoadedModel loaded;
    loaded.error = LoadError{displayName, {}, std::move(message)};
    return loaded;
}

} // namespace

LoadedModel loadModelFile(const std::string& path)
{
    std::string text;
    if (const Status status = readFileLimited(path, kMaxModelFileBytes, text); !status)
        return failure(path, status.message);
    return loadModelText(text, path);
}

LoadedModel loadModelText(std::string_view text, const std::string& displayName)
{
    const char first = firstSignificantCharacter(text);
    std::vector<LoadWarning> warnings;
    if (first == '<') {
        auto result = readPlcOpenModel(text, displayName, &warnings);
        return fromResult(std::move(result), ModelFormat::PlcOpen, std::move(warnings));
    }
    if (looksLikeNativeJson(text))
        return fromResult(loadNativeJson(text, displayName), ModelFormat::Native);
    if (looksLikeGGGeneratorJson(text)) {
        auto result = loadGGGeneratorJson(text, displayName, &warnings);
        return fromResult(std::move(result), ModelFormat::GGGenerator, std::move(warnings));
    }
    // A NUL byte is no blank: such a file is not empty.
    const bool nulFirst = first == '\0' && text.find('\0') != std::string_view::npos;
    if (first == '\0' && !nulFirst)
        return failure(displayName, "the file is empty");
    if (first == '{' || first == '[' || nulFirst) {
        // JSON of neither kind: the native loader says precisely what is wrong
        // (malformed JSON, a NUL byte, or the missing "format").
        return fromResult(loadNativeJson(text, displayName), ModelFormat::Native);
    }
    return failure(displayName, "not a model file: expected a GG Studio model (JSON with \"format\": \""
        + std::string(kNativeFormatName) + "\"), a GG-Generator JSON file or a GG Studio PLCopen XML file");
}

std::string unsupportedModelMessage(const Model& model, TemplateSupport support)
{
    if (model.templateKind() == TemplateKind::Gemma || support == TemplateSupport::GemmaAndPackML)
        return {};
    return "a PackML model (format 3.0); GG Studio does not handle PackML models here yet (ggstudio-cli new, "
           "convert, validate, export, st, simulate and verify do)";
}

LoadedModel loadSupportedModelFile(const std::string& path, TemplateSupport support)
{
    LoadedModel loaded = loadModelFile(path);
    if (!loaded.ok())
        return loaded;
    if (std::string message = unsupportedModelMessage(*loaded.model, support); !message.empty()) {
        LoadedModel refused = failure(path, std::move(message));
        refused.format = loaded.format;
        return refused;
    }
    return loaded;
}

Status saveModelFile(const Model& model, const std::string& path, ModelFormat format)
{
    switch (format) {
    case ModelFormat::Native:
        return writeFileAtomically(path, saveNativeJson(model));
    case ModelFormat::GGGenerator:
        if (model.templateKind() != TemplateKind::Gemma)
            return Status::failure("file.format", "GG-Generator JSON holds GEMMA models only; save a PackML model "
                                                  "as a GG Studio model file");
        return writeFileAtomically(path, saveGGGeneratorJson(model));
    case ModelFormat::PlcOpen:
        break;
    }
    return Status::failure("file.format", "PLCopen XML is written by the PLCopen export, not as a model file");
}

} // namespace core
