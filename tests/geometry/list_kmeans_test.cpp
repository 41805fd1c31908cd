// cluster by k-means (geometry/lists/kmeans.hpp) against a reference Lloyd iteration written in
// the test (bit for bit, on 1,000 random lists), its fixed point, K > n, and shuffled starts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "base/random.hpp"
#include "geometry/lists/kmeans.hpp"
#include "geometry/lists/ordering.hpp"

namespace shapevo::lists {
namespace list_kmeans_test {

struct ReferenceKMeans {
    std::vector<std::uint32_t> clusterOf;
    std::vector<glm::dvec3> centroids;
    std::uint32_t rounds = 0;
    bool converged = false;
};

/// Lloyd's iteration, written out as kmeans.hpp states it.
ReferenceKMeans referenceLloyd(const std::vector<glm::dvec3>& points, std::uint32_t k, std::uint32_t maxRounds) {
    ReferenceKMeans r;
    const std::size_t n = points.size();
    const std::size_t clusters = std::min<std::size_t>(std::max<std::uint32_t>(k, 1), n);
    r.centroids.assign(points.begin(), points.begin() + clusters);
    if (n == 0) return r;
    for (std::uint32_t round = 0; round < std::max<std::uint32_t>(maxRounds, 1); ++round) {
        std::vector<std::uint32_t> assignment(n);
        for (std::size_t i = 0; i < n; ++i) {
            double best = 0.0;
            for (std::uint32_t c = 0; c < clusters; ++c) {
                const glm::dvec3 d = points[i] - r.centroids[c];
                const double dd = d.x * d.x + d.y * d.y + d.z * d.z;
                if (c == 0 || dd < best) best = dd, assignment[i] = c;
            }
        }
        r.rounds = round + 1;
        if (round > 0 && assignment == r.clusterOf) {
            r.converged = true;
            break;
        }
        r.clusterOf = assignment;
        for (std::uint32_t c = 0; c < clusters; ++c) {
            glm::dvec3 sum(0.0);
            std::size_t count = 0;
            for (std::size_t i = 0; i < n; ++i)
                if (assignment[i] == c) sum += points[i], ++count;
            if (count > 0) r.centroids[c] = sum / double(count);
        }
    }
    return r;
}

std::vector<glm::dvec3> randomPoints(Rng& rng, std::uint32_t n) {
    std::vector<glm::dvec3> points(n);
    for (glm::dvec3& p : points) {
        if (&p != points.data() && rng.below(10) == 0) {
            p = points[rng.below(std::uint32_t(&p - points.data()))];  // some duplicates
            continue;
        }
        const double spread = rng.below(2) ? 1.0 : 100.0;
        p = {rng.normal() * spread, rng.normal() * spread, rng.below(3) == 0 ? 0.0 : rng.normal()};
    }
    return points;
}

TEST(ListKMeans, EqualsAReferenceLloydIterationBitForBitOnRandomLists) {
    Rng rng(41);
    std::vector<std::uint32_t> clusterOf;
    std::vector<glm::dvec3> centroids;
    ListWorkspace ws;
    int converged = 0;
    for (int list = 0; list < 1000; ++list) {
        const std::vector<glm::dvec3> points = randomPoints(rng, rng.below(80));
        const std::uint32_t k = rng.below(10), rounds = rng.below(25);
        const KMeansResult r = clusterKMeans(points, k, rounds, clusterOf, centroids, ws);
        const ReferenceKMeans ref = referenceLloyd(points, k, rounds);
        ASSERT_EQ(r.rounds, ref.rounds) << "list " << list;
        ASSERT_EQ(r.converged, ref.converged);
        ASSERT_EQ(r.clusters, ref.centroids.size());
        if (!points.empty()) {
            ASSERT_EQ(clusterOf, ref.clusterOf);
        }
        if (!centroids.empty()) {
            ASSERT_EQ(std::memcmp(centroids.data(), ref.centroids.data(), centroids.size() * sizeof(glm::dvec3)), 0);
        }
        converged += r.converged;
    }
    EXPECT_GT(converged, 300);  // both ways of stopping are exercised
    EXPECT_LT(converged, 1000);
}

TEST(ListKMeans, EndsAtAFixedPointWhereEveryEntityIsNearestToItsOwnCentroid) {
    Rng rng(43);
    std::vector<std::uint32_t> clusterOf;
    std::vector<glm::dvec3> centroids;
    ListWorkspace ws;
    for (int list = 0; list < 200; ++list) {
        const std::vector<glm::dvec3> points = randomPoints(rng, 1 + rng.below(200));
        const KMeansResult r = clusterKMeans(points, 6, 1000, clusterOf, centroids, ws);
        ASSERT_TRUE(r.converged);
        for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(nearestCentroid(points[i], centroids), clusterOf[i]);
        for (std::uint32_t c = 0; c < r.clusters; ++c) {  // each centroid is its members' mean
            glm::dvec3 sum(0.0);
            int count = 0;
            for (std::size_t i = 0; i < points.size(); ++i)
                if (clusterOf[i] == c) sum += points[i], ++count;
            if (count > 0) {
                ASSERT_EQ(centroids[c], sum / double(count));
            }
        }
    }
}

TEST(ListKMeans, MoreClustersThanEntitiesGivesOneClusterPerDistinctEntity) {
    std::vector<std::uint32_t> clusterOf;
    std::vector<glm::dvec3> centroids;
    ListWorkspace ws;
    const std::vector<glm::dvec3> points{{0, 0, 0}, {5, 0, 0}, {0, 0, 0}, {1, 2, 3}};
    const KMeansResult r = clusterKMeans(points, 10, 20, clusterOf, centroids, ws);
    EXPECT_EQ(r.clusters, 4u);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(clusterOf, (std::vector<std::uint32_t>{0, 1, 0, 3}));  // the duplicate joins cluster 0; 2 stays empty
    const KMeansResult none = clusterKMeans(std::vector<glm::dvec3>{}, 6, 20, clusterOf, centroids, ws);
    EXPECT_EQ(none.clusters, 0u);
    EXPECT_TRUE(clusterOf.empty());
    EXPECT_TRUE(centroids.empty());
}

TEST(ListKMeans, TheSameShuffleSeedGivesTheSameClusters) {
    Rng rng(47);
    const std::vector<glm::dvec3> points = randomPoints(rng, 300);
    std::vector<std::uint32_t> order, a, b, c;
    std::vector<glm::dvec3> shuffled(points.size()), centroids;
    ListWorkspace ws;
    auto clustersFor = [&](double u, std::vector<std::uint32_t>& out) {
        shuffleOrder(std::uint32_t(points.size()), u, 99, order);
        for (std::size_t i = 0; i < order.size(); ++i) shuffled[i] = points[order[i]];
        std::vector<std::uint32_t> clusterOf;
        clusterKMeans(shuffled, 6, 100, clusterOf, centroids, ws);
        out.assign(points.size(), 0);
        for (std::size_t i = 0; i < order.size(); ++i) out[order[i]] = clusterOf[i];
    };
    clustersFor(0.3, a);
    clustersFor(0.3, b);
    clustersFor(0.7, c);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

}  // namespace list_kmeans_test
}  // namespace shapevo::lists
