// Silhouette outlines: the builder's unit shapes (a kind's own live in its K::OutlineScratch, built
// here once per builder), the local -> pixel map of a primitive, the fast path (every point in
// front and inside the guard band: project and snap) and the cut path (near plane / ground, then
// the guard band, in double precision) for convex pieces and mesh triangles.
#include "score/image/silhouette_outline.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shape/kinds.hpp"

namespace shapevo {

namespace {

using UnitShape = OutlineBuilder::UnitShape;
using Homogeneous = OutlineBuilder::Homogeneous;

/// Rings of `table` points (x, z) at the given (radius, y), joined ring to ring, plus loose
/// points joined to every point of one ring (the apex / poles).
UnitShape ringShape(const std::vector<glm::dvec2>& table, const std::vector<glm::dvec2>& rings,
                    const std::vector<std::pair<glm::dvec3, int>>& loose) {
    UnitShape s;
    const int n = int(table.size());
    s.rings = std::uint16_t(rings.size());
    s.ringSize = std::uint16_t(n);
    for (const glm::dvec2& ring : rings)
        for (const glm::dvec2& t : table) s.vertices.push_back({ring.x * t.x, ring.y, ring.x * t.y});
    auto edge = [&s](int a, int b) {
        s.edges.push_back(std::uint16_t(a));
        s.edges.push_back(std::uint16_t(b));
    };
    for (int r = 0; r < int(rings.size()); ++r)
        for (int k = 0; k < n; ++k) {
            edge(r * n + k, r * n + (k + 1) % n);
            if (r + 1 < int(rings.size())) edge(r * n + k, (r + 1) * n + k);
        }
    for (const auto& [point, ring] : loose) {
        const int index = int(s.vertices.size());
        s.vertices.push_back(point);
        for (int k = 0; k < n; ++k) edge(index, ring * n + k);
    }
    return s;
}

std::vector<glm::dvec2> roundTable(int sides) {
    std::vector<glm::dvec2> t;
    for (int k = 0; k < sides; ++k) {
        const double a = 2.0 * M_PI * k / sides;
        t.push_back({std::cos(a), std::sin(a)});
    }
    return t;
}

std::vector<glm::dvec2> squareTable() { return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; }

/// The UV sphere: kRoundSides meridians, kRoundSides / 2 latitude bands, and the poles.
UnitShape uvSphere() {
    std::vector<glm::dvec2> latitudes;
    const int bands = kRoundSides / 2;
    for (int j = 1; j < bands; ++j) latitudes.push_back({std::sin(M_PI * j / bands), -std::cos(M_PI * j / bands)});
    return ringShape(roundTable(kRoundSides), latitudes, {{{0, -1, 0}, 0}, {{0, 1, 0}, bands - 2}});
}

OutlineBuilder::RingTable squareRingTable() {
    OutlineBuilder::RingTable t;
    t.corners = squareTable();
    t.normals = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    t.apothem = 1.0;
    t.reach = std::sqrt(2.0);
    return t;
}

/// The round rings' levels of detail: 16, 8, 4 corners (every 1st, 2nd, 4th).
std::array<OutlineBuilder::RingTable, kRoundLevels> roundRingTables() {
    const std::vector<glm::dvec2> round = roundTable(kRoundSides);
    std::array<OutlineBuilder::RingTable, kRoundLevels> tables;
    for (int level = 0; level < kRoundLevels; ++level) {
        const int sides = kRoundSides >> level;
        OutlineBuilder::RingTable& t = tables[std::size_t(level)];
        for (int k = 0; k < sides; ++k) {
            t.corners.push_back(round[std::size_t(k << level)]);
            const double a = 2.0 * M_PI * (k + 0.5) / sides;
            t.normals.push_back({std::cos(a), std::sin(a)});
        }
        t.apothem = std::cos(M_PI / sides);
        t.reach = 1.0;
    }
    return tables;
}

/// Convex hull (counter-clockwise) of points in double precision; a pre-step only: the exact
/// hull is taken again after snapping.
void doubleHull(std::vector<glm::dvec2>& pts, std::vector<glm::dvec2>& hull) {
    std::sort(pts.begin(), pts.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    hull.resize(2 * pts.size() + 1);
    auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k > 1 ? k - 1 : k);
}

/// Sutherland-Hodgman: keep the side of the line coordinate[axis] = bound given by `below`.
void clipPolygon(const std::vector<glm::dvec2>& in, std::vector<glm::dvec2>& out, int axis, double bound, bool below) {
    out.clear();
    const std::size_t n = in.size();
    auto inside = [&](const glm::dvec2& p) { return below ? p[axis] <= bound : p[axis] >= bound; };
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2& p = in[i];
        const glm::dvec2& q = in[(i + 1) % n];
        const bool pin = inside(p), qin = inside(q);
        if (pin) out.push_back(p);
        if (pin != qin) {
            const double t = (bound - p[axis]) / (q[axis] - p[axis]);
            glm::dvec2 c = p + (q - p) * t;
            c[axis] = bound;
            out.push_back(c);
        }
    }
}

}  // namespace

