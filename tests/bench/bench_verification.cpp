// Verification (core/verification.h): the realistic model (budget 50 ms) and
// the verification stress model (40 BOOL variables, a token on every eligible
// variable: 2^27 token configurations in F1 alone; budget 1 s).

#include "core/verification.h"

#include "modelfactory.h"

#include <catch2/catch.hpp>

TEST_CASE("Verification", "[bench][verification]")
{
    const core::Model realistic = factory::realisticModel();
    const core::Model stress = factory::verificationStressModel();
    REQUIRE_FALSE(core::verifyModel(realistic).violated());
    REQUIRE(core::verifyModel(stress).exhaustive);

    BENCHMARK("verify realistic model") { return core::verifyModel(realistic).findings.size(); };
    BENCHMARK("verify stress model") { return core::verifyModel(stress).findings.size(); };
}
