// The contract of a primitive kind, as the C++20 concept PrimitiveKindContract: what the struct K
// of a kind (one file in shape/kinds/) must declare for the parser, derive, the voxelizer, the
// silhouette builder and the tessellation to use it through static dispatch (shape/kinds.hpp
// checks every kind it lists, so a kind missing a member does not build, and the compiler names
// the part of the contract below and the member). The parts:
//   KindIdentity        K::kind (its PrimitiveKind; the list's order is the enum's), K::keyword
//                       (its grammar keyword)
//   KindGrammar         K::parseArguments(args): reads what follows the keyword (grammar/parser.cpp:
//                       args.optionalExpression(word, otherwise), args.meshFile(), args.word(w),
//                       args.atStatementEnd(), args.tag(v), ...); K::emit(primitive, args): sets
//                       what the statement adds to the derived frame (geometry/derive.cpp:
//                       args.expression(i), args.slot()), its parameters with setParams<K>
//   KindParameters      optional K::Params: the kind's own parameters, kept in Primitive::params
//                       (shape/primitive.hpp: trivially copyable, at most KindParams::kBytes, no
//                       padding; read with paramsOf<K>(p)); a kind without parameters declares none
//   KindVoxelRows       K::voxelize(p, meshes, rows, counts): its exact voxel rows (`rows` is
//                       score/voxelizer.hpp's row interface: see voxelizeChords in shape/chord_rows.hpp)
//   KindSilhouette      K::outline(builder, map, p, out): its silhouette pieces
//                       (score/silhouette_outline.hpp is the builder; shape/outline.hpp the pieces)
//   KindTessellation    K::surface(surfaceBuilder, p, meshes): its surface (shape/surface.hpp)
// Optional members, found with `requires` where they are used: K::VoxelScratch (the voxelizer
// keeps one, rows.scratch<K>()), K::OutlineScratch (its silhouette state: the outline builder
// keeps one, built once with K::OutlineScratch(builder) from the builder's unit shapes or the
// kind's own geometry, and hands it out as builder.scratch<K>(); shape/kinds.hpp's
// KindOutlineScratch), K::shapeOf(p, meshes) (null: the primitive refers to data it does
// not have, and draws nothing), K::textureRadius(p) (a round kind: its sides are textured
// cylindrically at that radius, geometry/texture_uv.hpp).
//
// The members taking a builder or arguments are templates over them; the concept checks them with
// the empty stand-ins below (their bodies are checked where the real builders call them).
#pragma once
#include <concepts>
#include <string_view>
#include <type_traits>
#include <vector>

#include "mesh/mesh_shape.hpp"
#include "shape/outline.hpp"
#include "shape/primitive.hpp"
#include "shape/surface.hpp"

namespace shapevo {

namespace kind_contract {
/// Stand-ins for what the parser, derive, the voxelizer and the silhouette builder pass.
struct ParserArguments {};
struct DeriveArguments {};
struct VoxelRows {};
struct VoxelCounts {};
struct OutlineBuilder {
    struct LocalMap {};
};
}  // namespace kind_contract

template <class K>
concept KindIdentity = requires {
    { K::kind } -> std::convertible_to<PrimitiveKind>;
    { K::keyword } -> std::convertible_to<std::string_view>;
};

template <class K>
concept KindGrammar = requires(kind_contract::ParserArguments& parse, const kind_contract::DeriveArguments& derive,
                               Primitive& p) {
    K::parseArguments(parse);
    K::emit(p, derive);
};

template <class K>
concept KindParameters = !requires { typename K::Params; } || KindParams::fits<typename K::Params>;

template <class K>
concept KindVoxelRows = requires(const Primitive& p, const std::vector<MeshShape>* meshes, kind_contract::VoxelRows& rows,
                                 kind_contract::VoxelCounts& counts) {
    K::voxelize(p, meshes, rows, counts);
};

template <class K>
concept KindSilhouette = requires(kind_contract::OutlineBuilder& builder, const kind_contract::OutlineBuilder::LocalMap& map,
                                  const Primitive& p, Outline& out) {
    K::outline(builder, map, p, out);
};

template <class K>
concept KindTessellation = requires(SurfaceBuilder& s, const Primitive& p, const std::vector<MeshShape>* meshes) {
    K::surface(s, p, meshes);
};

/// Everything a primitive kind's struct must declare (the file's header lists the parts).
template <class K>
concept PrimitiveKindContract =
    KindIdentity<K> && KindGrammar<K> && KindParameters<K> && KindVoxelRows<K> && KindSilhouette<K> && KindTessellation<K>;

}  // namespace shapevo
