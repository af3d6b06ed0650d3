// Issue 36: the verifier against SPIN on a growing series
// (factory::verificationSeriesModel: 2, 4, 8, 16 nested GRAFCETs with
// three-way parallel sections and 10 stored BOOLs, then 16 with 20 and 40)
// and on the both-layers stress model ("stress"), side by side in one run: for each model GG
// Studio's program states, time (best of three core::verifyModel, no time
// limit, exhaustive required) and peak heap (live bytes counted by
// allocationcounter.cpp during one more run, above what was live before it),
// and SPIN's pan on the same model exported (core::buildProgramPromela,
// compiled once as core::kSpinCompile says): states stored, time (best of
// three pan.run(), the process start included) and the memory pan reports.
// A line per model, then the same as CSV (`series-csv,...`), which
// docs/plots/series.py turns into docs/plots/series.svg. Nothing asserts a
// time. The smoke pass runs the smallest size once; GGSTUDIO_SERIES_SIZES
// (labels, comma-separated) chooses the sizes.

#include "core/verification/promelaprogram.h"
#include "core/verification/verification.h"

#include "allocationcounter.h"
#include "benchrepeats.h"
#include "catchsession.h"
#include "modelfactory.h"
#include "spinrunner.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct SeriesModel {
    std::string label;
    int grafcets = 0; // 0: the both-layers stress model
    int bools = 0;
};

