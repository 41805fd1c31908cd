// cluster by k-means (PCGR §4.1, §4.4, Fig 7): Lloyd's iteration on one 3D point per entity (the
// caller evaluates "by E", e.g. scope.origin), deterministic and allocation-free once warm.
//
// Exactly: K' = min(K, n) clusters (K = 0 counts as 1). The initial centroids are the first K'
// points in list order (shuffle first for a random start). A round: (1) every point goes to the
// nearest centroid by squared Euclidean distance, ties (and NaN distances) to the lowest cluster
// index; (2) if no point changed cluster since the previous round, stop: a fixed point; (3) every
// centroid becomes the mean of its members, summed left to right in list order (a cluster left
// empty keeps its centroid). At most `maxRounds` rounds (0 counts as 1); when that bound stops it,
// the clusters are the last assignment and the centroids their means.
// K > n: every point starts as its own centroid, so n clusters come out (a point equal to an
// earlier one joins that one's cluster and leaves its own empty); clusterOf never reaches n.
// n = 0: nothing, 0 rounds.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/lists/list_workspace.hpp"

namespace shapevo::lists {

struct KMeansResult {
    std::uint32_t clusters = 0;  ///< K' = min(max(K, 1), n)
    std::uint32_t rounds = 0;    ///< assignment rounds run
    bool converged = false;      ///< stopped at a fixed point (not by maxRounds)
};

/// clusterOf[i] (resized to n) = the cluster of point i; centroids (resized to K') = the
/// clusters' centroids.
KMeansResult clusterKMeans(std::span<const glm::dvec3> points, std::uint32_t k, std::uint32_t maxRounds,
                           std::vector<std::uint32_t>& clusterOf, std::vector<glm::dvec3>& centroids, ListWorkspace& ws);

/// The cluster of `p` among `centroids`: the nearest by squared distance, ties to the lowest index.
std::uint32_t nearestCentroid(const glm::dvec3& p, std::span<const glm::dvec3> centroids);

}  // namespace shapevo::lists
