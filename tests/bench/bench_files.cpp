#include "modelfactory.h"

#include "core/nativeformat.h"

#include <catch2/catch.hpp>

#include <memory>
#include <variant>

TEST_CASE("Load + save the realistic model (target <= 2 ms)", "[benchmark][files]")
{
    const std::string text = core::saveNativeJson(factory::realisticModel());
    BENCHMARK("load + save native JSON")
    {
        auto loaded = core::loadNativeJson(text, "<bench>");
        return core::saveNativeJson(*std::get<std::unique_ptr<core::Model>>(loaded)).size();
    };
}
