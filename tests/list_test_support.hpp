// Helpers shared by the list-operation tests (tests/geometry/list_*_test.cpp): random values of
// mixed magnitudes, random rotations, and the plain first-appearance grouping the group and
// aggregate tests compare with.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "base/random.hpp"

namespace shapevo::test::list_support {

/// Values of mixed magnitudes (so the summation order shows in the bits), sometimes NaN.
inline double randomValue(Rng& rng, bool withNaN) {
    if (withNaN && rng.below(25) == 0) return std::numeric_limits<double>::quiet_NaN();
    return (rng.uniform() - 0.5) * std::pow(10.0, double(rng.below(33)) - 16.0);
}

/// Axes of a uniformly random rotation (a random unit quaternion), as floats.
inline glm::mat3 randomRotationAxes(Rng& rng) {
    const glm::dquat q = glm::normalize(glm::dquat(rng.normal(), rng.normal(), rng.normal(), rng.normal()));
    return glm::mat3(glm::mat3_cast(q));
}

/// Key equality for grouping: == except NaN equals NaN.
inline bool sameKey(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

/// The reference grouping of keys (m per entity): scan the groups found so far for an equal key,
/// else open a new one; members in list order.
inline std::vector<std::vector<std::uint32_t>> referenceGroups(const std::vector<double>& keys, std::uint32_t m) {
    std::vector<std::vector<std::uint32_t>> groups;
    const std::uint32_t n = std::uint32_t(keys.size() / m);
    for (std::uint32_t i = 0; i < n; ++i) {
        bool placed = false;
        for (auto& g : groups) {
            bool equal = true;
            for (std::uint32_t k = 0; k < m; ++k) equal = equal && sameKey(keys[g[0] * m + k], keys[i * m + k]);
            if (equal) {
                g.push_back(i);
                placed = true;
                break;
            }
        }
        if (!placed) groups.push_back({i});
    }
    return groups;
}

}  // namespace shapevo::test::list_support
