// ray cast (ray_cast.hpp): one nearest-hit query of the box tree per caster.
#include "geometry/lists/ray_cast.hpp"

#include <glm/geometric.hpp>

namespace shapevo::lists {

void casterRay(const Scope& caster, RayAxis along, glm::dvec3& origin, glm::dvec3& direction) {
    origin = glm::dvec3(caster.origin);
    direction = glm::normalize(glm::dvec3(caster.axes[along.axis]));
    if (along.negative) direction = -direction;
}

void rayCast(std::span<const Scope> casters, RayAxis along, std::span<const Scope> targets, BoxTree& tree, std::span<RayHit> out) {
    tree.build(targets);
    for (std::size_t i = 0; i < casters.size(); ++i) {
        glm::dvec3 origin, direction;
        casterRay(casters[i], along, origin, direction);
        const BoxTree::Hit h = tree.nearest(origin, direction, kNoBox, &casters[i]);
        RayHit& r = out[i];
        r.hit = h.box != kNoBox;
        r.target = h.box;
        r.distance = h.distance;
        r.point = r.hit ? origin + direction * h.distance : glm::dvec3(0.0);
    }
}

}  // namespace shapevo::lists
