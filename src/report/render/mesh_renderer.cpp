// MeshRenderer: z-buffered, flat-shaded, 2 x 2 supersampled triangles (mesh_renderer.hpp).
#include "report/render/mesh_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "image/png_mean_colour.hpp"

namespace shapevo {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr int kSrgbSteps = 4096;

/// Light, relative to the camera: ambient, a key light from the upper left in front, a fill
/// from the right.
constexpr float kAmbient = 0.2f, kKey = 0.7f, kFill = 0.3f;
constexpr glm::vec3 kKeyDirection{-0.35f, 0.6f, 0.7f}, kFillDirection{0.5f, 0.1f, 0.8f};  // (right, up, toward)

float srgbOf(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

/// Twice the signed area of (a, b, p): > 0 when p is left of a -> b in picture coordinates
/// (y down), i.e. clockwise on screen.
inline float edge(float ax, float ay, float bx, float by, float px, float py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

}  // namespace

MeshRenderer::MeshRenderer() : srgb_(kSrgbSteps + 1) {
    for (int i = 0; i <= kSrgbSteps; ++i)
        srgb_[std::size_t(i)] = std::uint8_t(std::lround(255.0f * srgbOf(float(i) / float(kSrgbSteps))));
}

void MeshRenderer::render(const Mesh& mesh, const ViewCamera& camera, std::span<std::uint8_t> rgba, int imageWidth, int x0,
                          int y0) {
    const int w = camera.width, h = camera.height;
    if (w <= 0 || h <= 0 || x0 < 0 || y0 < 0 || imageWidth < x0 + w ||
        rgba.size() < (std::size_t(y0 + h) * std::size_t(imageWidth)) * 4)
        throw std::invalid_argument("MeshRenderer::render: the picture does not fit in the image");
    const bool coloured = !mesh.materials.empty();
    if (coloured && mesh.triangleMaterials.size() != mesh.triangles.size())
        throw std::invalid_argument("MeshRenderer::render: not one material per triangle");
    for (const auto& t : mesh.triangles)
        if (t[0] >= mesh.vertices.size() || t[1] >= mesh.vertices.size() || t[2] >= mesh.vertices.size())
            throw std::invalid_argument("MeshRenderer::render: a triangle indexes past the vertices");
    for (std::uint32_t m : mesh.triangleMaterials)
        if (m >= mesh.materials.size()) throw std::invalid_argument("MeshRenderer::render: a triangle indexes past the materials");

    constexpr int ss = kSupersample;
    const int sw = w * ss, sh = h * ss;
    const std::size_t samples = std::size_t(sw) * std::size_t(sh);
    depth_.assign(samples, std::numeric_limits<float>::infinity());
    surface_.assign(samples, kNone);
    shade_.resize(mesh.triangles.size());
    projected_.resize(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::vec3 p = camera.project(mesh.vertices[i]);
        projected_[i] = {p.x * float(ss), p.y * float(ss), p.z};
    }
    albedo_.resize(mesh.materials.size());
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const MeshMaterial& mat = mesh.materials[m];
        albedo_[m] = mat.color;
        if (mat.texture >= 0 && std::size_t(mat.texture) < mesh.textures.size())
            if (const auto mean = pngMeanColour(mesh.textures[std::size_t(mat.texture)].png))
                albedo_[m] *= glm::vec3((*mean)[0], (*mean)[1], (*mean)[2]);
    }
    auto world = [&](const glm::vec3& d) { return glm::normalize(d.x * camera.right + d.y * camera.up + d.z * camera.toward); };
    const glm::vec3 key = world(kKeyDirection), fill = world(kFillDirection);

    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        glm::vec3 a = projected_[tri[0]], b = projected_[tri[1]], c = projected_[tri[2]];
        if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z)) continue;
        float area = edge(a.x, a.y, b.x, b.y, c.x, c.y);
        if (area == 0.0f) continue;
        if (area < 0.0f) {  // seen from behind: draw it from this side too
            std::swap(b, c);
            area = -area;
        }
        // The samples whose centres (x + 0.5, y + 0.5) lie in the triangle's bounding box.
        const float fx0 = std::max(0.0f, std::ceil(std::min({a.x, b.x, c.x}) - 0.5f));
        const float fx1 = std::min(float(sw - 1), std::floor(std::max({a.x, b.x, c.x}) - 0.5f));
        const float fy0 = std::max(0.0f, std::ceil(std::min({a.y, b.y, c.y}) - 0.5f));
        const float fy1 = std::min(float(sh - 1), std::floor(std::max({a.y, b.y, c.y}) - 0.5f));
        if (!(fx0 <= fx1 && fy0 <= fy1)) continue;
        const int minX = int(fx0), maxX = int(fx1), minY = int(fy0), maxY = int(fy1);

        const glm::vec3 &wa = mesh.vertices[tri[0]], &wb = mesh.vertices[tri[1]], &wc = mesh.vertices[tri[2]];
        glm::vec3 n = glm::cross(wb - wa, wc - wa);
        const float len = glm::length(n);
        n = len > 0.0f && std::isfinite(len) ? n / len : camera.toward;
        if (glm::dot(n, camera.toward) < 0.0f) n = -n;
        const glm::vec3 albedo = coloured ? albedo_[mesh.triangleMaterials[t]] : kNeutralColour;
        const float light = kAmbient + kKey * std::max(0.0f, glm::dot(n, key)) + kFill * std::max(0.0f, glm::dot(n, fill));
        shade_[t] = glm::min(albedo * light, glm::vec3(1.0f));

        const float inv = 1.0f / area, dzb = (b.z - a.z) * inv, dzc = (c.z - a.z) * inv;
        for (int y = minY; y <= maxY; ++y) {
            const float py = float(y) + 0.5f;
            std::size_t at = std::size_t(y) * std::size_t(sw) + std::size_t(minX);
            for (int x = minX; x <= maxX; ++x, ++at) {
                const float px = float(x) + 0.5f;
                const float wA = edge(b.x, b.y, c.x, c.y, px, py);
                const float wB = edge(c.x, c.y, a.x, a.y, px, py);
                const float wC = edge(a.x, a.y, b.x, b.y, px, py);
                if (wA < 0.0f || wB < 0.0f || wC < 0.0f) continue;
                const float z = a.z + wB * dzb + wC * dzc;
                if (z < depth_[at]) {
                    depth_[at] = z;
                    surface_[at] = std::uint32_t(t);
                }
            }
        }
    }

    // Resolve: average each pixel's samples in linear light, then encode as sRGB.
    const float scale = float(kSrgbSteps) / float(ss * ss);
    for (int y = 0; y < h; ++y) {
        std::uint8_t* out = rgba.data() + (std::size_t(y0 + y) * std::size_t(imageWidth) + std::size_t(x0)) * 4;
        for (int x = 0; x < w; ++x, out += 4) {
            glm::vec3 sum(0.0f);
            for (int sy = 0; sy < ss; ++sy)
                for (int sx = 0; sx < ss; ++sx) {
                    const std::uint32_t s = surface_[std::size_t(y * ss + sy) * std::size_t(sw) + std::size_t(x * ss + sx)];
                    sum += s == kNone ? kBackground : shade_[s];
                }
            for (int ch = 0; ch < 3; ++ch)
                out[ch] = srgb_[std::size_t(std::clamp(int(sum[ch] * scale + 0.5f), 0, kSrgbSteps))];
            out[3] = 255;
        }
    }
}

}  // namespace shapevo
