// Primitive: what a derivation emits, and Geometry, one model's primitives. Every kind lives in an
// oriented frame: a centre, three unit axes (a right- or left-handed frame; mirroring flips one)
// and half extents along them. Each kind is defined in its own file shape/kinds/<kind>.hpp
// (keyword, exact solid, voxel rows, silhouette outline, tessellation; shape/kinds.hpp lists
// them). In the frame's local coordinates u = (x/half.x, y/half.y, z/half.z) the solids are:
//   Box       |u.x| <= 1, |u.y| <= 1, |u.z| <= 1
//   Cylinder  u.x^2 + u.z^2 <= 1, |u.y| <= 1                (axis = the frame's y axis)
//   Cone      u.x^2 + u.z^2 <= r(u.y)^2, |u.y| <= 1, with r(y) = (1 + taper)/2 + (taper - 1)/2 * y:
//             radius 1 at the bottom (u.y = -1) and `taper` (in [0, 1]) at the top; taper 0 is a
//             pointed cone, taper 1 a cylinder
//   Sphere    |u| <= 1 (an ellipsoid filling the box)
//   Roof      |u.x| <= rx(u.y), |u.z| <= rz(u.y), |u.y| <= 1, with rx(y) = (1 + taper)/2 +
//             (taper - 1)/2 * y and rz(y) the same with taperZ (both in [0, 1]): the convex hull
//             of the bottom face (the full square at u.y = -1) and the top face |u.x| <= taper,
//             |u.z| <= taperZ at u.y = +1. Both 1: the box; taper 0: a gable ridge along z;
//             taperZ 0: along x; both 0: a pyramid
//   Paraboloid u.x^2 + u.z^2 <= (1 - u.y)/2, |u.y| <= 1: radius 1 at the bottom, apex at the top
//   Mesh      the closed triangle mesh Geometry::meshes[mesh], whose vertices are already in u
//             coordinates (the file's bounding box mapped onto [-1, 1]^3)
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "mesh/mesh_shape.hpp"
#include "shape/texture.hpp"

namespace shapevo {

/// One enumerator per kind, in the order of the kinds list (shape/kinds.hpp checks it).
enum class PrimitiveKind : unsigned char { Box, Cylinder, Cone, Sphere, Mesh, Roof, Paraboloid };
inline constexpr int kPrimitiveKinds = 7;
/// Polygon sides used wherever a round primitive must be drawn as a polyhedron (exported
/// meshes; silhouettes in image targets): cylinders and cones become kRoundSides-gon prisms and
/// frusta with vertices at angles 2*pi*k/kRoundSides from the local +x axis towards +z.
inline constexpr int kRoundSides = 16;

struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Box;
    std::uint16_t mesh = 0;  ///< Mesh: index into Geometry::meshes
    float taper = 1.0f;      ///< Cone: top radius / bottom radius; Roof: top face / bottom face along x; in [0, 1]
    glm::vec3 centre{0.0f};
    glm::mat3 axes{1.0f};    ///< columns: the frame's local x, y, z directions (unit length)
    glm::vec3 half{0.5f};    ///< half extents along the axes
    float taperZ = 1.0f;     ///< Roof: top face / bottom face along z, in [0, 1] (last: the fields above keep their places)
};

/// How a primitive looks in exported meshes: a colour (linear RGB in [0, 1]) and a named
/// material (an index into Geometry::materialNames; 0 is the unnamed default), and for a
/// textured material its image and texture frame. Scoring never reads it.
struct Appearance {
    glm::vec3 color{0.8f, 0.8f, 0.8f};
    std::uint16_t material = 0;
    std::uint16_t texture = 0;  ///< 0: none; k: Geometry::textures[k - 1], placed by Geometry::textureFrames[frame]
    std::uint32_t frame = 0;    ///< with a texture: its frame in Geometry::textureFrames
    bool operator==(const Appearance&) const = default;
};

/// The geometry of one model; reused between evaluations (clear() keeps capacity).
struct Geometry {
    std::vector<Primitive> primitives;
    /// Empty when the grammar sets no colour or material (derive then writes none); otherwise
    /// one entry per primitive, in the same order.
    std::vector<Appearance> appearance;
    /// Names of the grammar's materials, index 0 = "" (owned by the Grammar; may be null).
    const std::vector<std::string>* materialNames = nullptr;
    /// The grammar's meshes that Mesh primitives refer to (owned by the Grammar; may be null
    /// when there are none).
    const std::vector<MeshShape>* meshes = nullptr;
    /// The texture frames Appearance::frame refers to (empty when the grammar has no `texture`).
    std::vector<TextureFrame> textureFrames;
    /// The grammar's textures that Appearance::texture refers to (owned by the Grammar; may be null).
    const std::vector<Texture>* textures = nullptr;
    void clear() {
        primitives.clear();
        appearance.clear();
        textureFrames.clear();
    }
};

}  // namespace shapevo
