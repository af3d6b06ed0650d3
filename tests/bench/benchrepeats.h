#pragma once

#include <cstdlib>

// How many times a benchmark repeats the runs whose figure it prints (best
// of three, ten runs averaged...): `full` normally, once in the test suite's
// smoke pass (bench.smoke sets GGSTUDIO_BENCH_SMOKE), which checks that the
// benchmarks build and run, not what they measure, and must stay quick under
// the sanitizers.
inline bool benchSmokeRun()
{
    return std::getenv("GGSTUDIO_BENCH_SMOKE") != nullptr;
}

inline int benchRepeats(int full)
{
    return benchSmokeRun() ? 1 : full;
}

// pan's compile flags: -O2 as core::kSpinCompile for the timed runs; -O0 in
// the smoke pass, which times nothing and where compiling pan.c at -O2 took
// most of the pass.
inline const char* benchPanCompileFlags()
{
    return benchSmokeRun() ? "-O0 -DSAFETY -DMEMLIM=1024" : "-O2 -DSAFETY -DMEMLIM=1024";
}
