// 2-rank MPI tests (run by ctest under mpirun -np 2): migrated genomes arrive intact on the next
// rank and join one migration later (no waiting for a neighbour less than an interval behind),
// replace its worst, bad bytes are refused, and async mode drains.
#include <gtest/gtest.h>

#include <mpi.h>

#include <chrono>
#include <thread>

#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "island/async_control.hpp"
#include "island/island_meeting.hpp"
#include "genome/families/tree_family.hpp"
#include "island/ring_migration.hpp"

namespace shapevo {
namespace {

const Grammar& spaceship() {
    static const Grammar g = loadGrammar(std::string(SHAPEVO_SOURCE_DIR) + "/grammars/spaceship.grammar");
    return g;
}

const TreeFamily& spaceshipFamily() {
    static const TreeFamily family(spaceship());
    return family;
}

/// The population rank `r` starts with: the same on every rank that builds it.
Population populationOf(int r, std::size_t n) {
    Population p;
    Rng rng(1000 + std::uint64_t(r));
    const GenomeLimits limits{60};
    for (std::size_t i = 0; i < n; ++i) {
        Chromosome c;
        const std::uint32_t length = 2 + rng.below(30);
        while (c.genes < length && grow(spaceship(), c, rng, limits)) {
        }
        p.individuals.push_back(c);
        p.fitness.push_back(double(i) + 0.25 * r);  // the last individuals are the best
    }
    return p;
}

class TwoRanks : public ::testing::Test {
protected:
    void SetUp() override {
        if (mpi.size() < 2) GTEST_SKIP() << "needs mpirun -np 2 or more";
    }
    static MpiSession& mpiRef();
    /// Ring migration settings: every `interval` generations an island's `count` best leave.
    static MigrationSettings every(std::uint32_t interval, std::uint32_t count, bool async = false) {
        MigrationSettings m;
        m.interval = interval;
        m.count = count;
        m.async = async;
        return m;
    }
    const MpiSession& mpi = mpiRef();
};

}  // namespace

// The session is created in main() (MPI_Init before any test).
MpiSession* gMpi = nullptr;
MpiSession& TwoRanks::mpiRef() { return *gMpi; }

namespace {

TEST_F(TwoRanks, BestGenomesArriveIntactOnTheNextRankOneMigrationLater) {
    RingMigration migration(mpi, every(5, 3), spaceshipFamily(), GenomeLimits{60});
    Population mine = populationOf(mpi.rank(), 20);
    const Population original = mine;
    migration.afterGeneration(mine, 4, mine.size());  // not a migration generation: nothing moves
    migration.afterGeneration(mine, 5, mine.size());  // my best leave; nothing has arrived to join yet
    EXPECT_EQ(migration.received(), 0u);
    for (std::size_t i = 0; i < 20; ++i) EXPECT_EQ(mine.individuals[i].words, original.individuals[i].words);
    // A checkpoint would hold the left neighbour's three best, received but not yet joined.
    const int left = (mpi.rank() + mpi.size() - 1) % mpi.size();
    const Population sender = populationOf(left, 20);
    ASSERT_EQ(migration.arrivals().size(), 3u);
    EXPECT_EQ(migration.arrivals().individuals[0].words, sender.individuals[19].words);
    migration.afterGeneration(mine, 10, mine.size());  // they join now
    EXPECT_EQ(migration.received(), 3u);
    EXPECT_EQ(migration.rejected(), 0u);
    // the sender's three best (indices 19, 18, 17) replaced my three worst (indices 0, 1, 2)
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(mine.individuals[std::size_t(k)].words, sender.individuals[std::size_t(19 - k)].words) << "slot " << k;
        EXPECT_EQ(mine.individuals[std::size_t(k)].genes, sender.individuals[std::size_t(19 - k)].genes);
        EXPECT_EQ(mine.fitness[std::size_t(k)], sender.fitness[std::size_t(19 - k)]);
    }
    for (std::size_t i = 3; i < 20; ++i) EXPECT_EQ(mine.individuals[i].words, original.individuals[i].words);
    migration.finish();  // the migrants of generation 10 are still in flight: taken and dropped
}

TEST_F(TwoRanks, ASyncIslandDoesNotWaitForANeighbourLessThanAnIntervalBehind) {
    RingMigration migration(mpi, every(5, 2), spaceshipFamily(), GenomeLimits{60});
    Population mine = populationOf(mpi.rank(), 10);
    MPI_Barrier(MPI_COMM_WORLD);
    const double waitedBefore = mpi.waitedSeconds();
    // Rank 0 is slow between its migrations; rank 1 reaches each one 100 ms earlier and must not
    // wait there, since what it takes up was sent a whole interval before.
    migration.afterGeneration(mine, 5, mine.size());
    if (mpi.rank() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    migration.afterGeneration(mine, 10, mine.size());
    EXPECT_EQ(migration.received(), 2u);
    if (mpi.rank() == 1) {
        EXPECT_LT(mpi.waitedSeconds() - waitedBefore, 0.05);
    }
    migration.finish();
}

TEST_F(TwoRanks, AsyncMigrationDeliversAndFinishesWithoutDeadlock) {
    RingMigration migration(mpi, every(1, 2, /*async=*/true), spaceshipFamily(), GenomeLimits{60});
    Population mine = populationOf(mpi.rank(), 10);
    for (std::uint32_t g = 1; g <= 50; ++g) migration.afterGeneration(mine, g, mine.size());
    migration.finish();
    EXPECT_EQ(migration.rejected(), 0u);
    // everything that arrived was a valid chromosome of the sender (checked on arrival)
    SUCCEED() << "received " << migration.received();
}

TEST_F(TwoRanks, AMeetingGivesEveryRankTheSameRowsAndCountsItsWaiting) {
    MeetingInput in;
    for (std::uint32_t g = 1; g <= 3; ++g) {
        GenerationStats s;
        s.generation = g;
        s.best = 0.1 * g + 0.01 * mpi.rank();  // rank 1 holds every best
        s.iou = 0.5 + 0.1 * mpi.rank();
        s.evaluations = 10 * g;
        in.rows.push_back(islandRow(s, {s.best, 0.0}));
    }
    in.signal = mpi.rank() == 1 ? 10 : 0;
    in.checkpointDue = mpi.rank() == 0;
    const double waitedBefore = mpi.waitedSeconds();
    if (mpi.rank() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(200));  // rank 1 waits
    const MeetingResult m = meet(mpi, in);
    ASSERT_EQ(m.rows.size(), 3u);
    for (std::uint32_t g = 1; g <= 3; ++g) {
        EXPECT_EQ(m.rows[g - 1].generation, g);
        EXPECT_DOUBLE_EQ(m.rows[g - 1].best, 0.1 * g + 0.01 * (mpi.size() - 1));
        EXPECT_EQ(m.rows[g - 1].evaluations, 10u * g * std::uint32_t(mpi.size()));
    }
    EXPECT_DOUBLE_EQ(m.rows[0].iou, 0.5 + 0.1 * (mpi.size() - 1));
    EXPECT_EQ(m.signal, 10);
    EXPECT_TRUE(m.checkpointDue);
    if (mpi.rank() == 1) {
        EXPECT_GT(mpi.waitedSeconds() - waitedBefore, 0.1);
    }
}

TEST_F(TwoRanks, AsyncStatusesReachRankZeroAndOrdersReachEveryRankWithoutWaiting) {
    AsyncControl control(mpi, 0.0);
    IslandStatus own;
    own.generation = 5 + mpi.rank();
    own.best = 0.25 * (mpi.rank() + 1);
    own.finished = 1;
    if (mpi.rank() != 0) {
        const auto start = std::chrono::steady_clock::now();
        control.report(own, true);
        std::optional<AsyncOrder> order;
        for (int k = 0; k < 20000 && !order; ++k) {
            order = control.poll();  // never blocks
            if (!order) std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        ASSERT_TRUE(order.has_value());
        EXPECT_EQ(order->kind, AsyncOrder::Stop);
        EXPECT_EQ(order->signal, 15);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 4.0);
    } else {
        for (int k = 0; k < 20000 && !control.heardFromAll(); ++k) {
            control.collect(own);
            if (!control.heardFromAll()) std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        ASSERT_TRUE(control.heardFromAll());
        EXPECT_EQ(control.newest(1).generation, 6.0);
        EXPECT_EQ(control.newest(1).best, 0.5);
        EXPECT_GE(control.ageSeconds(1), 0.0);
        control.order(AsyncOrder{AsyncOrder::Stop, 15});
    }
    control.finish();
}

TEST(Migration, CorruptMessagesAreRefused) {
    const GenomeLimits limits{60};
    const Population p = populationOf(0, 5);
    std::vector<std::uint32_t> words;
    packIndividuals(p, {4, 3}, words);
    std::vector<Chromosome> got;
    std::vector<double> fitness;
    ASSERT_EQ(unpackIndividuals(spaceshipFamily(), limits, words, got, fitness), "");
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0].words, p.individuals[4].words);
    auto truncated = words;
    truncated.pop_back();
    got.clear();
    EXPECT_NE(unpackIndividuals(spaceshipFamily(), limits, truncated, got, fitness), "");
    auto damaged = words;
    damaged[5] = 9999;  // the first gene's rule id
    got.clear();
    EXPECT_NE(unpackIndividuals(spaceshipFamily(), limits, damaged, got, fitness), "");
}

}  // namespace
}  // namespace shapevo

int main(int argc, char** argv) {
    shapevo::MpiSession mpi(argc, argv);
    shapevo::gMpi = &mpi;
    ::testing::InitGoogleTest(&argc, argv);
    // only rank 0 prints results; every rank runs every test
    if (mpi.rank() != 0) {
        auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
    }
    const int failed = RUN_ALL_TESTS();
    const bool allPassed = mpi.allTrue(failed == 0);
    return allPassed ? 0 : 1;
}
