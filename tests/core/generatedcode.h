#pragma once

// What the agreement tests feed the ST interpreter: a model's generated IEC
// code split as the interpreter reads it, and whether this build runs under
// the sanitizers (the tests then run a sample of their random models).

#include "core/codegen/stgenerator.h"

#include <string>
#include <vector>

namespace sttest {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

struct GeneratedCode {
    std::string program;                     // the PROGRAM
    std::string globals;                     // the VAR_GLOBAL block
    std::vector<std::string> functionBlocks; // every FUNCTION_BLOCK

    std::string all() const
    {
        std::string text = globals + "\n" + program;
        for (const std::string& fb : functionBlocks)
            text += "\n" + fb;
        return text;
    }
};

// GEMMA or PackML, IEC dialect.
inline GeneratedCode generateIec(const core::Model& model)
{
    const core::PlcProject project = core::buildPlcProject(model, core::Dialect::Iec);
    GeneratedCode generated;
    generated.globals = core::formatGlobals(project);
    for (const core::PlcPou& pou : project.pous) {
        if (pou.kind == core::PouKind::Program)
            generated.program = core::formatPou(pou, core::Dialect::Iec);
        else
            generated.functionBlocks.push_back(core::formatPou(pou, core::Dialect::Iec));
    }
    return generated;
}

} // namespace sttest
