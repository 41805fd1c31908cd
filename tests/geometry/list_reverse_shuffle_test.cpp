// reverse and shuffle (geometry/lists/ordering.hpp): reverse twice is the identity and reverses
// order by into order by descending; shuffle is a permutation, repeatable, changed by any bit of
// its seed, and uniform over the 24 orders of 4 entities (chi-square over 10,000 seeds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

#include "base/random.hpp"
#include "geometry/lists/ordering.hpp"

namespace shapevo::lists {
namespace list_reverse_shuffle_test {

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

}  // namespace list_reverse_shuffle_test
}  // namespace shapevo::lists
