// Primitive: what a derivation emits, and Geometry, one model's primitives. Every kind lives in an
// oriented frame: a centre, three unit axes (a right- or left-handed frame; mirroring flips one)
// and half extents along them; what a kind needs beyond its frame (a cone's taper, a roof's two
// fractions, a mesh's index) is its own parameter block, KindParams, that only the kind reads
// (through its K::Params). Each kind is defined in its own file shape/kinds/<kind>.hpp (keyword,
// parameters, exact solid, voxel rows, silhouette outline, tessellation; the contract is the
// concept in shape/primitive_kind.hpp, and shape/kinds.hpp lists them). In the frame's local coordinates u = (x/half.x, y/half.y, z/half.z) the solids are:
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
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
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

namespace detail {
/// True for a P without padding bytes; a compile error (reading an uninitialized byte in a
/// constant expression) for one with padding, whose bytes could not be compared as a key.
template <class P>
constexpr bool noPaddingBytes() {
    const auto bytes = std::bit_cast<std::array<unsigned char, sizeof(P)>>(P{});
    unsigned sum = 0;
    for (unsigned char b : bytes) sum += b;  // reads every byte: padding does not compile
    return sum <= 255u * sizeof(P);
}
}  // namespace detail

/// A kind's own parameters as bytes, which only the kind interprets: as its K::Params (a
/// trivially copyable struct of at most kBytes bytes without padding), read with paramsOf<K>(p)
/// and written with setParams<K>(p, params). Copied, hashed and compared as bytes
/// (score/primitive_cache.hpp): writing zeroes every byte the kind's Params does not cover, so
/// equal parameters are equal bytes. All zero for a kind without parameters.
struct KindParams {
    static constexpr std::size_t kBytes = 8;
    alignas(4) unsigned char bytes[kBytes] = {};

    /// Whether P can be kept in the block (size, alignment, trivially copyable).
    template <class P>
    static constexpr bool fits = std::is_trivially_copyable_v<P> && sizeof(P) <= kBytes && alignof(P) <= 4;

    template <class P>
    P as() const {
        static_assert(fits<P>, "a kind's Params must be trivially copyable and fit KindParams::kBytes");
        P v;
        std::memcpy(&v, bytes, sizeof v);
        return v;
    }
    template <class P>
    void set(const P& v) {
        static_assert(fits<P>, "a kind's Params must be trivially copyable and fit KindParams::kBytes");
        static_assert(detail::noPaddingBytes<P>(), "a kind's Params must have no padding bytes (they are compared as bytes)");
        std::memset(bytes, 0, kBytes);
        std::memcpy(bytes, &v, sizeof v);
    }
    bool operator==(const KindParams&) const = default;
};

struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Box;
    KindParams params;       ///< the kind's own parameters (its K::Params; zero for a kind without them)
    glm::vec3 centre{0.0f};
    glm::mat3 axes{1.0f};    ///< columns: the frame's local x, y, z directions (unit length)
    glm::vec3 half{0.5f};    ///< half extents along the axes
};
static_assert(sizeof(Primitive) == 4 + KindParams::kBytes + 60, "kind, parameters, then the frame's 15 floats without padding");

/// Kind K's parameters of p (p.kind is K::kind).
template <class K>
typename K::Params paramsOf(const Primitive& p) {
    return p.params.as<typename K::Params>();
}
/// Sets kind K's parameters of p (p.kind is K::kind); every other byte of the block becomes zero.
template <class K>
void setParams(Primitive& p, const typename K::Params& params) {
    p.params.set(params);
}

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
