// Silhouette outlines: the projected points whose convex hulls make up a primitive's silhouette.
// This is the definition of "covered" for image targets; the rasterizer (silhouette_raster.hpp)
// and the brute-force reference in the tests both start from these points.
//
// A primitive's silhouette is the union of the convex hulls of its pieces. Points are snapped
// to fixed point, 1/256 pixel (FixedPoint), so everything after the snap is exact integer
// arithmetic: a pixel (i, j) is covered when its centre (256 i + 128, 256 j + 128) lies in the
// closed hull of a piece; a hull of zero area covers nothing.
//  - Box: one piece, its 8 corners.
//  - Cylinder, Cone: one piece, the vertices of the kRoundSides-gon prism / frustum (rings at
//    u.y = -1 and +1, vertices at angles 2 pi k / kRoundSides from +x towards +z; the top ring
//    has radius `taper`, clamped to [0, 1]), or the ring and the apex for a pointed cone (taper 0).
//    Of a box's, cylinder's or cone's vertices only the silhouette vertices are kept: those
//    where a face turned towards the eye (or the light) meets a face turned away; a face exactly
//    edge-on counts as both. In exact arithmetic they span the same hull as all vertices; after
//    rounding the hulls can differ only within rounding error of the outline. A primitive that is
//    cut (below), reaches beyond the guard band, or is flat (a half extent of 0) keeps all of its
//    vertices.
//  - Sphere: one piece, 2 * kRoundSides points on the ellipsoid's contact curve (where the rays
//    from the eye, or the parallel rays, graze it), evenly spaced in the ellipsoid's own unit
//    sphere frame: a polygon inscribed in the exact outline (about 0.6 % less area). A sphere that
//    is cut by the near plane / the ground, or that is flat (a half extent of 0), is drawn as its
//    UV polyhedron instead: kRoundSides meridians, kRoundSides / 2 latitude bands.
//  - Level of detail: a ring that projects small is drawn with every 2nd or every 4th of its
//    corners (8 or 4 instead of kRoundSides = 16; the sphere's contact curve with 16 or 8 of its 32
//    points): the fewest that keep the polygon within 1/4 pixel of the full one. The ring's pixel
//    radius is bounded by projectedRadius() below; 8 corners lie within 0.0761 radius of the
//    16-gon, 4 within 0.293 (the sphere: 16 points within 0.0192, 8 within 0.0761 of the circle).
//    The fewer corners are a subset of the full ones, so the drawn polygon lies inside the full
//    one. Primitives that take the cut or guard-band path keep every corner.
//  - Roof: one piece, its 8 corners (the top ones scaled by taper along x and taperZ along z,
//    clamped to [0, 1]; corners coincide for a ridge or an apex). Equal fractions are a square
//    frustum (or pyramid) and keep only the silhouette vertices, like a box.
//  - Paraboloid: one piece, the kParaboloidRings * kRoundSides + 1 vertices of its inscribed
//    polyhedron (rings at u.y = -1, -1/8, 1/2, 7/8 and the apex: shape/kinds/paraboloid.hpp),
//    always all of them and at full detail.
//  - Mesh: one piece per triangle of its mesh (Geometry::meshes, the index in MeshKind::Params; all
//    triangles, front or back).
// Each kind's part (which pieces, which fast path) is its K::outline in shape/kinds/<kind>.hpp.
// Cut by the near plane (the ground for shadows): a convex piece becomes the part in front,
// whose vertices are its vertices in front plus the points where its edges cross the plane.
// Guard band: points more than kGuardBand pixels beyond the picture's edges would overflow the
// fixed-point range, so a piece reaching that far is clipped to the guard rectangle first (in
// double precision); nothing inside the picture changes.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "score/image/camera.hpp"
#include "shape/kinds.hpp"
#include "shape/outline.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// Builds outlines for one camera; holds the unit shapes and scratch space (no allocation once warm).
/// Which pieces a primitive is drawn with is its kind's `outline` (shape/kinds/*.hpp, called with
/// static dispatch from addPrepared); the builder gives it the services below "for the kinds",
/// and keeps one K::OutlineScratch for each kind that declares one (scratch<K>()).
class OutlineBuilder {
public:
    explicit OutlineBuilder(const Camera& camera);
    /// Append the pieces of p's silhouette to `out` (nothing for a primitive with non-finite
    /// numbers or a Mesh primitive without its mesh).
    void add(const Primitive& p, const std::vector<MeshShape>* meshes, Outline& out) {
        if (prepare(p, meshes)) addPrepared(out);
    }
    /// The same in steps: prepare p (false: it draws nothing: numbers not finite, or a Mesh
    /// primitive without its mesh; p and meshes must stay alive until addPrepared), then
    /// optionally ask for its bound, then add its pieces.
    bool prepare(const Primitive& p, const std::vector<MeshShape>* meshes);
    /// Pixel centres the prepared primitive's outline can cover at most: columns x0..x1, rows
    /// y0..y1, clamped to the picture (empty if x0 > x1 or y0 > y1): the projected corners of its
    /// box u in [-1, 1]^3 with a margin of 1/64 pixel. False (no bound) if a corner is behind the
    /// clip plane.
    bool coverBound(int& x0, int& x1, int& y0, int& y1) const;
    void addPrepared(Outline& out);
    const Camera& camera() const { return camera_; }

