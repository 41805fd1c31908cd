// count / index and the amount filters (geometry/lists/amount.hpp): indices 0..n-1, the stated
// cases (10 entities from 2 take 3; beyond the size; empty), a plain index window on random
// lists, and the window per group (one door per house).
#include <gtest/gtest.h>

#include <vector>

#include "base/random.hpp"
#include "geometry/lists/amount.hpp"
#include "geometry/lists/grouping.hpp"

namespace shapevo::lists {
namespace list_amount_filter_test {

TEST(ListCount, IndicesAreZeroToNMinusOneInListOrderAndCountIsN) {
    std::vector<double> index(7, -1.0);
    writeIndices(index);
    EXPECT_EQ(index, (std::vector<double>{0, 1, 2, 3, 4, 5, 6}));
    EntityList list;
    list.clear(2);
    for (int i = 0; i < 5; ++i) list.append(Scope{}, std::vector<double>{9.0, 9.0});
    EXPECT_EQ(countInto(list, 1), 5u);
    for (std::uint32_t i = 0; i < 5; ++i) {
        EXPECT_EQ(list.attributes(i)[0], 9.0);
        EXPECT_EQ(list.attributes(i)[1], double(i));
    }
}

TEST(ListAmountFilter, TenEntitiesFromTwoTakeThree) {
    std::vector<std::uint32_t> kept, rest;
    amountFilter(10, 2, 3, kept, rest);
    EXPECT_EQ(kept, (std::vector<std::uint32_t>{2, 3, 4}));
    EXPECT_EQ(rest, (std::vector<std::uint32_t>{0, 1, 5, 6, 7, 8, 9}));
}

TEST(ListAmountFilter, AmountBeyondTheSizeKeepsAllRemainingAndAnEmptyListGivesNothing) {
    std::vector<std::uint32_t> kept, rest;
    amountFilter(10, 7, 100, kept, rest);
    EXPECT_EQ(kept, (std::vector<std::uint32_t>{7, 8, 9}));
    EXPECT_EQ(rest, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));
    amountFilter(10, 0, ~std::uint64_t(0), kept, rest);
    EXPECT_EQ(kept.size(), 10u);
    EXPECT_TRUE(rest.empty());
    amountFilter(10, 12, 3, kept, rest);
    EXPECT_TRUE(kept.empty());
    EXPECT_EQ(rest.size(), 10u);
    amountFilter(0, 2, 3, kept, rest);
    EXPECT_TRUE(kept.empty());
    EXPECT_TRUE(rest.empty());
}

TEST(ListAmountFilter, EqualsAPlainIndexWindowOnRandomLists) {
    Rng rng(5);
    std::vector<std::uint32_t> kept, rest;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(30), from = rng.below(35), amount = rng.below(35);
        amountFilter(n, from, amount, kept, rest);
        std::vector<std::uint32_t> k, r;
        for (std::uint32_t i = 0; i < n; ++i) (i >= from && i < from + amount ? k : r).push_back(i);
        ASSERT_EQ(kept, k);
        ASSERT_EQ(rest, r);
    }
}

TEST(ListAmountFilterByGroup, KeepsTheWindowOfEveryGroupInListOrder) {
    // Facades of 4 houses, interleaved; one door per house: the first facade of each house.
    const std::vector<double> house{0, 1, 0, 2, 1, 3, 3, 0, 2};
    Grouping g;
    ListWorkspace ws;
    groupBy(house, 1, g, ws);
    std::vector<std::uint32_t> kept, rest;
    amountFilterByGroup(g, 0, 1, kept, rest);
    EXPECT_EQ(kept, (std::vector<std::uint32_t>{0, 1, 3, 5}));
    EXPECT_EQ(rest, (std::vector<std::uint32_t>{2, 4, 6, 7, 8}));
    amountFilterByGroup(g, 1, 5, kept, rest);
    EXPECT_EQ(kept, (std::vector<std::uint32_t>{2, 4, 6, 7, 8}));
    EXPECT_EQ(rest, (std::vector<std::uint32_t>{0, 1, 3, 5}));
}

}  // namespace list_amount_filter_test
}  // namespace shapevo::lists
