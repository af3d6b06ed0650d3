#pragma once

// The native-format tests' two ways to load a text: expecting a model (the
// test fails with the loader's message otherwise), or expecting a refusal
// (the test fails if the text was accepted).

#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <variant>

namespace filetests {

inline std::unique_ptr<core::Model> loadOk(const std::string& text)
{
    auto result = core::loadNativeJson(text, "test.json");
    if (const auto* error = std::get_if<core::LoadError>(&result))
        FAIL("unexpected load error: " << error->toString());
    return std::move(std::get<std::unique_ptr<core::Model>>(result));
}

inline core::LoadError loadError(const std::string& text)
{
    auto result = core::loadNativeJson(text, "test.json");
    if (std::holds_alternative<std::unique_ptr<core::Model>>(result))
        FAIL("the file was accepted: " << text);
    return std::get<core::LoadError>(result);
}

} // namespace filetests