OutlineBuilder::Homogeneous OutlineBuilder::LocalMap::apply(const glm::dvec3& u) const {
    double r[4];
    for (int k = 0; k < 4; ++k) r[k] = m[k][0] * u.x + m[k][1] * u.y + m[k][2] * u.z + m[k][3];
    return {r[0], r[1], r[2], r[3]};
}

double OutlineBuilder::projectedRadius(const Homogeneous& c, const Homogeneous& a, const Homogeneous& b) {
    // p(t) - p(c) = (dx - p(c) dw) / (c.w + dw) with (dx, dw) = cos t (a.x, a.w) + sin t (b.x, b.w):
    // the numerator is at most the Frobenius norm of [J a, J b] times c.w, |dw| at most rho.
    const double rho = std::sqrt(a.w * a.w + b.w * b.w);
    if (!(c.w > 2.0 * rho)) return INFINITY;  // (NaN too)
    const double px = c.x / c.w, py = c.y / c.w;
    const double ax = a.x - px * a.w, ay = a.y - py * a.w, bx = b.x - px * b.w, by = b.y - py * b.w;
    const double r = std::sqrt(ax * ax + ay * ay + bx * bx + by * by) / (c.w - rho);
    return std::isfinite(r) ? r : INFINITY;
}

OutlineBuilder::UnitShape OutlineBuilder::roundShape(const std::vector<glm::dvec2>& rings,
                                                     const std::vector<std::pair<glm::dvec3, int>>& loose) {
    return ringShape(roundTable(kRoundSides), rings, loose);
}

OutlineBuilder::OutlineBuilder(const Camera& camera)
    : camera_(camera),
      width_(camera.width()),
      height_(camera.height()),
      box_(ringShape(squareTable(), {{1, -1}, {1, 1}}, {})),
      prism_(roundShape({{1, -1}, {1, 1}}, {})),
      pyramid_(roundShape({{1, -1}}, {{{0, 1, 0}, 0}})),
      uvSphere_(uvSphere()),
      squareRing_(squareRingTable()),
      roundRings_(roundRingTables()),
      sphereRing_(roundTable(kSphereSides)),
      kindScratch_(makeKindOutlineScratch(*this)) {}

bool OutlineBuilder::localMap(const Primitive& p, LocalMap& map) const {
    // local u -> world: centre + axes * (half * u); world -> homogeneous: camera rows / clip plane
    double a[3][4];  // a[j] = world coordinate j as a function of (u, 1)
    for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) a[j][k] = double(p.axes[k][j]) * double(p.half[k]);
        a[j][3] = p.centre[j];
    }
    const double(*rows)[4] = camera_.rows();
    double sum = 0.0;  // not finite if any entry is not
    for (int r = 0; r < 4; ++r) {
        const double* c = r < 3 ? rows[r] : camera_.clipPlane();
        for (int k = 0; k < 4; ++k) {
            map.m[r][k] = c[0] * a[0][k] + c[1] * a[1][k] + c[2] * a[2][k] + (k == 3 ? c[3] : 0.0);
            sum += map.m[r][k] * 0.0;  // 0 for numbers, NaN for infinities and NaN
        }
    }
    return sum == 0.0;
}

bool OutlineBuilder::prepare(const Primitive& p, const std::vector<MeshShape>* meshes) {
    prepared_ = nullptr;
    if (!hasShapeData(p, meshes)) return false;
    if (!localMap(p, map_)) return false;
    prepared_ = &p;
    meshes_ = meshes;
    return true;
}

bool OutlineBuilder::coverBound(int& x0, int& x1, int& y0, int& y1) const {
    const double(*m)[4] = map_.m;
    // The box u in [-1, 1]^3 holds every kind's points; all of its corners in front?
    if (!(m[3][3] - std::fabs(m[3][0]) - std::fabs(m[3][1]) - std::fabs(m[3][2]) >= 0.0)) return false;
    // The projected corners: homogeneous coordinate r of corner (+-1, +-1, +-1) is
    // m[r][3] +- m[r][2] +- m[r][1] +- m[r][0], built up by sums (bit k of the index: sign of u_k).
    double h[3][8];
    for (int r = 0; r < 3; ++r) {
        h[r][0] = m[r][3] - m[r][2], h[r][4] = m[r][3] + m[r][2];
        for (int k = 0; k < 8; k += 4) h[r][k + 2] = h[r][k] + m[r][1], h[r][k] -= m[r][1];
        for (int k = 0; k < 8; k += 2) h[r][k + 1] = h[r][k] + m[r][0], h[r][k] -= m[r][0];
    }
    double x[8], y[8];
    for (int c = 0; c < 8; ++c) {
        const double inverse = 1.0 / h[2][c];
        x[c] = h[0][c] * inverse, y[c] = h[1][c] * inverse;
    }
    double xmin = x[0], xmax = x[0], ymin = y[0], ymax = y[0];
    for (int c = 1; c < 8; ++c) xmin = std::min(xmin, x[c]), xmax = std::max(xmax, x[c]), ymin = std::min(ymin, y[c]), ymax = std::max(ymax, y[c]);
    if (!(xmin <= xmax && ymin <= ymax)) return false;  // NaN
    // Pixel centres i + 0.5 in [min, max], with a margin far above snapping and rounding errors.
    constexpr double kMargin = 1.0 / 64.0;
    auto first = [](double v, int size) { return int(std::clamp(std::ceil(v - 0.5 - kMargin), 0.0, double(size))); };
    auto last = [](double v, int size) { return int(std::clamp(std::floor(v - 0.5 + kMargin), -1.0, double(size) - 1.0)); };
    x0 = first(xmin, int(width_)), x1 = last(xmax, int(width_));
    y0 = first(ymin, int(height_)), y1 = last(ymax, int(height_));
    return true;
}

