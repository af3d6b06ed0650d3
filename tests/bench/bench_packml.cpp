#include "benchrepeats.h"
#include "packmlfactory.h"

#include "core/checks/checks.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlsimulator.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <stdexcept>

// Issue 34's PackML figures on its stress model (31 modes, eleven 40-step
// GRAFCETs shared by "same as") and on the shipped example.

TEST_CASE("PackML program of the stress model", "[benchmark][packml]")
{
    const core::Model model = factory::packmlStressModel();
    BENCHMARK("build the PackML program")
    {
        return core::packml::buildPackmlProgram(model).instances.size();
    };
}

TEST_CASE("PackML: re-check after a command-condition edit, stress model (target <= 1 ms)", "[benchmark][packml]")
{
    core::Model model = factory::packmlStressModel();
    bool toggle = false;
    BENCHMARK("set the Hold condition + re-check")
    {
        toggle = !toggle;
        (void)model.setCommandCondition(core::packml::Command::Hold, toggle ? "Cmd_Hold AND In1" : "Cmd_Hold");
        return core::checkModel(model).size();
    };
}

TEST_CASE("PackML: Structured Text of the whole program, stress model (target <= 2 ms)", "[benchmark][packml]")
{
    const core::Model model = factory::packmlStressModel();
    BENCHMARK("ST of the whole PackML program")
    {
        return core::formatSingleFileIec(core::buildPlcProject(model, core::Dialect::Iec)).size();
    };
}

TEST_CASE("PackML: simulation speed, shipped example (target >= 1,000,000 scans/s)", "[benchmark][packml]")
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");
    if (!loaded.ok())
        throw std::runtime_error("cannot load the bottle filler");
    core::packml::PackmlSimulator simulator(*loaded.model);
    (void)simulator.setInput("Cmd_Reset", true);
    BENCHMARK("1,000 scans of the bottle filler")
    {
        for (int i = 0; i < 1000; ++i)
            (void)simulator.scan();
        return simulator.scanCount();
    };
}

// Default options (the 4 s time limit): the figure is the time to a verdict,
// the time limit itself while the exploration is not exhaustive (GV100).
TEST_CASE("PackML: verification of the shipped example (target <= 1 s)", "[benchmark][packml]")
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");
    if (!loaded.ok())
        throw std::runtime_error("cannot load the bottle filler");
    // The smoke pass runs it once: Catch2's estimate and sample run it twice.
    if (benchSmokeRun()) {
        if (core::verifyModel(*loaded.model).configurations == 0)
            throw std::runtime_error("the bottle filler's verification reached no configuration");
        return;
    }
    BENCHMARK("verify the bottle filler")
    {
        return core::verifyModel(*loaded.model).configurations;
    };
}
