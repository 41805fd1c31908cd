// Primitive: what a derivation emits. An oriented box: centre, three unit axes (a right- or
// left-handed frame; mirroring flips one), and half extents along them.
#pragma once
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace shapevo {

enum class PrimitiveKind : unsigned char { Box };

struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Box;
    glm::vec3 centre{0.0f};
    glm::mat3 axes{1.0f};    ///< columns: the box's local x, y, z directions (unit length)
    glm::vec3 half{0.5f};    ///< half extents along the axes
};

/// The geometry of one model; reused between evaluations (clear() keeps capacity).
struct Geometry {
    std::vector<Primitive> primitives;
    void clear() { primitives.clear(); }
};

}  // namespace shapevo
