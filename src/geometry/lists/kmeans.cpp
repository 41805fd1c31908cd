// Lloyd's k-means as kmeans.hpp states it: assign, stop at a fixed point, update; sums left to
// right in list order.
#include "geometry/lists/kmeans.hpp"

#include <algorithm>

namespace shapevo::lists {

std::uint32_t nearestCentroid(const glm::dvec3& p, std::span<const glm::dvec3> centroids) {
    std::uint32_t best = 0;
    double bestDistance = 0.0;
    for (std::uint32_t c = 0; c < centroids.size(); ++c) {
        const glm::dvec3 d = p - centroids[c];
        const double distance = d.x * d.x + d.y * d.y + d.z * d.z;
        if (c == 0 || distance < bestDistance) {
            best = c;
            bestDistance = distance;
        }
    }
    return best;
}

KMeansResult clusterKMeans(std::span<const glm::dvec3> points, std::uint32_t k, std::uint32_t maxRounds,
                           std::vector<std::uint32_t>& clusterOf, std::vector<glm::dvec3>& centroids, ListWorkspace& ws) {
    const std::uint32_t n = std::uint32_t(points.size());
    KMeansResult result;
    clusterOf.resize(n);
    result.clusters = std::min(std::max(k, 1u), n);
    centroids.assign(points.begin(), points.begin() + result.clusters);
    if (n == 0) return result;
    const std::uint32_t rounds = std::max(maxRounds, 1u);
    std::vector<glm::dvec3>& sums = ws.points;
    std::vector<std::uint32_t>& sizes = ws.counts;
    for (std::uint32_t round = 0; round < rounds; ++round) {
        bool changed = round == 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t c = nearestCentroid(points[i], centroids);
            changed |= c != clusterOf[i];
            clusterOf[i] = c;
        }
        result.rounds = round + 1;
        if (!changed) {
            result.converged = true;
            break;
        }
        sums.assign(result.clusters, glm::dvec3(0.0));
        sizes.assign(result.clusters, 0);
        for (std::uint32_t i = 0; i < n; ++i) {
            sums[clusterOf[i]] += points[i];
            ++sizes[clusterOf[i]];
        }
        for (std::uint32_t c = 0; c < result.clusters; ++c)
            if (sizes[c] > 0) centroids[c] = sums[c] / double(sizes[c]);
    }
    return result;
}

}  // namespace shapevo::lists
