// libFuzzer target: the GG-Generator importer on arbitrary bytes. Whatever
// imports must be a valid model that survives an export and a re-import.

#include "core/formats/gggeneratorformat.h"

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
    auto result = core::loadGGGeneratorJson(text, "fuzz.json");
    if (const auto* error = std::get_if<core::LoadError>(&result)) {
        expect(!error->toString().empty());
        return 0;
    }
    const core::Model& model = *std::get<std::unique_ptr<core::Model>>(result);
    expect(model.invariantViolations().empty());
    const std::string exported = core::saveGGGeneratorJson(model);
    auto reimported = core::loadGGGeneratorJson(exported, "exported.json");
    const auto* again = std::get_if<std::unique_ptr<core::Model>>(&reimported);
    expect(again != nullptr);
    expect((*again)->sameContent(model));
    expect(core::saveGGGeneratorJson(**again) == exported);
    return 0;
}