    struct Homogeneous {
        double x, y, w, clip;  ///< homogeneous pixel coordinates and the signed clip distance
    };
    /// An upper bound on how far (in pixels) the points c + cos(t) a + sin(t) b of an ellipse in
    /// homogeneous coordinates project from the projection of c: |J a|, |J b| with J the
    /// projection's derivative at c, over the least w on the ellipse. Infinity if w varies by
    /// half or more over it (then no level of detail applies) or the numbers are not finite.
    static double projectedRadius(const Homogeneous& c, const Homogeneous& a, const Homogeneous& b);
    /// Ring corners (kRoundSides >> level) or sphere contact-curve points the last round primitive
    /// given to addPrepared was drawn with; 0 after boxes and meshes and on the cut path.
    int lastRoundPoints() const { return lastRoundPoints_; }
    using UnitShape = shapevo::UnitShape;  ///< shape/outline.hpp

    /// A ring of a box / prism / frustum: radius-1 corners (x, z) in cyclic order and the outward
    /// normals (x, z) of the side faces between corners k and k + 1.
    struct RingTable {
        std::vector<glm::dvec2> corners, normals;
        double apothem = 1.0;  ///< distance of the side faces from the axis
        double reach = 1.0;    ///< largest distance of a corner from the axis
    };

    // ---- For the kinds' outline code (shape/kinds/*.hpp) -------------------------------------
    /// Local -> homogeneous map of one primitive: h = m * (u, 1).
    struct LocalMap {
        double m[4][4];  ///< rows: x, y, w, clip
        Homogeneous apply(const glm::dvec3& u) const;
    };
    /// The eye in the primitive's local coordinates, homogeneous: (e, 1) for a perspective
    /// camera, (e, 0) with e along the rays for parallel ones. False if the frame is degenerate.
    bool localEye(const LocalMap& map, glm::dvec3& e, double& ew) const;
    /// Silhouette vertices of a two-ring shape (bottom ring radius 1 at u.y = -1, top ring radius
    /// topScale at u.y = 1; topScale 0: an apex), in loop order. `table` null: a round ring, its
    /// level of detail chosen by size. False (nothing added) if the shape reaches behind the clip
    /// plane or beyond the guard band, or the frame is degenerate.
    bool addRingsFast(const LocalMap& map, const RingTable* table, double topScale, Outline& out);
    /// One piece: all vertices of `shape`, cut by the clip plane along its edges if needed.
    void addConvex(const LocalMap& map, const UnitShape& shape, Outline& out);
    /// Points with clip >= 0, already cut: project, hull, clip to the guard band, snap, append.
    void addClippedPiece(const Homogeneous* h, std::size_t n, bool convexCycle, Outline& out);
    bool insideGuard(double x, double y) const {
        return x >= -kGuardBand && x <= width_ + kGuardBand && y >= -kGuardBand && y <= height_ + kGuardBand;
    }
    void setLastRoundPoints(int points) { lastRoundPoints_ = points; }
    /// The meshes given to prepare() (a Mesh primitive's mesh is there: prepare checked it).
    const std::vector<MeshShape>* preparedMeshes() const { return meshes_; }
    /// Unit shapes: the box (bottom ring at vertices 0 .. 3, top ring 4 .. 7); the kRoundSides-gon
    /// prism (bottom ring 0 .. kRoundSides - 1, then the top ring) and pyramid; the UV sphere
    /// (kRoundSides meridians, kRoundSides / 2 bands); the square ring of a box; (cos, sin) of the
    /// kSphereSides contact-curve angles. All are ready when the kinds' OutlineScratch is built.
    const UnitShape& boxShape() const { return box_; }
    const UnitShape& prismShape() const { return prism_; }
    const UnitShape& pyramidShape() const { return pyramid_; }
    const UnitShape& uvSphereShape() const { return uvSphere_; }
    const RingTable& squareRing() const { return squareRing_; }
    const std::vector<glm::dvec2>& sphereRing() const { return sphereRing_; }
    /// A round unit shape: kRoundSides-gon rings at the given (radius, u.y), each joined to the
    /// next, the corners at angles 2 pi k / kRoundSides from +x towards +z; then loose points, each
    /// joined to every corner of the ring given with it (an apex, a pole).
    static UnitShape roundShape(const std::vector<glm::dvec2>& rings, const std::vector<std::pair<glm::dvec3, int>>& loose);
    /// Kind K's own silhouette state (K::OutlineScratch, built once with this builder; shape/kinds.hpp).
    template <class K>
    auto& scratch() {
        return outlineScratch<K>(kindScratch_);
    }
    /// Reusable scratch: homogeneous points; per mesh vertex its snapped point and whether it is
    /// in front and inside the guard band.
    std::vector<Homogeneous>& homogeneousScratch() { return h_; }
    std::vector<FixedPoint>& snappedScratch() { return snapped_; }
    std::vector<std::uint8_t>& fastScratch() { return fast_; }

private:
    bool localMap(const Primitive& p, LocalMap& map) const;  ///< false if not finite

    const Camera& camera_;
    double width_, height_;
    LocalMap map_;                              ///< of the prepared primitive
    const Primitive* prepared_ = nullptr;
    const std::vector<MeshShape>* meshes_ = nullptr;
    int lastRoundPoints_ = 0;
    UnitShape box_, prism_, pyramid_, uvSphere_;
    RingTable squareRing_;
    std::array<RingTable, kRoundLevels> roundRings_;  ///< kRoundSides >> level corners
    std::vector<glm::dvec2> sphereRing_;  ///< (cos, sin) of the kSphereSides contact-curve angles
    KindOutlineScratch kindScratch_;      ///< built from *this: declared after the shapes above
    std::vector<Homogeneous> h_, cut_;
    std::vector<glm::dvec2> xy_, hull_, clipped_;
    std::vector<FixedPoint> snapped_;   ///< mesh vertices, snapped once per primitive
    std::vector<glm::dvec3> loop_;      ///< silhouette vertices (u) in loop order
    std::vector<std::uint8_t> fast_;    ///< mesh vertices: in front and inside the guard band
};

}  // namespace shapevo
