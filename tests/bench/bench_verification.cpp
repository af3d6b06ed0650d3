// Verification (core/verification/verification.h): the realistic model (budget 50 ms) and
// the verification stress model (40 BOOL variables, a token on every eligible
// variable: 2^27 token configurations in F1 alone; budget 1 s); and the
// hostile shapes of issue 15, each within the default budget of the command
// line and the editor (5 s and 1 GiB in all): 12 INT comparisons per
// condition, 24 mixed operands per condition, and two conditions of about
// 5,000 characters (which end with GV100 findings naming them).

#include "core/verification/verification.h"

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

TEST_CASE("Verification of comparison-heavy models", "[bench][verification]")
{
    const core::Model comparisons = factory::comparisonVerificationModel(12, false);
    const core::Model mixed = factory::comparisonVerificationModel(24, true);
    const core::Model huge = factory::hugeConditionVerificationModel();
    // Whether the time budget suffices depends on the build (a sanitizer
    // build is many times slower): the tests check the results, not this.

    BENCHMARK("verify 12 INT comparisons per condition") { return core::verifyModel(comparisons).findings.size(); };
    BENCHMARK("verify 24 mixed operands per condition") { return core::verifyModel(mixed).findings.size(); };
    BENCHMARK("verify 5,000-character conditions") { return core::verifyModel(huge).findings.size(); };
}
