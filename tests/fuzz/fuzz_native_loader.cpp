// libFuzzer target: the native model loader on arbitrary bytes. Besides
// crashes and sanitizer reports, it checks that whatever loads is a valid
// model that saves and reloads unchanged, byte for byte.

#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void expect(bool condition)
{
    if (!condition)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto result = core::loadNativeJson(text, "fuzz.json");
    if (const auto* error = std::get_if<core::LoadError>(&result)) {
        expect(!error->toString().empty());
    } else {
        const core::Model& model = *std::get<std::unique_ptr<core::Model>>(result);
        expect(model.invariantViolations().empty());
        const std::string saved = core::saveNativeJson(model);
        auto reloaded = core::loadNativeJson(saved, "saved.json");
        const auto* again = std::get_if<std::unique_ptr<core::Model>>(&reloaded);
        expect(again != nullptr);
        expect((*again)->sameContent(model));
        expect(core::saveNativeJson(**again) == saved);
    }
    // Format detection and dispatch must cope with anything as well.
    const core::LoadedModel detected = core::loadModelText(text, "fuzz");
    expect(detected.ok() || !detected.error.message.empty());
    return 0;
}
