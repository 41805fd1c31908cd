// ray cast (PCGR §4.5, Fig 8): each entity of list 1 casts a ray from its scope's origin (its
// centre) along one of its scope's axes, ± as given; the result is the nearest hit among the
// oriented boxes (scopes) of list 2: the smallest distance at which the ray is in a closed box (0
// if it starts inside one; flat scopes are their rectangles), ties to the lowest index. A target
// whose origin, axes and size equal the caster's bit for bit is the caster itself and is skipped,
// so a list may be cast against itself. Equal to testing every target (box_tree.hpp: exact);
// deterministic; allocation-free once the tree has grown.
#pragma once
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "geometry/lists/box_tree.hpp"

namespace shapevo::lists {

/// Which axis of the caster's scope the ray follows: 0 = x, 1 = y, 2 = z (a flat scope's normal).
struct RayAxis {
    std::uint8_t axis = 2;
    bool negative = false;  ///< along -axis
};

struct RayHit {
    bool hit = false;
    std::uint32_t target = kNoBox;  ///< index into list 2 (kNoBox on a miss)
    double distance = kNoDistance;  ///< from the caster's origin (a unit direction)
    glm::dvec3 point{0.0};          ///< origin + direction * distance (0 on a miss)
};

/// The ray of a caster: its origin and unit direction.
void casterRay(const Scope& caster, RayAxis along, glm::dvec3& origin, glm::dvec3& direction);

/// out[i] (out.size() == casters.size()) = caster i's nearest hit among `targets`; `tree` is
/// rebuilt over `targets`.
void rayCast(std::span<const Scope> casters, RayAxis along, std::span<const Scope> targets, BoxTree& tree, std::span<RayHit> out);

}  // namespace shapevo::lists
