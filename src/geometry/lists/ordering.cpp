// order by, reverse, shuffle (ordering.hpp). order by uses std::sort with the list position as
// the last key: a strict total order, so the result is the stable order without std::stable_sort's
// temporary buffer (which allocates).
#include "geometry/lists/ordering.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "base/random.hpp"

namespace shapevo::lists {

int compareKey(double a, double b, SortDirection direction) {
    const bool nanA = std::isnan(a), nanB = std::isnan(b);
    if (nanA || nanB) return nanA == nanB ? 0 : (nanA ? 1 : -1);  // NaN last in both directions
    if (a == b) return 0;
    const bool before = direction == SortDirection::Ascending ? a < b : a > b;
    return before ? -1 : 1;
}

void identityOrder(std::uint32_t n, std::vector<std::uint32_t>& order) {
    order.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
}

void orderBy(std::span<const double> keys, std::span<const SortDirection> directions, std::vector<std::uint32_t>& order) {
    const std::size_t keyCount = directions.size();
    const std::uint32_t n = keyCount == 0 ? 0 : std::uint32_t(keys.size() / keyCount);
    identityOrder(n, order);
    if (keyCount == 0) return;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double* ka = keys.data() + std::size_t(a) * keyCount;
        const double* kb = keys.data() + std::size_t(b) * keyCount;
        for (std::size_t k = 0; k < keyCount; ++k)
            if (const int c = compareKey(ka[k], kb[k], directions[k])) return c < 0;
        return a < b;  // ties keep list order
    });
}

void reverseOrder(std::span<std::uint32_t> order) { std::reverse(order.begin(), order.end()); }

void shuffleOrder(std::uint32_t n, double u, std::uint64_t key, std::vector<std::uint32_t>& order) {
    identityOrder(n, order);
    // The seed depends on every bit of u and key; Rng's SplitMix64 seeding spreads it over its state.
    std::uint64_t seed = std::bit_cast<std::uint64_t>(u) * 0x9E3779B97F4A7C15ULL;
    seed ^= key + 0x632BE59BD9B4E019ULL + (seed << 6) + (seed >> 2);
    Rng rng(seed);
    for (std::uint32_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
}

}  // namespace shapevo::lists
