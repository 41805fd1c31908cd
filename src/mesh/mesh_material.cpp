// Mesh materials: the sRGB encoding, material name and consistency checks, grouping by material.
#include "mesh/mesh_material.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "base/input_error.hpp"

namespace shapevo {

float clampUnit(float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; }

float linearToSrgb(float c) {
    const double v = clampUnit(c);
    return float(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

std::array<std::uint8_t, 3> srgbBytes(const glm::vec3& linear) {
    std::array<std::uint8_t, 3> b{};
    for (int a = 0; a < 3; ++a) b[std::size_t(a)] = std::uint8_t(std::lround(255.0 * double(linearToSrgb(linear[a]))));
    return b;
}

std::string srgbHex(const glm::vec3& linear) {
    const auto b = srgbBytes(linear);
    char s[8];
    std::snprintf(s, sizeof s, "%02x%02x%02x", unsigned(b[0]), unsigned(b[1]), unsigned(b[2]));
    return s;
}

bool isMaterialName(std::string_view name) {
    if (name.empty()) return false;
    for (char c : name)
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.'))
            return false;
    return true;
}

namespace {
/// Textures and UVs: each image named as promised and used as a PNG, each material's texture
/// one of them, UVs finite, one per vertex, present exactly when a material has a texture.
void checkTextures(const Mesh& mesh, const std::string& path) {
    std::set<std::string_view> names;
    for (std::size_t t = 0; t < mesh.textures.size(); ++t) {
        const MeshTexture& tex = mesh.textures[t];
        const std::string where = "texture " + std::to_string(t);
        const std::string_view name = tex.name;
        if (!isMaterialName(name) || name.size() < 5 || name.substr(name.size() - 4) != ".png")
            throw InputError(path, where,
                             "file name '" + shortened(tex.name) + "' is not A-Z a-z 0-9 _ - . characters ending in .png");
        if (!names.insert(name).second) throw InputError(path, where, "file name '" + tex.name + "' is used twice");
        if (tex.png.size() < 8 || tex.png[0] != 0x89 || tex.png[1] != 'P' || tex.png[2] != 'N' || tex.png[3] != 'G')
            throw InputError(path, where, "image '" + tex.name + "' is not a PNG");
    }
    bool textured = false;
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const int t = mesh.materials[m].texture;
        if (t < -1 || t >= int(mesh.textures.size()))
            throw InputError(path, "material " + std::to_string(m), "texture " + std::to_string(t) + " out of range");
        textured = textured || t >= 0;
    }
    if (!textured && !mesh.uvs.empty()) throw InputError(path, "", "UV coordinates but no textured material");
    if (textured && mesh.uvs.size() != mesh.vertices.size())
        throw InputError(path, "", std::to_string(mesh.uvs.size()) + " UV coordinates for " +
                                       std::to_string(mesh.vertices.size()) + " vertices");
    for (std::size_t v = 0; v < mesh.uvs.size(); ++v)
        if (!std::isfinite(mesh.uvs[v].x) || !std::isfinite(mesh.uvs[v].y))
            throw InputError(path, "vertex " + std::to_string(v), "UV coordinate is not a finite number");
}
}  // namespace

void checkMaterials(const Mesh& mesh, const std::string& path) {
    if (mesh.materials.empty()) {
        if (!mesh.triangleMaterials.empty())
            throw InputError(path, "", "triangles name materials but the mesh has none");
        if (!mesh.textures.empty() || !mesh.uvs.empty())
            throw InputError(path, "", "textures or UV coordinates but no materials");
        return;
    }
    if (mesh.triangleMaterials.size() != mesh.triangles.size())
        throw InputError(path, "", std::to_string(mesh.triangleMaterials.size()) + " triangle materials for " +
                                       std::to_string(mesh.triangles.size()) + " triangles");
    std::set<std::string_view> names;
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const MeshMaterial& mat = mesh.materials[m];
        const std::string where = "material " + std::to_string(m);
        if (!isMaterialName(mat.name))
            throw InputError(path, where,
                             "name '" + shortened(mat.name) + "' is empty or has a character other than A-Z a-z 0-9 _ - .");
        if (!names.insert(mat.name).second) throw InputError(path, where, "name '" + mat.name + "' is used twice");
        for (int a = 0; a < 3; ++a)
            if (!(mat.color[a] >= 0.0f && mat.color[a] <= 1.0f))
                throw InputError(path, where, "colour channel is not a number in [0, 1]");
    }
    for (std::size_t t = 0; t < mesh.triangleMaterials.size(); ++t)
        if (mesh.triangleMaterials[t] >= mesh.materials.size())
            throw InputError(path, "triangle " + std::to_string(t),
                             "material " + std::to_string(mesh.triangleMaterials[t]) + " out of range");
    checkTextures(mesh, path);
}

std::vector<std::vector<std::uint32_t>> trianglesByMaterial(const Mesh& mesh) {
    std::vector<std::vector<std::uint32_t>> groups(mesh.materials.empty() ? 1 : mesh.materials.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        groups[mesh.materials.empty() ? 0 : mesh.triangleMaterials.at(t)].push_back(std::uint32_t(t));
    return groups;
}

}  // namespace shapevo
