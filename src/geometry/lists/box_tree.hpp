// BoxTree: a bounding-volume hierarchy over oriented boxes (scopes), for the ray queries of ray
// cast and facing. Exact: a query returns what testing every box with rayBoxDistance returns (the
// tree's boxes are axis-aligned bounds grown a little beyond rounding, and only prune boxes a ray
// cannot reach at or before the best distance found). Deterministic; building and querying
// allocate nothing once the vectors have grown.
//
// rayBoxDistance: the distance along a ray (unit direction) at which it first is in the closed
// box, 0 if it starts inside, +inf if it misses. A flat box (size 0 on an axis) is its rectangle.
// Axes are taken orthonormal, as derive makes them.
#pragma once
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/pieces.hpp"

namespace shapevo::lists {

inline constexpr std::uint32_t kNoBox = ~0u;
inline constexpr double kNoDistance = std::numeric_limits<double>::infinity();

double rayBoxDistance(const glm::dvec3& origin, const glm::dvec3& direction, const Scope& box);

/// true when a and b have the same origin, axes and size, bit for bit (look aside).
bool sameFrame(const Scope& a, const Scope& b);

class BoxTree {
public:
    /// Builds the tree over `boxes`, which must outlive the queries (the tree keeps the span).
    void build(std::span<const Scope> boxes);

    struct Hit {
        std::uint32_t box = kNoBox;     ///< index into the boxes, kNoBox for none
        double distance = kNoDistance;  ///< along the ray
    };
    /// The nearest box the ray hits (smallest distance; ties to the lowest index), skipping box
    /// `skipIndex` and every box whose frame equals `*skipFrame` (either may be kNoBox / null).
    Hit nearest(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t skipIndex, const Scope* skipFrame) const;
    /// Whether some box other than `skipIndex` is hit at a distance below `maxDistance`.
    bool anyBefore(const glm::dvec3& origin, const glm::dvec3& direction, double maxDistance, std::uint32_t skipIndex) const;

private:
    struct Node {
        double lo[3], hi[3];
        std::uint32_t first = 0;  ///< leaf: first item; inner: the left child (the right is first + 1)
        std::uint32_t count = 0;  ///< leaf: items; inner: 0
    };
    void buildNode(std::uint32_t self, std::uint32_t begin, std::uint32_t end);
    template <class Visit>
    void walk(const glm::dvec3& origin, const glm::dvec3& direction, double& limit, Visit&& visit) const;

    std::span<const Scope> boxes_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> items_;   ///< box indices, leaf by leaf
    std::vector<double> bounds_;         ///< per box: lo x y z, hi x y z (grown)
};

}  // namespace shapevo::lists
