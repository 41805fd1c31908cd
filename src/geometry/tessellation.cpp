// Tessellation: each primitive's kind builds its surface (K::surface, static dispatch); a model's
// appearances become the mesh's materials, one per distinct (clamped colour, material) pair.
#include "geometry/tessellation.hpp"

#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "mesh/mesh_material.hpp"
#include "shape/kinds.hpp"
#include "shape/surface.hpp"

namespace shapevo {

namespace {

/// Gives each distinct appearance one material of the mesh, in order of first use.
class MaterialTable {
public:
    MaterialTable(const std::vector<std::string>* names, Mesh& mesh) : names_(names), mesh_(mesh) {}

    std::uint32_t indexOf(const Appearance& a) {
        const glm::vec3 color(clampUnit(a.color.x), clampUnit(a.color.y), clampUnit(a.color.z));
        const auto key = std::make_tuple(color.x, color.y, color.z, a.material);
        if (const auto found = index_.find(key); found != index_.end()) return found->second;
        const std::string base = appearanceName(Appearance{color, a.material}, names_);
        std::string name = base;
        for (int n = 2; used_.count(name); ++n) name = base + "_" + std::to_string(n);
        used_.insert(name);
        const auto index = std::uint32_t(mesh_.materials.size());
        mesh_.materials.push_back(MeshMaterial{name, color});
        index_.emplace(key, index);
        return index;
    }

private:
    const std::vector<std::string>* names_;
    Mesh& mesh_;
    std::map<std::tuple<float, float, float, std::uint16_t>, std::uint32_t> index_;
    std::set<std::string> used_;
};

}  // namespace

void appendSurface(const Primitive& p, const std::vector<MeshShape>* meshes, Mesh& out) {
    SurfaceBuilder s(p, out);
    visitKind(p.kind, [&](auto kind) { decltype(kind)::type::surface(s, p, meshes); });
}

std::string appearanceName(const Appearance& a, const std::vector<std::string>* materialNames) {
    std::string name;
    if (a.material != 0) {
        if (!materialNames || a.material >= materialNames->size())
            throw std::out_of_range("appearance names material " + std::to_string(a.material) +
                                    ", which the grammar does not have");
        name = (*materialNames)[a.material];
        for (char& c : name)
            if (!isMaterialName(std::string_view(&c, 1))) c = '_';
    }
    if (name.empty()) {  // built step by step: GCC 12 warns (-Wrestrict) on literal + string
        name = "color_";
        name += srgbHex(a.color);
    }
    return name;
}

Mesh tessellate(const Geometry& geometry) {
    Mesh m;
    const bool looks = !geometry.appearance.empty();
    if (looks && geometry.appearance.size() != geometry.primitives.size())
        throw std::invalid_argument(std::to_string(geometry.appearance.size()) + " appearances for " +
                                    std::to_string(geometry.primitives.size()) + " primitives");
    MaterialTable table(geometry.materialNames, m);
    for (std::size_t i = 0; i < geometry.primitives.size(); ++i) {
        const std::size_t before = m.triangles.size();
        appendSurface(geometry.primitives[i], geometry.meshes, m);
        if (looks && m.triangles.size() > before)
            m.triangleMaterials.resize(m.triangles.size(), table.indexOf(geometry.appearance[i]));
    }
    return m;
}

}  // namespace shapevo
