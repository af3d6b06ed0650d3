#include "modelfactory.h"

#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <variant>

namespace test_property {

using namespace core;

TEST_CASE("Random edit sequences keep every invariant and survive save and open", "[property]")
{
    std::mt19937 random(20261121);
    int acceptedTotal = 0;
    for (int sequence = 0; sequence < 1000; ++sequence) {
        Model model;
        const int length = std::uniform_int_distribution<int>(1, 40)(random);
        acceptedTotal += factory::applyRandomEdits(model, random, length);
        INFO("sequence " << sequence);
        const auto violations = model.invariantViolations();
        REQUIRE(violations.empty());

        const std::string saved = saveNativeJson(model);
        auto loaded = loadNativeJson(saved, "<property>");
        REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
        const Model& reopened = *std::get<std::unique_ptr<Model>>(loaded);
        REQUIRE(reopened.sameContent(model));
        REQUIRE(saveNativeJson(reopened) == saved);
    }
    // Most operations must have been accepted, or the test would prove little.
    CHECK(acceptedTotal > 10000);
}

TEST_CASE("Refused random edits leave the model unchanged", "[property]")
{
    std::mt19937 random(7);
    Model model;
    for (int i = 0; i < 2000; ++i) {
        Model before(model);
        const auto revision = model.revision();
        if (factory::applyRandomEdits(model, random, 1) == 0) {
            INFO("edit " << i);
            REQUIRE(model.sameContent(before));
            REQUIRE(model.revision() == revision);
        }
    }
}

} // namespace test_property
