#pragma once

// The Capper of spec packml.md §6.6 (tests/core/data/packml-capper.json):
// Production with its GRAFCETs in Resetting and Execute, Manual with the four
// states that are never disabled. The PackML program, generator and
// simulator tests run it against the trace the spec gives.

#include "core/formats/fileio.h"
#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <variant>

namespace packmltests {

inline std::unique_ptr<core::Model> loadCapper()
{
    const std::filesystem::path file = std::filesystem::path(GGSTUDIO_TEST_DATA_DIR) / "packml-capper.json";
    std::string text;
    REQUIRE(core::readFileLimited(file.string(), 1 << 20, text));
    auto result = core::loadNativeJson(text, file.string());
    if (const auto* error = std::get_if<core::LoadError>(&result))
        FAIL("the Capper does not load: " << error->toString());
    return std::move(std::get<std::unique_ptr<core::Model>>(result));
}

} // namespace packmltests
