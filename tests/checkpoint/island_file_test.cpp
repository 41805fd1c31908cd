// Island and run files round trip bit for bit; the writer refuses states it could not read back.
#include <bit>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "checkpoint_test_util.hpp"
#include "base/input_error.hpp"
#include "checkpoint/island_codec.hpp"

namespace shapevo {
namespace {

using test::makeIsland;
using test::spaceshipFamily;

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

void expectSameCurve(const std::vector<GenerationStats>& a, const std::vector<GenerationStats>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].generation, b[i].generation) << "row " << i;
        EXPECT_EQ(a[i].evaluations, b[i].evaluations) << "row " << i;
        EXPECT_EQ(bits(a[i].seconds), bits(b[i].seconds)) << "row " << i;
        EXPECT_EQ(bits(a[i].best), bits(b[i].best)) << "row " << i;
        EXPECT_EQ(bits(a[i].mean), bits(b[i].mean)) << "row " << i;
        EXPECT_EQ(bits(a[i].std), bits(b[i].std)) << "row " << i;
        EXPECT_EQ(bits(a[i].iou), bits(b[i].iou)) << "row " << i;
    }
}

void expectSamePopulation(const Population& a, const Population& b) {
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.fitness.size(), b.fitness.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.individuals[i].genes, b.individuals[i].genes) << "individual " << i;
        EXPECT_EQ(a.individuals[i].words, b.individuals[i].words) << "individual " << i;
        EXPECT_EQ(bits(a.fitness[i]), bits(b.fitness[i])) << "individual " << i;
    }
}

void expectSameIsland(const IslandState& a, const IslandState& b) {
    EXPECT_EQ(a.rank, b.rank);
    EXPECT_EQ(a.generation, b.generation);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(a.rng, b.rng);
    expectSamePopulation(a.population, b.population);
    expectSamePopulation(a.arrivals, b.arrivals);
    expectSameCurve(a.curve, b.curve);
}

TEST(CheckpointIslandFile, RoundTripOfGrownSpaceshipPopulationIsBitIdentical) {
    test::TempDir dir;
    const IslandState s = makeIsland(3, 40, 7);
    std::size_t words = 0;
    for (const Chromosome& c : s.population.individuals) words += c.words.size();
    ASSERT_GT(words, 200u);  // a real population, not a handful of roots
    writeIslandFile(dir.file("island-0003.h5"), s);
    expectSameIsland(s, readIslandFile(dir.file("island-0003.h5"), spaceshipFamily(), test::kLimits));
}

// Sync islands complete each exchange one migration late: the migrants received but not yet
// joined are part of the state, stored and validated like the population.
TEST(CheckpointIslandFile, MigrantsWaitingToJoinRoundTripAndAreValidatedLikeThePopulation) {
    test::TempDir dir;
    IslandState s = makeIsland(1, 30, 4);
    s.arrivals = makeIsland(6, 5).population;
    writeIslandFile(dir.file("island-0001.h5"), s);
    const IslandState back = readIslandFile(dir.file("island-0001.h5"), spaceshipFamily(), test::kLimits);
    ASSERT_EQ(back.arrivals.size(), 5u);
    expectSameIsland(s, back);

    IslandBytes bytes = encodeIsland(s);
    bytes.arrivalGeneCounts[0] = 0xff;  // the first migrant claims 255 genes, over the limit of 60
    try {
        decodeIsland(bytes.view(), spaceshipFamily(), test::kLimits, "x.h5");
        FAIL() << "a migrant over the gene limit was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/migrants/gene_counts"), std::string::npos) << e.what();
    }
    bytes = encodeIsland(s);
    bytes.arrivalOffsets.resize(bytes.arrivalOffsets.size() - 8);  // one offset short
    EXPECT_THROW(decodeIsland(bytes.view(), spaceshipFamily(), test::kLimits, "x.h5"), InputError);
}

TEST(CheckpointIslandFile, EmptyPopulationAndEmptyCurveRoundTrip) {
    test::TempDir dir;
    IslandState s;
    s.rank = 0;
    s.rng = {1, 2, 3, 4};
    writeIslandFile(dir.file("island-0000.h5"), s);
    expectSameIsland(s, readIslandFile(dir.file("island-0000.h5"), spaceshipFamily(), test::kLimits));
}

TEST(CheckpointIslandFile, SameStateGivesByteIdenticalFiles) {
    test::TempDir dir;
    writeIslandFile(dir.file("a.h5"), makeIsland(1));
    writeIslandFile(dir.file("b.h5"), makeIsland(1));
    EXPECT_EQ(test::fileBytes(dir.file("a.h5")), test::fileBytes(dir.file("b.h5")));
}

TEST(CheckpointIslandFile, WriterRefusesStatesThatCouldNotBeReadBack) {
    test::TempDir dir;
    IslandState fewer = makeIsland(0, 4);
    fewer.population.fitness.pop_back();
    EXPECT_THROW(writeIslandFile(dir.file("a.h5"), fewer), std::invalid_argument);
    IslandState nan = makeIsland(0, 4);
    nan.population.fitness[2] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(writeIslandFile(dir.file("b.h5"), nan), std::invalid_argument);
}

TEST(CheckpointIslandFile, MissingFileIsAnInputErrorNamingIt) {
    test::TempDir dir;
    try {
        readIslandFile(dir.file("island-0009.h5"), spaceshipFamily(), test::kLimits);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.file("island-0009.h5"));
    }
}

TEST(CheckpointRunFile, RoundTripKeepsEveryField) {
    test::TempDir dir;
    const RunMetadata m = test::makeRun(4, 9);
    writeRunMetadata(dir.file("run.h5"), m);
    const RunMetadata r = readRunMetadata(dir.file("run.h5"));
    EXPECT_EQ(r.schemaVersion, kCheckpointSchemaVersion);
    EXPECT_EQ(r.seed, m.seed);
    EXPECT_EQ(r.generation, m.generation);
    EXPECT_EQ(r.ranks, m.ranks);
    EXPECT_EQ(bits(r.wallSeconds), bits(m.wallSeconds));
    EXPECT_EQ(r.targetHash, m.targetHash);
    EXPECT_EQ(r.name, m.name);
    EXPECT_EQ(r.configPath, m.configPath);
    EXPECT_EQ(r.configText, m.configText);
    EXPECT_EQ(r.grammarPath, m.grammarPath);
    EXPECT_EQ(r.grammarText, m.grammarText);
    expectSameCurve(r.curve, m.curve);
}

TEST(CheckpointRunFile, EmptyTextsAndUtf8RoundTrip) {
    test::TempDir dir;
    RunMetadata m;
    m.name = "r\xc3\xa9sum\xc3\xa9";  // UTF-8
    writeRunMetadata(dir.file("run.h5"), m);
    const RunMetadata r = readRunMetadata(dir.file("run.h5"));
    EXPECT_EQ(r.name, m.name);
    EXPECT_EQ(r.configText, "");
    EXPECT_EQ(r.grammarPath, "");
    EXPECT_TRUE(r.curve.empty());
}

}  // namespace
}  // namespace shapevo
