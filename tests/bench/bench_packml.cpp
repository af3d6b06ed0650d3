#include "packmlfactory.h"

#include "core/templates/packml/packmlprogram.h"

#include <catch2/catch.hpp>

// Issue 34's PackML figures on its stress model (31 modes, eleven 40-step
// GRAFCETs shared by "same as"): what every engine reads first.
TEST_CASE("PackML program of the stress model", "[benchmark][packml]")
{
    const core::Model model = factory::packmlStressModel();
    BENCHMARK("build the PackML program")
    {
        return core::packml::buildPackmlProgram(model).instances.size();
    };
}
