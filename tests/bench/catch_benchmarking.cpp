// Catch2's implementation with benchmarking, compiled once for both benchmark
// executables (Debian's Catch2WithMain is built without benchmarking).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "catchsession.h"

int runCatchSession(int argc, char* argv[])
{
    return Catch::Session().run(argc, argv);
}
