// Texture UVs: planar and cylindrical mapping in a texture frame (see texture_uv.hpp).
#include "geometry/texture_uv.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include <glm/glm.hpp>

#include "shape/kinds.hpp"

namespace shapevo {

namespace {

/// 1 / tile, or 0 where the tile length is not a finite positive number.
glm::vec3 inverseTile(const glm::vec3& tile) {
    glm::vec3 inv(0.0f);
    for (int a = 0; a < 3; ++a)
        if (tile[a] > 0.0f && tile[a] <= std::numeric_limits<float>::max()) inv[a] = 1.0f / tile[a];
    return inv;
}

float sign(float x) { return x < 0.0f ? -1.0f : 1.0f; }

/// Whether p's kind is round (it has K::textureRadius), and then its mean radius in world units.
bool roundRadius(const Primitive& p, float& radius) {
    return visitKind(p.kind, [&](auto tag) {
        using K = typename decltype(tag)::type;
        if constexpr (requires { K::textureRadius(p); }) {
            radius = K::textureRadius(p);
            return true;
        } else {
            return false;
        }
    });
}

std::uint32_t bits(float f) {
    f += 0.0f;  // -0 -> +0
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

}  // namespace

glm::vec2 planarUv(const TextureFrame& frame, const glm::vec3& n, const glm::vec3& p) {
    const glm::vec3 inv = inverseTile(frame.tile);
    const glm::vec3 d = p - frame.origin;
    const glm::vec3 &ax = frame.axes[0], &ay = frame.axes[1], &az = frame.axes[2];
    const float nx = glm::dot(n, ax), ny = glm::dot(n, ay), nz = glm::dot(n, az);
    const float fx = std::fabs(nx), fy = std::fabs(ny), fz = std::fabs(nz);
    if (fz >= fx && fz >= fy) return {sign(nz) * glm::dot(d, ax) * inv.x, glm::dot(d, ay) * inv.y};
    if (fx >= fy) return {-sign(nx) * glm::dot(d, az) * inv.z, glm::dot(d, ay) * inv.y};
    return {glm::dot(d, ax) * inv.x, -sign(ny) * glm::dot(d, az) * inv.z};
}

void applyTextureUv(const Primitive& p, const TextureFrame& frame, std::uint32_t firstVertex, std::size_t firstTriangle,
                    Mesh& mesh) {
    if (mesh.uvs.size() != firstVertex || firstVertex > mesh.vertices.size() || firstTriangle > mesh.triangles.size())
        throw std::invalid_argument("applyTextureUv: the mesh's UVs do not end where the primitive begins");
    const glm::vec3 inv = inverseTile(frame.tile);
    const std::vector<glm::vec3> own(mesh.vertices.begin() + firstVertex, mesh.vertices.end());
    mesh.vertices.resize(firstVertex);
    // The primitive's axis for the cylindrical mapping, turned towards the frame's y axis.
    float radius = 0.0f;
    const bool round = roundRadius(p, radius);
    glm::vec3 w = p.axes[1];
    if (glm::dot(w, frame.axes[1]) < 0.0f) w = -w;
    const glm::vec3 e1 = p.axes[0], e2 = glm::cross(w, e1);
    const float onAxis = 1e-5f * radius;
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::uint32_t> index;
    for (std::size_t t = firstTriangle; t < mesh.triangles.size(); ++t) {
        auto& tri = mesh.triangles[t];
        glm::vec3 q[3];
        for (int k = 0; k < 3; ++k) q[k] = own.at(tri[k] - firstVertex);
        const glm::vec3 cross = glm::cross(q[1] - q[0], q[2] - q[0]);
        const float length = glm::length(cross);
        const glm::vec3 n = length > 0.0f ? cross / length : glm::vec3(0.0f);
        glm::vec2 uv[3];
        if (round && length > 0.0f && std::fabs(glm::dot(n, w)) < std::numbers::sqrt2_v<float> * 0.5f) {
            const auto angle = [&](const glm::vec3& r) { return std::atan2(glm::dot(r, e2), glm::dot(r, e1)); };
            const float reference = angle((q[0] + q[1] + q[2]) / 3.0f - p.centre);
            float phi[3], sum = 0.0f;
            bool axial[3];
            int off = 0;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 r = q[k] - p.centre;
                axial[k] = glm::length(r - glm::dot(r, w) * w) <= onAxis;
                phi[k] = angle(r);
                const float pi = std::numbers::pi_v<float>;
                while (phi[k] - reference > pi) phi[k] -= 2.0f * pi;
                while (phi[k] - reference < -pi) phi[k] += 2.0f * pi;
                if (!axial[k]) sum += phi[k], ++off;
            }
            for (int k = 0; k < 3; ++k) {
                if (axial[k]) phi[k] = off > 0 ? sum / float(off) : reference;
                uv[k] = {phi[k] * radius * inv.x, glm::dot(q[k] - frame.origin, w) * inv.y};
            }
        } else {
            for (int k = 0; k < 3; ++k) uv[k] = planarUv(frame, n, q[k]);
        }
        for (int k = 0; k < 3; ++k) {
            const auto key = std::make_tuple(tri[k], bits(uv[k].x), bits(uv[k].y));
            auto [at, added] = index.try_emplace(key, std::uint32_t(mesh.vertices.size()));
            if (added) {
                mesh.vertices.push_back(q[k]);
                mesh.uvs.push_back(uv[k]);
            }
            tri[k] = at->second;
        }
    }
}

}  // namespace shapevo
