// order by (geometry/lists/ordering.hpp) against std::stable_sort with the same keys written out
// in the test, on 1,000 seeded random lists with ties, NaNs and -0s: equal orders, swapping two
// keys changes the order as the reference predicts, NaN last in both directions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "base/random.hpp"
#include "geometry/lists/ordering.hpp"

namespace shapevo::lists {
namespace list_order_by_test {

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

}  // namespace list_order_by_test
}  // namespace shapevo::lists
