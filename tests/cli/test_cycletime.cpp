#include "cycletime.h"

#include <catch2/catch.hpp>

using cli::parseCycleTime;

TEST_CASE("Cycle times are read as engineers write task intervals", "[cli]")
{
    CHECK(parseCycleTime("20ms") == 20);
    CHECK(parseCycleTime("20") == 20);
    CHECK(parseCycleTime("T#20ms") == 20);
    CHECK(parseCycleTime("t#1s500ms") == 1500);
    CHECK(parseCycleTime("1.5s") == 1500);
    CHECK(parseCycleTime("2m") == 120000);
    CHECK(parseCycleTime("1h") == 3600000);
    CHECK(parseCycleTime("10MS") == 10);
}

TEST_CASE("Cycle times that are not durations are refused", "[cli]")
{
    CHECK_FALSE(parseCycleTime(""));
    CHECK_FALSE(parseCycleTime("T#"));
    CHECK_FALSE(parseCycleTime("fast"));
    CHECK_FALSE(parseCycleTime("-5ms"));
    CHECK_FALSE(parseCycleTime("1s500"));
    CHECK_FALSE(parseCycleTime("0.5ms"));
    CHECK_FALSE(parseCycleTime("20 ms"));
    CHECK_FALSE(parseCycleTime("99999999h"));
}
