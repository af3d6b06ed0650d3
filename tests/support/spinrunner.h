#pragma once

// Runs SPIN on a Promela text, for the tests and the benchmarks that check
// the verifier against it (docs/verification.md, "SPIN cross-check"): spin
// and the C compiler once per model, in a fresh temporary folder removed
// afterwards; then pan as often as needed. Needs the Debian packages `spin`
// and `gcc` (CI installs both); a step that fails throws std::runtime_error
// with what spin, the compiler or the shell printed.

#include "core/verification/promela.h"

#include <filesystem>
#include <string>
#include <vector>

namespace spin {

// spin and gcc can be run.
bool available();

class CompiledPan {
public:
    // `compileFlags`: the tests compile pan.c with -O0 (their state spaces
    // take milliseconds, optimising pan.c takes seconds); the benchmarks
    // with core::kSpinCompile's -O2.
    // `generate`: spin's command (core::kSpinGenerate; "spin -o2 -o3 -a" keeps
    // the write-only variables in pan's state).
    CompiledPan(const std::string& promelaText, const std::string& name,
                const std::string& compileFlags = "-O0 -DSAFETY -DMEMLIM=512",
                const std::string& generate = core::kSpinGenerate);
    CompiledPan(const CompiledPan&) = delete;
    CompiledPan& operator=(const CompiledPan&) = delete;
    ~CompiledPan();

    // pan's output (core::readSpinReport says whether the search completed);
    // `environment` is put before the command ("GG_LIST=1").
    std::string run(const std::string& environment = {}, const std::string& arguments = "-m200000 -w20") const;

    // One run per start (GG_START), each stopped when it enters State
    // `until` (GG_UNTIL), in one shell: pan's outputs, in order. `depth` is
    // pan's stack limit (a search that needs more says so and is not
    // complete); a small one saves allocating kSpinRun's.
    std::vector<std::string> runFrom(const std::vector<std::string>& starts, int until, long long depth) const;

private:
    std::filesystem::path m_folder;
};

} // namespace spin
