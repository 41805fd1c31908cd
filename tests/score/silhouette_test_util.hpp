// Shared by the silhouette tests: the brute-force point-in-hull reference, random primitives
// and scenes (one camera of each kind), a concave test mesh and random targets.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "genome/random.hpp"
#include "score/image/camera.hpp"
#include "score/image/silhouette_raster.hpp"

#include "random_primitives.hpp"

namespace shapevo::test {

using Mask = std::vector<std::uint8_t>;

/// A 160 x 120 perspective camera that sees the whole of test::kSmallTree's trees.
inline Camera smallTreeCamera() {
    CameraSpec s;
    s.width = 160, s.height = 120;
    s.eye = {0.0, 1.5, 9.0}, s.lookAt = {0.0, 1.5, 0.0};
    return Camera::compile(s, "test");
}

inline std::int64_t orient(FixedPoint o, FixedPoint a, FixedPoint b) {
    return (std::int64_t(a.x) - o.x) * (std::int64_t(b.y) - o.y) - (std::int64_t(a.y) - o.y) * (std::int64_t(b.x) - o.x);
}

struct BruteStats {
    long onBoundary = 0;  ///< covered pixel centres exactly on a supporting line
    long onSlanted = 0;   ///< ... on one that is neither horizontal nor vertical
};

using Line = std::pair<FixedPoint, FixedPoint>;

/// Every line through two of the points that has all points on its left or on it, and whether
/// the points span an area. A point is in their closed convex hull exactly when it is on the
/// left of or on every such line (needs the area).
inline bool supportingLines(const std::vector<FixedPoint>& pts, std::vector<Line>& lines) {
    lines.clear();
    const std::size_t n = pts.size();
    bool area = false;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            if (pts[i] == pts[j]) continue;
            bool allLeft = true;
            for (std::size_t k = 0; k < n && allLeft; ++k) {
                const std::int64_t o = orient(pts[i], pts[j], pts[k]);
                if (o != 0) area = true;
                allLeft = o >= 0;
            }
            if (allLeft) lines.push_back({pts[i], pts[j]});
        }
    return area;
}

/// OR the pixels whose centres lie in the closed convex hull of `pts` into `mask` (zero area: none).
inline void bruteForcePiece(const std::vector<FixedPoint>& pts, int width, int height, Mask& mask, BruteStats& stats) {
    std::vector<Line> lines;
    const bool area = supportingLines(pts, lines);
    if (!area) return;
    std::int64_t x0 = INT64_MAX, x1 = INT64_MIN, y0 = INT64_MAX, y1 = INT64_MIN;
    for (const FixedPoint& p : pts) {
        x0 = std::min<std::int64_t>(x0, p.x), x1 = std::max<std::int64_t>(x1, p.x);
        y0 = std::min<std::int64_t>(y0, p.y), y1 = std::max<std::int64_t>(y1, p.y);
    }
    // pixel i has its centre at 256 i + 128; only centres inside the bounding box can be inside
    const std::int64_t i0 = std::max<std::int64_t>(0, (x0 - 128) / 256 - 1), i1 = std::min<std::int64_t>(width - 1, (x1 - 128) / 256 + 1);
    const std::int64_t j0 = std::max<std::int64_t>(0, (y0 - 128) / 256 - 1), j1 = std::min<std::int64_t>(height - 1, (y1 - 128) / 256 + 1);
    for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t i = i0; i <= i1; ++i) {
            const FixedPoint c{std::int32_t(256 * i + 128), std::int32_t(256 * j + 128)};
            bool inside = true, edge = false, slanted = false;
            for (const auto& [a, b] : lines) {
                const std::int64_t o = orient(a, b, c);
                if (o < 0) {
                    inside = false;
                    break;
                }
                edge = edge || o == 0;
                slanted = slanted || (o == 0 && a.x != b.x && a.y != b.y);
            }
            if (inside) {
                mask[std::size_t(j) * std::size_t(width) + std::size_t(i)] = 1;
                stats.onBoundary += edge;
                stats.onSlanted += slanted;
            }
        }
}

inline void bruteForce(const Primitive& p, const std::vector<MeshShape>& meshes, OutlineBuilder& builder, int width, int height,
                Mask& mask, BruteStats& stats) {
    Outline outline;
    builder.add(p, &meshes, outline);
    for (const OutlinePiece& piece : outline.pieces) {
        const std::vector<FixedPoint> pts(outline.points.begin() + piece.first, outline.points.begin() + piece.first + piece.count);
        bruteForcePiece(pts, width, height, mask, stats);
    }
}

