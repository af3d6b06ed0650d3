#pragma once

// Runs the benchmarks the command line selects (catch_benchmarking.cpp): the
// benchmark executables' main() calls it once its own set-up is done.
int runCatchSession(int argc, char* argv[]);
