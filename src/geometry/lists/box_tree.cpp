// BoxTree (box_tree.hpp): median splits on the longest axis of the centres' bounds, leaves of at
// most 4 boxes; queries walk nearer child first with a fixed stack and prune by the best distance.
#include "geometry/lists/box_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "geometry/lists/merge.hpp"

namespace shapevo::lists {
namespace {

constexpr std::uint32_t kLeafBoxes = 4;

/// Entry distance of a ray into an axis-aligned box (>= 0), or +inf for a miss.
double rayBoundsDistance(const glm::dvec3& origin, const glm::dvec3& inverse, const double* lo, const double* hi) {
    double t0 = 0.0, t1 = kNoDistance;
    for (int a = 0; a < 3; ++a) {
        double near = (lo[a] - origin[a]) * inverse[a], far = (hi[a] - origin[a]) * inverse[a];
        if (std::isnan(near) || std::isnan(far)) {  // direction 0 on this axis with the origin on a face
            if (origin[a] < lo[a] || origin[a] > hi[a]) return kNoDistance;
            continue;
        }
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
    }
    return t0 <= t1 ? t0 : kNoDistance;
}

}  // namespace

double rayBoxDistance(const glm::dvec3& origin, const glm::dvec3& direction, const Scope& box) {
    const glm::dvec3 offset = origin - glm::dvec3(box.origin);
    double t0 = 0.0, t1 = kNoDistance;
    for (int a = 0; a < 3; ++a) {
        const glm::dvec3 axis(box.axes[a]);
        const double o = glm::dot(offset, axis), d = glm::dot(direction, axis), half = 0.5 * double(box.size[a]);
        if (d == 0.0) {
            if (!(std::abs(o) <= half)) return kNoDistance;
            continue;
        }
        double near = (-half - o) / d, far = (half - o) / d;
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
    }
    return t0 <= t1 ? t0 : kNoDistance;
}

bool sameFrame(const Scope& a, const Scope& b) {
    return std::memcmp(&a.origin, &b.origin, sizeof a.origin) == 0 && std::memcmp(&a.axes, &b.axes, sizeof a.axes) == 0 &&
           std::memcmp(&a.size, &b.size, sizeof a.size) == 0;
}

void BoxTree::build(std::span<const Scope> boxes) {
    boxes_ = boxes;
    const std::uint32_t n = std::uint32_t(boxes.size());
    bounds_.resize(6 * std::size_t(n));
    items_.resize(n);
    glm::dvec3 corners[8];
    for (std::uint32_t i = 0; i < n; ++i) {
        items_[i] = i;
        scopeCorners(boxes[i], corners);
        double* b = bounds_.data() + 6 * std::size_t(i);
        for (int a = 0; a < 3; ++a) {
            double lo = corners[0][a], hi = lo;
            for (const glm::dvec3& c : corners) lo = std::min(lo, c[a]), hi = std::max(hi, c[a]);
            // Grown beyond the rounding of the corners and of the queries' slab arithmetic.
            const double pad = 1e-7 * (std::abs(lo) + std::abs(hi) + (hi - lo)) + 1e-9;
            b[a] = lo - pad;
            b[3 + a] = hi + pad;
        }
    }
    nodes_.clear();
    if (n > 0) {
        nodes_.resize(1);
        buildNode(0, 0, n);
    }
}

void BoxTree::buildNode(std::uint32_t self, std::uint32_t begin, std::uint32_t end) {
    // nodes_[self] gets the bounds of every box of items_[begin, end).
    double lo[3], hi[3], clo[3], chi[3];
    for (int a = 0; a < 3; ++a) lo[a] = clo[a] = kNoDistance, hi[a] = chi[a] = -kNoDistance;
    for (std::uint32_t k = begin; k < end; ++k) {
        const double* b = bounds_.data() + 6 * std::size_t(items_[k]);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b[a]), hi[a] = std::max(hi[a], b[3 + a]);
            const double c = 0.5 * (b[a] + b[3 + a]);
            clo[a] = std::min(clo[a], c), chi[a] = std::max(chi[a], c);
        }
    }
    std::copy(lo, lo + 3, nodes_[self].lo);
    std::copy(hi, hi + 3, nodes_[self].hi);
    if (end - begin <= kLeafBoxes) {
        nodes_[self].first = begin;
        nodes_[self].count = end - begin;
        return;
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (chi[a] - clo[a] > chi[axis] - clo[axis]) axis = a;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end, [&](std::uint32_t x, std::uint32_t y) {
        const double cx = bounds_[6 * std::size_t(x) + axis] + bounds_[6 * std::size_t(x) + 3 + axis];
        const double cy = bounds_[6 * std::size_t(y) + axis] + bounds_[6 * std::size_t(y) + 3 + axis];
        return cx < cy || (!(cy < cx) && x < y);
    });
    const std::uint32_t left = std::uint32_t(nodes_.size());
    nodes_[self].first = left;
    nodes_[self].count = 0;
    nodes_.resize(nodes_.size() + 2);
    buildNode(left, begin, mid);
    buildNode(left + 1, mid, end);
}

template <class Visit>
void BoxTree::walk(const glm::dvec3& origin, const glm::dvec3& direction, double& limit, Visit&& visit) const {
    if (nodes_.empty()) return;
    const glm::dvec3 inverse(1.0 / direction.x, 1.0 / direction.y, 1.0 / direction.z);
    struct Entry {
        std::uint32_t node;
        double distance;
    };
    Entry stack[96];  // depth <= log2(n / 4) + 1, one pending sibling per level
    int top = 0;
    auto reach = [&](std::uint32_t node) { return rayBoundsDistance(origin, inverse, nodes_[node].lo, nodes_[node].hi); };
    const double rootDistance = reach(0);
    if (rootDistance == kNoDistance) return;
    stack[top++] = {0, rootDistance};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.distance > limit) continue;
        const Node& node = nodes_[e.node];
        if (node.count > 0) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) visit(items_[k]);
            continue;
        }
        Entry near{node.first, reach(node.first)}, far{node.first + 1, reach(node.first + 1)};
        if (far.distance < near.distance) std::swap(near, far);
        if (far.distance != kNoDistance && far.distance <= limit) stack[top++] = far;
        if (near.distance != kNoDistance && near.distance <= limit) stack[top++] = near;
    }
}

BoxTree::Hit BoxTree::nearest(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t skipIndex,
                              const Scope* skipFrame) const {
    Hit best;
    double limit = kNoDistance;
    walk(origin, direction, limit, [&](std::uint32_t i) {
        if (i == skipIndex || (skipFrame != nullptr && sameFrame(boxes_[i], *skipFrame))) return;
        const double t = rayBoxDistance(origin, direction, boxes_[i]);
        if (t == kNoDistance) return;
        if (t < best.distance || (t == best.distance && i < best.box)) {
            best = {i, t};
            limit = t;
        }
    });
    return best;
}

bool BoxTree::anyBefore(const glm::dvec3& origin, const glm::dvec3& direction, double maxDistance, std::uint32_t skipIndex) const {
    bool found = false;
    double limit = maxDistance;
    walk(origin, direction, limit, [&](std::uint32_t i) {
        if (found || i == skipIndex) return;
        if (rayBoxDistance(origin, direction, boxes_[i]) < maxDistance) {
            found = true;
            limit = -1.0;  // every pending node is now beyond the limit
        }
    });
    return found;
}

}  // namespace shapevo::lists
