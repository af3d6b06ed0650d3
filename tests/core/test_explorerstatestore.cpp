// The program explorer's compact storage (core/verification/statestore.h):
// every state stored decodes back to exactly its bytes, equal states share
// one index and only they do, and the edges of each state stay its own; the
// explorer on it finds the states and scans it found with one std::string
// per state in a std::unordered_map (issue 36).

#include "modelfactory.h"

#include "core/verification/programexplorer.h"
#include "core/verification/statestore.h"

#include <catch2/catch.hpp>

#include <map>
#include <random>
#include <string>
#include <vector>

namespace test_explorerstatestore {

using namespace core::explore;

namespace {

// A state as the explorer lays them out: a step index in two bytes, then
// mostly 0 and 1 bytes (steps, outputs, stored BOOLs) with, at `wide`
// places, any byte (TON counts, a machine's key).
std::string randomState(std::mt19937& random, std::size_t size, int onesPercent, std::size_t wide)
{
    std::string state(size, '\0');
    std::uniform_int_distribution<int> percent(0, 99), byte(0, 255);
    for (char& c : state)
        c = static_cast<char>(percent(random) < onesPercent ? 1 : 0);
    for (std::size_t i = 0; i < wide && i < size; ++i)
        state[(i * 7919) % size] = static_cast<char>(byte(random));
    return state;
}

} // namespace

TEST_CASE("Explorer state store: every shape of state decodes back to its bytes", "[explore][statestore]")
{
    std::mt19937 random(20261207);
    std::vector<std::string> states{"", std::string(1, '\0'), std::string(1, '\x01'), std::string(1, '\xFF'),
                                    std::string(10'000, '\0'), std::string(300, '\x01'), std::string(300, '\xFE')};
    std::string sparse(10'000, '\0'); // a GRAFCET of 10,000 steps, two active
    sparse[0] = 3;
    sparse[4'000] = 1;
    sparse[9'999] = 1;
    states.push_back(sparse);
    for (std::size_t size : {2u, 7u, 8u, 9u, 64u, 200u, 1'000u})
        for (int ones : {0, 5, 50, 100})
            for (std::size_t wide : {0u, 1u, 4u})
                states.push_back(randomState(random, size, ones, wide));
    std::string encoded, decoded;
    for (const std::string& state : states) {
        INFO("size " << state.size());
        encodeState(state, encoded);
        CHECK(decodeState(reinterpret_cast<const unsigned char*>(encoded.data()), decoded) == encoded.size());
        CHECK(decoded == state);
    }
    // Compact: the dense form for the states of the series, the sparse one for the long GRAFCET.
    encodeState(randomState(random, 64, 30, 2), encoded);
    CHECK(encoded.size() <= 22);
    encodeState(sparse, encoded);
    CHECK(encoded.size() <= 12);
}

TEST_CASE("Explorer state store: one index per distinct state, each decoded back", "[explore][statestore]")
{
    std::mt19937 random(7);
    StateStore store;
    std::map<std::string, std::uint32_t> expected;
    std::vector<std::string> byIndex;
    std::uniform_int_distribution<int> sizes(0, 3);
    for (int i = 0; i < 60'000; ++i) {
        // Many repeats (few ones in short states), some long states.
        const std::size_t size = std::vector<std::size_t>{3, 12, 40, 3'000}[static_cast<std::size_t>(sizes(random))];
        const std::string state = randomState(random, size, size == 3'000 ? 1 : 20, i % 3);
        const auto [index, added] = store.insert(state);
        const auto known = expected.find(state);
        if (known == expected.end()) {
            REQUIRE(added);
            REQUIRE(index == byIndex.size());
            expected.emplace(state, index);
            byIndex.push_back(state);
        } else {
            REQUIRE_FALSE(added);
            REQUIRE(index == known->second);
        }
    }
    REQUIRE(store.size() == byIndex.size());
    CHECK(store.size() < 60'000); // repeats were found again
    std::string decoded;
    for (std::size_t i = 0; i < byIndex.size(); ++i) {
        store.decodeInto(i, decoded);
        REQUIRE(decoded == byIndex[i]);
        REQUIRE(store.find(byIndex[i]) == static_cast<std::int64_t>(i));
    }
    CHECK(store.find(std::string(5, '\x07')) == -1);
    CHECK(store.at(0) == byIndex[0]);
    CHECK(store.bytes() > 0);
}

TEST_CASE("Explorer state store: each state's edges stay its own across blocks", "[explore][statestore]")
{
    EdgeStore edges;
    std::vector<std::vector<std::uint32_t>> expected;
    std::mt19937 random(3);
    std::uniform_int_distribution<int> degree(0, 40);
    for (std::size_t s = 0; s < 3'000; ++s) {
        edges.addState();
        expected.emplace_back();
        const int count = s == 1'500 ? 20'000 : degree(random); // one state with more than a block
        for (int k = 0; k < count; ++k) {
            StateEdge edge;
            edge.to = static_cast<std::uint32_t>(s * 31 + static_cast<std::size_t>(k));
            edge.fired = k % 5 - 1;
            edge.completeTrue = k % 2;
            edge.entersD1 = k % 3 == 0 ? 1 : 0;
            edges.add(s, edge);
            expected.back().push_back(edge.to);
        }
    }
    std::size_t total = 0;
    for (std::size_t s = 0; s < expected.size(); ++s) {
        const std::span<const StateEdge> of = edges.of(s);
        REQUIRE(of.size() == expected[s].size());
        for (std::size_t k = 0; k < of.size(); ++k) {
            REQUIRE(of[k].to == expected[s][k]);
            REQUIRE(of[k].fired == static_cast<int>(k % 5) - 1);
            REQUIRE(of[k].completeTrue == k % 2);
            REQUIRE(of[k].entersD1 == (k % 3 == 0 ? 1u : 0u));
        }
        total += of.size();
    }
    CHECK(edges.edges() == total);
    CHECK(sizeof(StateEdge) == 8);
}

TEST_CASE("Explorer state store: the explorer finds the states and scans it found before", "[explore][statestore]")
{
    // Counted with the former storage (one std::string per state in a
    // std::unordered_map, a std::vector of edges per state), 2026-12-07.
    struct Case {
        int grafcets, bools;
        std::size_t states, scans;
    };
    for (const Case& c : {Case{2, 10, 479, 2682}, Case{4, 10, 2151, 12303}}) {
        INFO(c.grafcets << " GRAFCETs, " << c.bools << " BOOLs");
        Options options;
        options.hideWriteOnlyVariables = false; // as the former storage was measured: every stored BOOL kept
        ProgramExplorer explorer(factory::verificationSeriesModel(c.grafcets, c.bools), options);
        const Exploration& e = explorer.run();
        REQUIRE(e.exhaustive);
        CHECK(e.states == c.states);
        CHECK(e.scans == c.scans);
    }
}

} // namespace test_explorerstatestore
