// Writes one of the benchmarks' factory models as a native model file, to
// open it in the editor or hand it to the command line (for example
// `ggstudio-cli verify MODEL --promela OUT.pml` to run SPIN on it by hand).
// Usage: dump_factory_model stress|nested-stress|case-study|series GRAFCETS BOOLS > model.ggstudio.json

#include "core/formats/nativeformat.h"
#include "modelfactory.h"

#include <iostream>
#include <string>

namespace {

int write(const core::Model& model)
{
    std::cout << core::saveNativeJson(model);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string name = argc > 1 ? argv[1] : "";
    if (name == "stress" && argc == 2)
        return write(factory::bothLayersStressModel());
    if (name == "nested-stress" && argc == 2)
        return write(factory::nestedStressModel());
    if (name == "case-study" && argc == 2)
        return write(factory::caseStudyModel());
    if (name == "series" && argc == 4)
        return write(factory::verificationSeriesModel(std::stoi(argv[2]), std::stoi(argv[3])));
    std::cerr << "usage: dump_factory_model stress|nested-stress|case-study|series GRAFCETS BOOLS\n";
    return 64;
}
