// Mesh -> picture: the mesh becomes one Mesh primitive (its vertices normalized to [-1, 1]^3 in
// a frame that maps them back exactly where they were), drawn by silhouetteMask.
#include "score/image/mesh_image_target.hpp"

#include <algorithm>
#include <filesystem>

#include <glm/common.hpp>

#include "base/input_error.hpp"
#include "shape/kinds/mesh.hpp"
#include "shape/primitive.hpp"
#include "image/png_writer.hpp"
#include "mesh/mesh_shape.hpp"
#include "score/image/image_scorer.hpp"

namespace shapevo {

std::vector<std::uint8_t> meshSilhouette(const Mesh& mesh, const Camera& camera) {
    std::vector<std::uint8_t> mask(std::size_t(camera.width()) * std::size_t(camera.height()), 0);
    if (mesh.vertices.empty()) return mask;
    glm::vec3 lo = mesh.vertices.front(), hi = lo;
    for (const glm::vec3& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const glm::vec3 mid = lo * 0.5f + hi * 0.5f, half = hi * 0.5f - lo * 0.5f;
    std::vector<MeshShape> shapes(1);
    MeshShape& shape = shapes[0];
    shape.vertices.reserve(mesh.vertices.size());
    for (const glm::vec3& v : mesh.vertices) {
        glm::vec3 u(0.0f);
        for (int j = 0; j < 3; ++j) u[j] = half[j] > 0.0f ? std::clamp((v[j] - mid[j]) / half[j], -1.0f, 1.0f) : 0.0f;
        shape.vertices.push_back(u);
    }
    for (const auto& t : mesh.triangles)
        if (t[0] < mesh.vertices.size() && t[1] < mesh.vertices.size() && t[2] < mesh.vertices.size())
            shape.triangles.push_back(t);
    Primitive p;
    p.kind = PrimitiveKind::Mesh;
    setParams<MeshKind>(p, {0});
    p.centre = mid;
    p.axes = glm::mat3(1.0f);
    for (int j = 0; j < 3; ++j) p.half[j] = half[j] > 0.0f ? half[j] : 1.0f;  // a flat axis: u = 0 anyway
    Geometry g;
    g.meshes = &shapes;
    g.primitives.push_back(p);
    silhouetteMask(g, camera, mask);
    return mask;
}

PictureLevels pictureLevels(const PixelRule& rule) {
    PictureLevels l;
    int hit = -1, background = -1;
    for (int v : {0, 255})
        if (hit < 0 && rule.hit(v)) hit = v;
    for (int v = 0; v <= 255 && hit < 0; ++v)
        if (rule.hit(v)) hit = v;
    for (int v : {255, 0})
        if (background < 0 && rule.avoid(v)) background = v;
    for (int v = 255; v >= 0 && background < 0; --v)
        if (rule.avoid(v)) background = v;
    for (int v = 255; v >= 0 && background < 0; --v)
        if (!rule.hit(v)) background = v;
    l.ok = hit >= 0 && background >= 0;
    if (l.ok) l.hit = std::uint8_t(hit), l.background = std::uint8_t(background);
    return l;
}

std::uint64_t writeMeshImageTarget(const Mesh& mesh, const Camera& camera, const PixelRule& rule,
                                   const std::string& meshPath, const std::string& rulePlace,
                                   const std::string& outPath) {
    const PictureLevels levels = pictureLevels(rule);
    if (!levels.ok)
        throw InputError(rulePlace, "", "the pixel rule reads no grey level as hit, so no picture can be a target for it");
    std::error_code ec;
    if (std::filesystem::exists(outPath, ec)) throw InputError(outPath, "", "already exists; refusing to overwrite it");
    const std::vector<std::uint8_t> mask = meshSilhouette(mesh, camera);
    const auto covered = std::uint64_t(std::count(mask.begin(), mask.end(), std::uint8_t(1)));
    if (covered == 0)
        throw InputError(meshPath, "", std::string("the mesh covers no pixel of the camera's ") + std::to_string(camera.width()) + " x " +
                                           std::to_string(camera.height()) + " picture (it is out of view" +
                                           (camera.projection() == Projection::Shadow ? ", below the ground, or its shadow misses the ground rectangle)"
                                                                                      : " or behind the near plane)"));
    std::vector<std::uint8_t> rgba(mask.size() * 4);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const std::uint8_t v = mask[i] ? levels.hit : levels.background;
        rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = v;
        rgba[4 * i + 3] = 255;
    }
    writePngRgba(outPath, camera.width(), camera.height(), rgba);
    return covered;
}

}  // namespace shapevo