void OutlineBuilder::addPrepared(Outline& out) {
    lastRoundPoints_ = 0;
    if (!prepared_) return;
    const Primitive& p = *prepared_;
    visitKind(p.kind, [&](auto kind) { decltype(kind)::type::outline(*this, map_, p, out); });
}

bool OutlineBuilder::localEye(const LocalMap& map, glm::dvec3& e, double& ew) const {
    const glm::dvec3 r0(map.m[0][0], map.m[0][1], map.m[0][2]), r1(map.m[1][0], map.m[1][1], map.m[1][2]);
    if (camera_.parallel()) {
        e = glm::cross(r0, r1);  // the direction the x and y rows do not see
        ew = 0.0;
    } else {
        const glm::dvec3 r2(map.m[2][0], map.m[2][1], map.m[2][2]);
        const glm::dvec3 t(map.m[0][3], map.m[1][3], map.m[2][3]);
        const glm::dvec3 c12 = glm::cross(r1, r2), c20 = glm::cross(r2, r0), c01 = glm::cross(r0, r1);
        const double det = glm::dot(r0, c12);
        e = -(t.x * c12 + t.y * c20 + t.z * c01) / det;  // rows * (e, 1) = 0
        ew = 1.0;
    }
    const double len = glm::length(e);
    return len > 0.0 && std::isfinite(len);
}

void OutlineBuilder::addConvex(const LocalMap& map, const UnitShape& shape, Outline& out) {
    const std::size_t n = shape.vertices.size();
    h_.resize(n);
    bool fast = true;
    for (std::size_t i = 0; i < n; ++i) {
        h_[i] = map.apply(shape.vertices[i]);
        fast = fast && h_[i].clip >= 0.0;
    }
    if (fast) {
        const std::size_t first = out.points.size();
        for (std::size_t i = 0; i < n && fast; ++i) {
            const double x = h_[i].x / h_[i].w, y = h_[i].y / h_[i].w;
            fast = insideGuard(x, y);
            if (fast) out.points.push_back(snapToFixed(x, y));
        }
        if (fast) {
            out.pieces.push_back({std::uint32_t(first), std::uint32_t(n), shape.rings, shape.ringSize});
            return;
        }
        out.points.resize(first);
    }
    // Cut by the clip plane: the vertices in front and the crossings of edges with the plane.
    cut_.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (h_[i].clip >= 0.0) cut_.push_back(h_[i]);
    for (std::size_t e = 0; e < shape.edges.size(); e += 2) {
        const Homogeneous &p = h_[shape.edges[e]], &q = h_[shape.edges[e + 1]];
        if ((p.clip >= 0.0) == (q.clip >= 0.0)) continue;
        const double t = p.clip / (p.clip - q.clip);
        cut_.push_back({p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t, p.w + (q.w - p.w) * t, 0.0});
    }
    addClippedPiece(cut_.data(), cut_.size(), false, out);
}

void OutlineBuilder::addClippedPiece(const Homogeneous* h, std::size_t n, bool convexCycle, Outline& out) {
    if (n == 0) return;
    xy_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        if (!(h[i].w > 0.0)) return;  // cannot happen after the cut (w >= near); guards NaN
        const glm::dvec2 v(h[i].x / h[i].w, h[i].y / h[i].w);
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) return;  // (the sort below needs numbers)
        xy_.push_back(v);
    }
    if (!convexCycle) {
        doubleHull(xy_, hull_);
        xy_.swap(hull_);
    }
    const double lo = -kGuardBand;
    clipPolygon(xy_, clipped_, 0, lo, false);
    clipPolygon(clipped_, xy_, 0, width_ + kGuardBand, true);
    clipPolygon(xy_, clipped_, 1, lo, false);
    clipPolygon(clipped_, xy_, 1, height_ + kGuardBand, true);
    if (xy_.empty()) return;
    const std::size_t first = out.points.size();
    for (const glm::dvec2& v : xy_)  // clamped: clipping leaves points on the bounds up to rounding
        out.points.push_back(snapToFixed(std::clamp(v.x, lo, width_ + kGuardBand), std::clamp(v.y, lo, height_ + kGuardBand)));
    const auto count = std::uint32_t(xy_.size());
    out.pieces.push_back({std::uint32_t(first), count, 1, std::uint16_t(count)});
}

}  // namespace shapevo
