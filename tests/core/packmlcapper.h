#pragma once

// The Capper of spec packml.md §6.6 (tests/core/data/packml-capper.json):
// Production with its GRAFCETs in Resetting and Execute, Manual with the four
// states that are never disabled. The PackML program, generator and
// simulator tests run it against the trace the spec gives.

#include "core/formats/fileio.h"
#include "core/formats/nativeformat.h"
#include "core/templates/packml/packmlprogram.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace packmltests {

inline std::string capperText()
{
    const std::filesystem::path file = std::filesystem::path(GGSTUDIO_TEST_DATA_DIR) / "packml-capper.json";
    std::string text;
    REQUIRE(core::readFileLimited(file.string(), 1 << 20, text));
    return text;
}

inline std::unique_ptr<core::Model> loadCapper()
{
    auto result = core::loadNativeJson(capperText(), "packml-capper.json");
    if (const auto* error = std::get_if<core::LoadError>(&result))
        FAIL("the Capper does not load: " << error->toString());
    return std::move(std::get<std::unique_ptr<core::Model>>(result));
}

// The transition on `command` from `source` in `mode`, for tests that build
// a program wrong on purpose.
inline core::packml::ModeTransition& transitionOf(core::packml::PackmlProgram& program, int mode,
                                                  core::packml::State source, core::packml::Command command)
{
    using namespace core::packml;
    ProgramMode& m = *std::find_if(program.modes.begin(), program.modes.end(), [&](const ProgramMode& x) { return x.number == mode; });
    ProgramState& s = *std::find_if(m.states.begin(), m.states.end(), [&](const ProgramState& x) { return x.state == source; });
    auto found = std::find_if(s.transitions.begin(), s.transitions.end(), [&](const ModeTransition& t) {
        return t.transition.trigger == Trigger::Command && t.transition.command == command;
    });
    REQUIRE(found != s.transitions.end());
    return *found;
}

// The Capper with pieces of its file text replaced, each the first after `after`.
struct Replacement {
    std::string from, to, after = {};
};

inline std::unique_ptr<core::Model> capperWith(const std::vector<Replacement>& replacements)
{
    std::string text = capperText();
    for (const Replacement& r : replacements) {
        const std::size_t at = text.find(r.from, text.find(r.after));
        REQUIRE(at != std::string::npos);
        text.replace(at, r.from.size(), r.to);
    }
    auto result = core::loadNativeJson(text, "capper-variant.json");
    if (const auto* error = std::get_if<core::LoadError>(&result))
        FAIL("the variant does not load: " << error->toString());
    return std::move(std::get<std::unique_ptr<core::Model>>(result));
}

} // namespace packmltests
