// Aggregates (geometry/lists/aggregate.hpp): min / max / avg / sum of scalars and 3-vectors bit for
// bit equal to a left-to-right loop written in the test, over whole random lists and per group,
// and the stated values for empty lists and NaNs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "../list_test_support.hpp"
#include "base/random.hpp"
#include "geometry/lists/aggregate.hpp"
#include "geometry/lists/grouping.hpp"

namespace shapevo::lists {
namespace list_aggregate_test {

using test::list_support::randomValue;
using test::list_support::referenceGroups;

/// The reference aggregate of values[at[0]], values[at[1]], ... written plainly.
double referenceAggregate(Aggregate kind, const std::vector<double>& values, const std::vector<std::uint32_t>& at) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (kind == Aggregate::Sum || kind == Aggregate::Avg) {
        double sum = 0.0;
        for (const std::uint32_t i : at) sum += values[i];
        if (kind == Aggregate::Sum) return sum;
        return at.empty() ? nan : sum / double(at.size());
    }
    double best = nan;
    for (const std::uint32_t i : at) {
        const double v = values[i];
        if (std::isnan(v)) continue;
        if (std::isnan(best) || (kind == Aggregate::Min ? v < best : v > best)) best = v;
    }
    return best;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::vector<std::uint32_t> allPositions(std::size_t n) {
    std::vector<std::uint32_t> at(n);
    for (std::uint32_t i = 0; i < n; ++i) at[i] = i;
    return at;
}

TEST(ListAggregate, ScalarAndVectorAreBitIdenticalToALeftToRightLoopOnRandomLists) {
    Rng rng(23);
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(50);
        std::vector<double> values(n);
        for (double& v : values) v = randomValue(rng, list % 2 == 1);
        std::vector<glm::dvec3> vectors(n);
        std::vector<double> xs(n), ys(n), zs(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            vectors[i] = {randomValue(rng, false), randomValue(rng, false), randomValue(rng, true)};
            xs[i] = vectors[i].x, ys[i] = vectors[i].y, zs[i] = vectors[i].z;
        }
        for (const Aggregate kind : {Aggregate::Min, Aggregate::Max, Aggregate::Avg, Aggregate::Sum}) {
            ASSERT_TRUE(sameBits(aggregate(kind, values), referenceAggregate(kind, values, allPositions(n))));
            const glm::dvec3 v = aggregate(kind, std::span<const glm::dvec3>(vectors));
            ASSERT_TRUE(sameBits(v.x, referenceAggregate(kind, xs, allPositions(n))));
            ASSERT_TRUE(sameBits(v.y, referenceAggregate(kind, ys, allPositions(n))));
            ASSERT_TRUE(sameBits(v.z, referenceAggregate(kind, zs, allPositions(n))));
        }
    }
}

TEST(ListAggregate, SumsInListOrderAndEmptyListsGiveTheStatedValues) {
    EXPECT_EQ(aggregate(Aggregate::Sum, std::vector<double>{1e16, 1.0, -1e16}), 0.0);  // (1e16 + 1) rounds to 1e16
    EXPECT_EQ(aggregate(Aggregate::Sum, std::vector<double>{1e16, -1e16, 1.0}), 1.0);
    EXPECT_EQ(aggregate(Aggregate::Sum, std::vector<double>{}), 0.0);
    EXPECT_TRUE(std::isnan(aggregate(Aggregate::Avg, std::vector<double>{})));
    EXPECT_TRUE(std::isnan(aggregate(Aggregate::Min, std::vector<double>{})));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(aggregate(Aggregate::Max, std::vector<double>{nan, 3.0, nan, 5.0}), 5.0);
    EXPECT_EQ(aggregate(Aggregate::Min, std::vector<double>{nan, 3.0, nan, 5.0}), 3.0);
    EXPECT_TRUE(std::isnan(aggregate(Aggregate::Avg, std::vector<double>{nan, 3.0})));
}

TEST(ListAggregate, PerGroupEqualsThePerGroupLeftToRightLoop) {
    Rng rng(37);
    Grouping g;
    ListWorkspace ws;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(60);
        std::vector<double> keys(n), values(n);
        std::vector<glm::dvec3> vectors(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            keys[i] = double(rng.below(6));
            values[i] = randomValue(rng, true);
            vectors[i] = {randomValue(rng, false), randomValue(rng, false), randomValue(rng, false)};
        }
        groupBy(keys, 1, g, ws);
        std::vector<double> out(g.count());
        std::vector<glm::dvec3> outVectors(g.count());
        for (const Aggregate kind : {Aggregate::Min, Aggregate::Max, Aggregate::Avg, Aggregate::Sum}) {
            aggregateGroups(kind, values, g, out);
            aggregateGroups(kind, std::span<const glm::dvec3>(vectors), g, outVectors);
            const auto reference = referenceGroups(keys, 1);
            for (std::uint32_t k = 0; k < g.count(); ++k) {
                ASSERT_TRUE(sameBits(out[k], referenceAggregate(kind, values, reference[k])));
                std::vector<double> xs(n);
                for (std::uint32_t i = 0; i < n; ++i) xs[i] = vectors[i].y;
                ASSERT_TRUE(sameBits(outVectors[k].y, referenceAggregate(kind, xs, reference[k])));
            }
        }
    }
}

}  // namespace list_aggregate_test
}  // namespace shapevo::lists
