#include "modelfactory.h"

#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"

#include <catch2/catch.hpp>

namespace {

std::size_t gemmaProgramText(const core::Model& model)
{
    const core::PlcProject project = core::buildPlcProject(model, core::Dialect::Iec);
    return core::formatPou(project.pous.front(), core::Dialect::Iec).size();
}

} // namespace

TEST_CASE("Structured Text of the realistic model (target <= 1 ms)", "[benchmark][codegen]")
{
    const core::Model model = factory::realisticModel();
    BENCHMARK("GEMMA program ST") { return gemmaProgramText(model); };
}

TEST_CASE("Structured Text of the stress model (target <= 10 ms)", "[benchmark][codegen]")
{
    const core::Model model = factory::stressModel();
    BENCHMARK("GEMMA program ST") { return gemmaProgramText(model); };
}

TEST_CASE("PLCopen XML of the realistic model (target <= 3 ms)", "[benchmark][codegen]")
{
    const core::Model model = factory::realisticModel();
    core::PlcOpenOptions options;
    options.now = [] { return std::string("2026-01-01T00:00:00"); };
    BENCHMARK("PLCopen XML, IEC dialect")
    {
        return core::writePlcOpenXml(core::buildPlcProject(model, core::Dialect::Iec), model, options).size();
    };
}