/// A closed, concave mesh in unit coordinates: a five-pointed star extruded along y.
inline std::vector<MeshShape> starMesh() {
    MeshShape m;
    m.path = "star";
    for (int y : {-1, 1}) {
        m.vertices.push_back({0.0f, float(y), 0.0f});
        for (int k = 0; k < 10; ++k) {
            const double a = M_PI * k / 5.0, r = k % 2 ? 0.4 : 1.0;
            m.vertices.push_back({float(r * std::cos(a)), float(y), float(r * std::sin(a))});
        }
    }
    for (std::uint32_t k = 0; k < 10; ++k) {
        const std::uint32_t a = 1 + k, b = 1 + (k + 1) % 10;
        m.triangles.push_back({0, b, a});            // bottom cap
        m.triangles.push_back({11, 11 + a, 11 + b});  // top cap
        m.triangles.push_back({a, b, 11 + b});        // side
        m.triangles.push_back({a, 11 + b, 11 + a});
    }
    return {m};
}

struct Scene {
    const char* name;
    CameraSpec spec;
    glm::dvec3 centre;  ///< where the camera looks: primitives are placed around it
    double extent;      ///< half size of the region primitives are placed in
    glm::dvec3 nearPoint;  ///< a point on the near plane / the ground, for crossing primitives
};

inline std::vector<Scene> scenes() {
    std::vector<Scene> s;
    CameraSpec p;
    p.width = 200, p.height = 150;
    p.eye = {6.0, 5.0, 7.0}, p.lookAt = {0.0, 0.5, 0.0}, p.up = {0.1, 1.0, 0.0}, p.fovDegrees = 50.0, p.near = 0.5;
    const glm::dvec3 f = glm::normalize(p.lookAt - p.eye);
    s.push_back({"perspective", p, p.lookAt, 6.0, p.eye + p.near * f});
    CameraSpec o = p;
    o.projection = Projection::Orthographic;
    o.viewHeight = 9.0;
    s.push_back({"orthographic", o, o.lookAt, 6.0, o.eye + o.near * f});
    CameraSpec h;
    h.projection = Projection::Shadow;
    h.width = 200, h.height = 150;
    h.light = {0.4, -1.0, 0.3}, h.groundY = -2.0, h.groundMin = {-6.0, -6.0}, h.groundMax = {6.0, 6.0};
    s.push_back({"shadow", h, {0.0, 0.0, 0.0}, 6.0, {0.0, -2.0, 0.0}});
    return s;
}

inline Primitive randomPrimitive(PrimitiveKind kind, const Scene& scene, Rng& rng) {
    Primitive p;
    p.kind = kind;
    const int style = int(rng.below(10));
    glm::dvec3 c = scene.centre;
    for (int k = 0; k < 3; ++k) c[k] += scene.extent * (2.0 * rng.uniform() - 1.0);
    if (style == 0) c = scene.nearPoint + 1.5 * glm::dvec3(rng.normal(), rng.normal(), rng.normal());  // crosses the plane
    if (style == 1) c.x += (rng.below(2) ? 1 : -1) * 3.0 * scene.extent;                              // mostly off-screen
    p.centre = glm::vec3(c);
    for (int k = 0; k < 3; ++k) p.half[k] = float(0.02 * std::pow(150.0, rng.uniform()));  // 0.02 .. 3
    if (style == 2) p.half[int(rng.below(3))] = 0.0f;                                       // flat
    if (style == 3) p.half *= 20.0f;                                                         // huge: reaches the guard band
    p.axes = style == 4 ? glm::mat3(1.0f) : randomRotation(rng);
    if (rng.below(4) == 0) p.axes[int(rng.below(3))] *= -1.0f;  // mirrored
    const std::uint32_t t = rng.below(10);
    const float taper = t == 0 ? 0.0f : t == 1 ? 1.0f : float(rng.uniform());
    float taperZ = 1.0f;
    if (kind == PrimitiveKind::Roof) {  // drawn last: the other kinds' draws stay as they were
        const std::uint32_t tz = rng.below(10);
        taperZ = tz == 0 ? 0.0f : tz == 1 ? 1.0f : tz == 2 ? taper : float(rng.uniform());  // 2: a square frustum
    }
    setKindParams(p, taper, taperZ, 0);
    return p;
}


/// Pixel-centre distance (fixed-point units) to the nearest supporting line.
inline double distanceToBoundary(const std::vector<Line>& lines, FixedPoint c) {
    double best = 1e300;
    for (const auto& [a, b] : lines) {
        const double len = std::hypot(double(b.x) - a.x, double(b.y) - a.y);
        best = std::min(best, std::fabs(double(orient(a, b, c))) / len);
    }
    return best;
}

inline ImageTarget randomTarget(int width, int height, Rng& rng) {
    std::vector<std::uint8_t> lum(std::size_t(width) * height), alpha(lum.size(), 255);
    for (std::size_t i = 0; i < lum.size(); ++i) {
        const double u = rng.uniform();
        lum[i] = u < 0.4 ? 0 : u < 0.8 ? 255 : 128;
        alpha[i] = u < 0.9 ? 255 : 0;
    }
    PixelRule rule;
    rule.hitMax = 100, rule.avoidMin = 200;  // 128 = don't care
    return makeImageTarget(width, height, lum, alpha, rule);
}

}  // namespace shapevo::test
