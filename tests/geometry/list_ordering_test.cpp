// The list orderings and counts of geometry/lists (ordering.hpp, amount.hpp) against plain
// brute-force references on seeded random lists: order by == std::stable_sort with the same keys
// (NaN last, ties in list order), swapping two keys changes the order as the reference predicts,
// reverse, shuffle (a permutation, repeatable, uniform by chi-square), count / index and the
// amount filter's cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <vector>

#include "base/random.hpp"
#include "geometry/lists/amount.hpp"
#include "geometry/lists/ordering.hpp"

namespace shapevo::lists {
namespace list_ordering_test {

/// Keys with many ties, some NaNs and some -0s.
double randomKey(Rng& rng) {
    const std::uint32_t r = rng.below(20);
    if (r == 0) return std::numeric_limits<double>::quiet_NaN();
    if (r == 1) return -0.0;
    return double(rng.below(5)) - 2.0;
}

/// The reference comparison, written out: key by key, NaN after every number, equal keys go on.
bool referenceLess(const std::vector<double>& keys, const std::vector<SortDirection>& dirs, std::uint32_t a, std::uint32_t b) {
    const std::size_t m = dirs.size();
    for (std::size_t k = 0; k < m; ++k) {
        const double x = keys[a * m + k], y = keys[b * m + k];
        if (std::isnan(x) && std::isnan(y)) continue;
        if (std::isnan(x)) return false;
        if (std::isnan(y)) return true;
        if (x == y) continue;
        return dirs[k] == SortDirection::Ascending ? x < y : x > y;
    }
    return false;
}

std::vector<std::uint32_t> referenceOrder(const std::vector<double>& keys, const std::vector<SortDirection>& dirs) {
    std::vector<std::uint32_t> order(keys.size() / dirs.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return referenceLess(keys, dirs, a, b); });
    return order;
}

/// The keys with columns k0 and k1 swapped.
std::vector<double> swapColumns(const std::vector<double>& keys, std::size_t m, std::size_t k0, std::size_t k1) {
    std::vector<double> out = keys;
    for (std::size_t i = 0; i < keys.size() / m; ++i) std::swap(out[i * m + k0], out[i * m + k1]);
    return out;
}


TEST(ListOrderBy, EqualsStableSortWithTheSameKeysOnRandomLists) {
    Rng rng(43);
    std::vector<std::uint32_t> order;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(60), m = 1 + rng.below(3);
        std::vector<double> keys(n * m);
        for (double& k : keys) k = randomKey(rng);
        std::vector<SortDirection> dirs(m);
        for (SortDirection& d : dirs) d = rng.below(2) ? SortDirection::Ascending : SortDirection::Descending;
        orderBy(keys, dirs, order);
        ASSERT_EQ(order, referenceOrder(keys, dirs)) << "list " << list;
    }
}

TEST(ListOrderBy, SwappingTwoKeysChangesTheOrderAsTheBruteForcePredicts) {
    Rng rng(7);
    std::vector<std::uint32_t> ab, ba;
    int changed = 0;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = 2 + rng.below(30);
        std::vector<double> keys(n * 2);
        for (double& k : keys) k = randomKey(rng);
        const std::vector<SortDirection> dirs{SortDirection::Ascending, SortDirection::Descending};
        const std::vector<SortDirection> swappedDirs{dirs[1], dirs[0]};
        const std::vector<double> swapped = swapColumns(keys, 2, 0, 1);
        orderBy(keys, dirs, ab);
        orderBy(swapped, swappedDirs, ba);
        ASSERT_EQ(ab, referenceOrder(keys, dirs));
        ASSERT_EQ(ba, referenceOrder(swapped, swappedDirs));
        changed += ab != ba;
    }
    EXPECT_GT(changed, 500);  // the key order matters on most lists
}

TEST(ListOrderBy, NaNKeysSortLastInBothDirectionsAndTiesKeepListOrder) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> keys{nan, 2.0, 1.0, nan, 2.0, -0.0, 0.0};
    std::vector<std::uint32_t> order;
    orderBy(keys, std::vector<SortDirection>{SortDirection::Ascending}, order);
    EXPECT_EQ(order, (std::vector<std::uint32_t>{5, 6, 2, 1, 4, 0, 3}));
    orderBy(keys, std::vector<SortDirection>{SortDirection::Descending}, order);
    EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 4, 2, 5, 6, 0, 3}));
    orderBy(std::vector<double>{}, std::vector<SortDirection>{SortDirection::Ascending}, order);
    EXPECT_TRUE(order.empty());
}

TEST(ListReverse, TwiceIsTheIdentityAndOfOrderByIsOrderByDescendingForDistinctKeys) {
    Rng rng(11);
    std::vector<std::uint32_t> up, down, twice;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(50);
        std::vector<double> keys(n);
        for (std::uint32_t i = 0; i < n; ++i) keys[i] = double(i) * 0.5 - 3.0;
        for (std::uint32_t i = n; i > 1; --i) std::swap(keys[i - 1], keys[rng.below(i)]);  // distinct keys, random order
        orderBy(keys, std::vector<SortDirection>{SortDirection::Ascending}, up);
        orderBy(keys, std::vector<SortDirection>{SortDirection::Descending}, down);
        twice = up;
        reverseOrder(up);
        ASSERT_EQ(up, down);
        reverseOrder(up);
        reverseOrder(up);
        reverseOrder(up);
        ASSERT_EQ(up, twice);
    }
}

TEST(ListShuffle, IsAPermutationAndTheSameSeedGivesTheSameOrder) {
    Rng rng(3);
    std::vector<std::uint32_t> a, b, c;
    int differs = 0, eligible = 0;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(40);
        const double u = rng.uniform();
        const std::uint64_t key = rng.next();
        shuffleOrder(n, u, key, a);
        shuffleOrder(n, u, key, b);
        ASSERT_EQ(a, b);
        std::vector<std::uint32_t> sorted = a;
        std::sort(sorted.begin(), sorted.end());
        std::vector<std::uint32_t> identity(n);
        std::iota(identity.begin(), identity.end(), 0u);
        ASSERT_EQ(sorted, identity);
        shuffleOrder(n, std::nextafter(u, 2.0), key, c);  // one bit of u more
        eligible += n >= 6;
        differs += n >= 6 && a != c;
    }
    EXPECT_GE(differs, eligible - eligible / 100);  // 720+ orders: a changed bit changes nearly all
}

TEST(ListShuffle, EveryPermutationOfFourIsAboutEquallyLikelyOver10000Seeds) {
    // Chi-square over the 24 permutations (23 degrees of freedom; 49.7 is the 0.1 % point), once with
    // u varying (key fixed) and once with the key varying (u fixed).
    for (const bool varyKey : {false, true}) {
        std::map<std::vector<std::uint32_t>, int> seen;
        std::vector<std::uint32_t> order;
        Rng rng(varyKey ? 17 : 19);
        const int seeds = 10000;
        for (int s = 0; s < seeds; ++s) {
            shuffleOrder(4, varyKey ? 0.25 : rng.uniform(), varyKey ? rng.next() : 12345u, order);
            ++seen[order];
        }
        ASSERT_EQ(seen.size(), 24u);
        const double expected = seeds / 24.0;
        double chi2 = 0.0;
        for (const auto& [perm, count] : seen) chi2 += (count - expected) * (count - expected) / expected;
        EXPECT_LT(chi2, 49.7) << (varyKey ? "key varies" : "u varies");
    }
}

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

}  // namespace list_ordering_test
}  // namespace shapevo::lists
