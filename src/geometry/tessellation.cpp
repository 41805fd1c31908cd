// Tessellation: each primitive's kind builds its surface (K::surface, static dispatch); a model's
// appearances become the mesh's materials, one per distinct (clamped colour, material, texture);
// textured primitives get UVs (geometry/texture_uv.hpp).
#include "geometry/tessellation.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "geometry/texture_uv.hpp"
#include "mesh/mesh_material.hpp"
#include "shape/kinds.hpp"
#include "shape/surface.hpp"

namespace shapevo {

namespace {

/// Gives each distinct appearance one material of the mesh, in order of first use.
class MaterialTable {
public:
    MaterialTable(const Geometry& g, Mesh& mesh) : names_(g.materialNames), textures_(g.textures), mesh_(mesh) {}

    std::uint32_t indexOf(const Appearance& a) {
        const glm::vec3 color(clampUnit(a.color.x), clampUnit(a.color.y), clampUnit(a.color.z));
        const auto key = std::make_tuple(color.x, color.y, color.z, a.material, a.texture);
        if (const auto found = index_.find(key); found != index_.end()) return found->second;
        const std::string base = appearanceName(Appearance{color, a.material}, names_);
        std::string name = base;
        for (int n = 2; used_.count(name); ++n) name = base + "_" + std::to_string(n);
        used_.insert(name);
        const auto index = std::uint32_t(mesh_.materials.size());
        mesh_.materials.push_back(MeshMaterial{name, color, a.texture ? imageOf(a.texture - 1) : -1});
        index_.emplace(key, index);
        return index;
    }

private:
    /// The mesh texture of the grammar's texture `t`: one per image file, named after it.
    int imageOf(std::size_t t) {
        if (!textures_ || t >= textures_->size())
            throw std::out_of_range("appearance names texture " + std::to_string(t + 1) + ", which the grammar does not have");
        const Texture& texture = (*textures_)[t];
        if (const auto found = images_.find(texture.file); found != images_.end()) return found->second;
        std::string stem = std::filesystem::path(texture.path).stem().string();
        for (char& c : stem)
            if (!isMaterialName(std::string_view(&c, 1))) c = '_';
        if (stem.empty()) stem = "texture";
        std::string name = stem + ".png";
        for (int n = 2; imageNames_.count(name); ++n) name = stem + "_" + std::to_string(n) + ".png";
        imageNames_.insert(name);
        const int index = int(mesh_.textures.size());
        mesh_.textures.push_back(MeshTexture{name, texture.png});
        images_.emplace(texture.file, index);
        return index;
    }

    const std::vector<std::string>* names_;
    const std::vector<Texture>* textures_;
    Mesh& mesh_;
    std::map<std::tuple<float, float, float, std::uint16_t, std::uint16_t>, std::uint32_t> index_;
    std::set<std::string> used_;
    std::map<std::string, int> images_;  ///< Texture::file -> index in mesh_.textures
    std::set<std::string> imageNames_;
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
    MaterialTable table(geometry, m);
    for (std::size_t i = 0; i < geometry.primitives.size(); ++i) {
        const std::size_t before = m.triangles.size();
        const auto firstVertex = std::uint32_t(m.vertices.size());
        appendSurface(geometry.primitives[i], geometry.meshes, m);
        if (looks && m.triangles.size() > before) {
            const Appearance& a = geometry.appearance[i];
            m.triangleMaterials.resize(m.triangles.size(), table.indexOf(a));
            if (a.texture != 0) {
                if (a.frame >= geometry.textureFrames.size())
                    throw std::out_of_range("appearance names texture frame " + std::to_string(a.frame) + " of " +
                                            std::to_string(geometry.textureFrames.size()));
                m.uvs.resize(firstVertex);  // untextured vertices before this primitive: (0, 0)
                applyTextureUv(geometry.primitives[i], geometry.textureFrames[a.frame], firstVertex, before, m);
            }
        }
    }
    if (!m.uvs.empty()) m.uvs.resize(m.vertices.size());
    return m;
}

}  // namespace shapevo
