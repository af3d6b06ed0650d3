// Writes PLCopen XML samples (IEC dialect) into the folder given as argument,
// for the schema-validation test (validate_plcopen.cmake): the template, the
// realistic model, the paper's case study, 200 seeded random models (every
// other one with random nested GRAFCETs) and the shipped drilling-cell example.

#include "modelfactory.h"
#include "samplemodels.h"

#include "core/formats/fileio.h"
#include "core/codegen/plcopenwriter.h"
#include "core/formats/modelfiles.h"
#include "core/codegen/stgenerator.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

namespace {

constexpr int kRandomModels = 200;

bool writeSample(const std::filesystem::path& folder, const std::string& name, const core::Model& model)
{
    core::PlcOpenOptions options;
    options.now = [] { return std::string("2026-11-21T10:00:00"); };
    const std::string xml = core::writePlcOpenXml(core::buildPlcProject(model, core::Dialect::Iec), model, options);
    const core::Status status = core::writeFileAtomically((folder / (name + ".xml")).string(), xml);
    if (!status)
        std::fprintf(stderr, "plcopen_samples: %s\n", status.message.c_str());
    return status.ok;
}

std::string randomName(int seed)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "random-%03d", seed);
    return buffer;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: plcopen_samples OUTPUT_FOLDER\n");
        return 2;
    }
    try {
        const std::filesystem::path folder(argv[1]);
        std::filesystem::create_directories(folder);
        bool ok = writeSample(folder, "template", core::Model());
        ok = writeSample(folder, "realistic", factory::realisticModel()) && ok;
        ok = writeSample(folder, "case-study", samples::caseStudyModel()) && ok;
        for (int seed = 0; seed < kRandomModels; ++seed) {
            core::Model model = samples::randomModel(static_cast<std::uint32_t>(seed));
            // Every other one with random nested GRAFCETs: their FBs must validate too.
            if (seed % 2 == 1)
                samples::addRandomNestedGrafcets(model, static_cast<std::uint32_t>(seed));
            ok = writeSample(folder, randomName(seed), model) && ok;
        }
        const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
        ok = example.model && writeSample(folder, "drilling-cell", *example.model) && ok;
        return ok ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "plcopen_samples: %s\n", error.what());
        return 1;
    }
}