double bestMilliseconds(const std::function<void()>& work)
{
    double fastest = 1e300;
    for (int i = 0; i < benchRepeats(3); ++i) {
        const auto start = std::chrono::steady_clock::now();
        work();
        fastest = std::min(fastest,
                           std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return fastest;
}

std::string fixed(double value, int decimals)
{
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// Hidden: as both tools run by default (write-only variables out of the
// state). Kept: the explorer with hideWriteOnlyVariables off, pan generated
// with spin -o2 (write-only variables kept).
enum class Memories { Hidden, Kept };

// One line printed for the model in that mode; its CSV row returned.
std::string measure(const SeriesModel& size, const core::Model& model, Memories memories, bool withSpin)
{
    const bool kept = memories == Memories::Kept;
    core::VerificationOptions unlimited;
    unlimited.timeLimit = std::chrono::milliseconds(0);
    unlimited.hideWriteOnlyVariables = !kept;
    const std::size_t before = allocations::live();
    allocations::resetPeak();
    const core::VerificationResult counted = core::verifyModel(model, unlimited);
    const double peakBytes = static_cast<double>(allocations::peak() - before);
    REQUIRE(counted.exhaustive);
    REQUIRE(counted.programStates > 0);
    const double ours = bestMilliseconds([&] { (void)core::verifyModel(model, unlimited); });
    const double bytesPerState = peakBytes / static_cast<double>(counted.programStates);

    const std::string mode = kept ? "kept" : "hidden";
    std::string line = size.label + " (write-only memories " + mode + "): GG Studio "
        + std::to_string(counted.programStates) + " states, " + fixed(ours, 1) + " ms, peak heap "
        + fixed(peakBytes / 1e6, 2) + " MB (" + fixed(bytesPerState, 0) + " bytes per state)";
    std::string row = "series-csv," + size.label + "," + mode + "," + std::to_string(size.grafcets) + ","
        + std::to_string(size.bools) + "," + std::to_string(counted.programStates) + "," + fixed(ours, 2) + ","
        + fixed(peakBytes, 0);
    if (withSpin) {
        const core::PromelaModel promela = core::buildProgramPromela(model);
        const spin::CompiledPan pan(promela.text, "bench-series", benchPanCompileFlags(),
                                    kept ? "spin -o2 -o3 -a" : core::kSpinGenerate);
        // kSpinRun's stack first; ten times deeper only when pan says it is too small
        // (allocating the deeper stack alone takes pan about 0.1 s).
        std::string arguments = "-m200000 -w20";
        core::SpinReport report = core::readSpinReport(pan.run({}, arguments));
        if (!report.complete) {
            arguments = "-m2000000 -w22";
            report = core::readSpinReport(pan.run({}, arguments));
        }
        INFO(report.problem);
        REQUIRE(report.complete);
        const double theirs = bestMilliseconds([&] { (void)pan.run({}, arguments); });
        line += "; SPIN's pan " + std::to_string(report.statesStored) + " states, " + fixed(theirs, 1)
            + " ms, memory " + fixed(report.totalMemoryMb, 1) + " MB in all (" + fixed(report.stateMemoryMb, 2)
            + " MB for states); GG Studio / SPIN time = " + fixed(ours / theirs, 3);
        row += "," + std::to_string(report.statesStored) + "," + fixed(theirs, 2) + ","
            + fixed(report.totalMemoryMb, 3) + "," + fixed(report.stateMemoryMb, 3);
    } else {
        row += ",,,,";
    }
    std::cout << line << "\n" << std::flush;
    return row;
}

} // namespace

TEST_CASE("Verification series against SPIN", "[bench][verification][series]")
{
    // Nested GRAFCETs x stored BOOLs: the nested layer grows, then the stored BOOLs.
    // The smoke pass (under the sanitizers in CI) only checks that it runs: the smallest size.
    std::vector<SeriesModel> models{{"2x10", 2, 10}};
    if (!benchSmokeRun()) {
        models.insert(models.end(), {{"4x10", 4, 10},
                                     {"8x10", 8, 10},
                                     {"16x10", 16, 10},
                                     {"16x20", 16, 20},
                                     {"16x40", 16, 40},
                                     {"stress", 0, 20}});
    }
    // GGSTUDIO_SERIES_SIZES=2x10,4x10,stress runs only those (pan.c of the 16x
    // sizes takes gcc -O2 a quarter of an hour and more).
    if (const char* only = std::getenv("GGSTUDIO_SERIES_SIZES")) {
        const std::string wanted = std::string(",") + only + ",";
        std::erase_if(models, [&](const SeriesModel& m) { return wanted.find("," + m.label + ",") == std::string::npos; });
    }
    const bool withSpin = spin::available();
    if (!withSpin)
        std::cout << "verification series: spin or gcc not found, GG Studio only\n";
    std::vector<std::string> csv{"series-csv,label,memories,grafcets,bools,gg_states,gg_ms,gg_peak_bytes,pan_states,"
                                 "pan_ms,pan_total_mb,pan_state_mb"};
    for (const SeriesModel& size : models) {
        INFO(size.label);
        const core::Model model
            = size.grafcets > 0 ? factory::verificationSeriesModel(size.grafcets, size.bools) : factory::bothLayersStressModel();
        csv.push_back(measure(size, model, Memories::Hidden, withSpin));
        // Both keeping the memories nothing reads (more states, the same
        // findings): up to 8x10, as pan.c of 16 GRAFCETs takes too long to compile.
        if (!benchSmokeRun() && size.grafcets <= 8)
            csv.push_back(measure(size, model, Memories::Kept, withSpin));
    }
    for (const std::string& row : csv)
        std::cout << row << "\n";
}

// Issue 36's other figure: issue 32's unstable GRAFCET of 10,000 steps
// (factory::unstableGrafcetModel), where a state holds the situation of
// 10,000 steps. Minutes, not seconds: hidden, run with
// ./build/tests/bench/series_benchmarks "[series10k]".
TEST_CASE("Verification of a 10,000-step GRAFCET: memory per state", "[.][bench][series10k]")
{
    const core::Model model = factory::unstableGrafcetModel(10'000);
    core::VerificationOptions unlimited;
    unlimited.timeLimit = std::chrono::milliseconds(0);
    const std::size_t before = allocations::live();
    allocations::resetPeak();
    const auto start = std::chrono::steady_clock::now();
    const core::VerificationResult result = core::verifyModel(model, unlimited);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const double peakBytes = static_cast<double>(allocations::peak() - before);
    REQUIRE(result.exhaustive);
    std::cout << "10,000-step GRAFCET: " << result.programStates << " states, " << fixed(ms, 0) << " ms, peak heap "
              << fixed(peakBytes / 1e6, 1) << " MB ("
              << fixed(peakBytes / static_cast<double>(result.programStates), 0) << " bytes per state)\n";
}

int main(int argc, char* argv[])
{
    return runCatchSession(argc, argv);
}
