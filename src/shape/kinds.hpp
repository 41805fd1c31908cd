// The primitive kinds, listed once, and their static dispatch. Every kind is one file in
// shape/kinds/ holding one struct K that meets PrimitiveKindContract (shape/primitive_kind.hpp:
// its kind and keyword, grammar arguments, parameters, voxel rows, silhouette outline,
// tessellation, and the optional members); the list below is checked against it, kind by kind.
// A kind's own work space is kept per kind from this list too: KindVoxelScratch (the voxelizer's,
// one K::VoxelScratch each) and KindOutlineScratch (the silhouette builder's, one K::OutlineScratch
// each), so a kind needing its own state declares it in its own file and nothing else changes.
// visitKind(kind, f) calls f(KindTag<K>{}) for the kind's struct: one compare chain per primitive
// (or statement), inlined, so the per-row and per-span loops inside a kind are monomorphic; no
// virtual call anywhere.
//
// A new kind: its file in shape/kinds/, its enumerator in shape/primitive.hpp, one line below.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "shape/kinds/box.hpp"
#include "shape/kinds/cone.hpp"
#include "shape/kinds/cylinder.hpp"
#include "shape/kinds/mesh.hpp"
#include "shape/kinds/paraboloid.hpp"
#include "shape/kinds/roof.hpp"
#include "shape/kinds/sphere.hpp"
#include "shape/primitive.hpp"
#include "shape/primitive_kind.hpp"

namespace shapevo {

template <class... K>
struct KindList {
    static constexpr std::size_t size = sizeof...(K);
};

/// The kinds, in PrimitiveKind order.
using Kinds = KindList<BoxKind, CylinderKind, ConeKind, SphereKind, MeshKind, RoofKind, ParaboloidKind>;

template <class K>
struct KindTag {
    using type = K;
};

namespace detail {
template <class... K>
constexpr bool kindsInEnumOrder(KindList<K...>) {
    int i = 0;
    return ((int(K::kind) == i++) && ...);
}
template <class F, class K, class... Rest>
[[gnu::always_inline]] inline decltype(auto) visitKind(PrimitiveKind k, F& f, KindList<K, Rest...>) {
    if constexpr (sizeof...(Rest) == 0) {
        return f(KindTag<K>{});  // the last kind: no test left
    } else {
        if (k == K::kind) return f(KindTag<K>{});
        return visitKind(k, f, KindList<Rest...>{});
    }
}
template <class K>
struct VoxelScratchOf {
    struct type {};
};
template <class K>
    requires requires { typename K::VoxelScratch; }
struct VoxelScratchOf<K> {
    using type = typename K::VoxelScratch;
};
template <class List>
struct AllVoxelScratch;
template <class... K>
struct AllVoxelScratch<KindList<K...>> : VoxelScratchOf<K>::type... {};

/// The place of a kind without K::OutlineScratch in KindOutlineScratch: empty.
struct NoOutlineScratch {
    template <class Builder>
    explicit NoOutlineScratch(const Builder&) {}
};
template <class K>
struct OutlineScratchOf {
    using type = NoOutlineScratch;
};
template <class K>
    requires requires { typename K::OutlineScratch; }
struct OutlineScratchOf<K> {
    using type = typename K::OutlineScratch;
};
template <class List>
struct AllOutlineScratch;
template <class... K>
struct AllOutlineScratch<KindList<K...>> {
    using type = std::tuple<typename OutlineScratchOf<K>::type...>;
};
}  // namespace detail

namespace detail {
/// The check, kind by kind: a kind that misses part of the contract fails here, and the compiler
/// names the kind, the part of PrimitiveKindContract and the member.
template <class K>
constexpr bool meetsContract() {
    static_assert(PrimitiveKindContract<K>, "every primitive kind meets PrimitiveKindContract (shape/primitive_kind.hpp)");
    return PrimitiveKindContract<K>;
}
template <class... K>
constexpr bool allMeetContract(KindList<K...>) {
    return (meetsContract<K>() && ...);
}
}  // namespace detail

static_assert(detail::allMeetContract(Kinds{}), "every listed kind meets PrimitiveKindContract");
static_assert(Kinds::size == std::size_t(kPrimitiveKinds), "one kind per PrimitiveKind");
static_assert(detail::kindsInEnumOrder(Kinds{}), "the kinds list follows the PrimitiveKind order");

/// f(KindTag<K>{}) for the kind struct K of `k`.
template <class F>
[[gnu::always_inline]] inline decltype(auto) visitKind(PrimitiveKind k, F&& f) {
    return detail::visitKind(k, f, Kinds{});
}

/// The kind whose keyword is `word`: calls f(KindTag<K>{}) and returns true; false if none is.
template <class F>
bool visitKeyword(std::string_view word, F&& f) {
    return [&]<class... K>(KindList<K...>) { return ((word == K::keyword ? (f(KindTag<K>{}), true) : false) || ...); }(Kinds{});
}

/// The keywords, comma separated ("box, cylinder, ..."), for error messages.
inline std::string kindKeywords() {
    return [&]<class... K>(KindList<K...>) {
        std::string s;
        ((s += (s.empty() ? "" : ", "), s += K::keyword), ...);
        return s;
    }(Kinds{});
}

/// Per-kind voxelizer work space: one K::VoxelScratch for each kind that declares one.
using KindVoxelScratch = detail::AllVoxelScratch<Kinds>;
template <class K>
typename detail::VoxelScratchOf<K>::type& voxelScratch(KindVoxelScratch& all) {
    return all;
}

/// Per-kind silhouette state, one element per kind in Kinds order (its PrimitiveKind): the kind's
/// K::OutlineScratch for each kind that declares one, an empty placeholder for the others. Built
/// once per outline builder (score/image/silhouette_outline.hpp), each K::OutlineScratch from the
/// builder (K::OutlineScratch(builder): the unit shapes it already holds, or the kind's own geometry).
using KindOutlineScratch = detail::AllOutlineScratch<Kinds>::type;
template <class Builder>
KindOutlineScratch makeKindOutlineScratch(const Builder& builder) {
    return [&]<class... K>(KindList<K...>) {
        return KindOutlineScratch(typename detail::OutlineScratchOf<K>::type(builder)...);
    }(Kinds{});
}
template <class K>
typename detail::OutlineScratchOf<K>::type& outlineScratch(KindOutlineScratch& all) {
    return std::get<std::size_t(K::kind)>(all);
}

/// False if p refers to data `meshes` does not hold (K::shapeOf; kinds without one always draw).
inline bool hasShapeData(const Primitive& p, const std::vector<MeshShape>* meshes) {
    return visitKind(p.kind, [&](auto tag) {
        using K = typename decltype(tag)::type;
        if constexpr (requires { K::shapeOf(p, meshes); }) return K::shapeOf(p, meshes) != nullptr;
        else return true;
    });
}

}  // namespace shapevo
