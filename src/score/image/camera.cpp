// Camera: checks on a CameraSpec and the three projections as homogeneous 3x4 rows.
#include "score/image/camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "base/input_error.hpp"

namespace shapevo {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

void setRow(double (&row)[4], const glm::dvec3& a, double d) {
    row[0] = a.x;
    row[1] = a.y;
    row[2] = a.z;
    row[3] = d;
}

}  // namespace

Camera Camera::compile(const CameraSpec& s, const std::string& file, const std::string& section) {
    auto fail = [&](const char* key, const std::string& what) { throw InputError(file, section + "." + key, what); };
    if (s.width < 1 || s.width > 16384) fail("width", std::to_string(s.width) + " is out of range [1, 16384]");
    if (s.height < 1 || s.height > 16384) fail("height", std::to_string(s.height) + " is out of range [1, 16384]");
    Camera c;
    c.projection_ = s.projection;
    c.width_ = s.width;
    c.height_ = s.height;
    const double W = s.width, H = s.height;

    if (s.projection == Projection::Shadow) {
        const glm::dvec3 L = s.light;
        if (!finite(L)) fail("light", "must be finite");
        const double len = glm::length(L);
        if (!(len > 0.0)) fail("light", "the light direction is zero");
        if (std::fabs(L.y) <= 1e-9 * len)
            fail("light", "the light is parallel to the ground (its y component is 0): shadows would be infinitely long");
        if (L.y > 0.0) fail("light", "the light points up, away from the ground; give the direction its rays travel (y < 0)");
        if (!std::isfinite(s.groundY)) fail("ground_y", "must be finite");
        if (!finite(s.groundMin)) fail("ground_min", "must be finite");
        if (!finite(s.groundMax)) fail("ground_max", "must be finite");
        if (!(s.groundMax.x > s.groundMin.x) || !(s.groundMax.y > s.groundMin.y))
            fail("ground_max", "the ground rectangle is empty: ground_max must exceed ground_min in both x and z");
        // Square ground pixels: extend the shorter side about the centre to the picture's aspect.
        glm::dvec2 lo = s.groundMin, hi = s.groundMax;
        const double ground = (hi.x - lo.x) / (hi.y - lo.y), picture = W / H;
        if (std::fabs(ground / picture - 1.0) > 1e-3) {
            const glm::dvec2 centre = 0.5 * (lo + hi);
            glm::dvec2 half = 0.5 * (hi - lo);
            if (ground < picture) half.x = half.y * picture;
            else half.y = half.x / picture;
            lo = centre - half, hi = centre + half;
            c.groundExtended_ = true;
        }
        c.groundMin_ = lo, c.groundMax_ = hi;
        // P' = P - L (P.y - g) / L.y on the ground; x <- P'.x, row <- P'.z.
        const double sx = W / (hi.x - lo.x), sz = H / (hi.y - lo.y);
        const double kx = L.x / L.y, kz = L.z / L.y;
        setRow(c.rows_[0], sx * glm::dvec3(1.0, -kx, 0.0), sx * (kx * s.groundY - lo.x));
        setRow(c.rows_[1], sz * glm::dvec3(0.0, -kz, 1.0), sz * (kz * s.groundY - lo.y));
        setRow(c.rows_[2], glm::dvec3(0.0), 1.0);
        c.clip_[0] = 0.0;
        c.clip_[1] = 1.0;
        c.clip_[2] = 0.0;
        c.clip_[3] = -s.groundY;
        return c;
    }

    if (!finite(s.eye)) fail("eye", "must be finite");
    if (!finite(s.lookAt)) fail("look_at", "must be finite");
    if (!finite(s.up)) fail("up", "must be finite");
    const glm::dvec3 view = s.lookAt - s.eye;
    if (!(glm::length(view) > 0.0)) fail("look_at", "look_at equals eye: the camera has no view direction");
    const glm::dvec3 f = glm::normalize(view);
    if (!(glm::length(s.up) > 0.0)) fail("up", "the up vector is zero");
    const glm::dvec3 side = glm::cross(f, glm::normalize(s.up));
    if (!(glm::length(side) > 1e-9)) fail("up", "the up vector is parallel to the view direction (eye -> look_at)");
    const glm::dvec3 r = glm::normalize(side), u = glm::cross(r, f);
    if (!std::isfinite(s.near) || !(s.near >= 1e-9)) fail("near", "must be a positive distance (at least 1e-9)");

    if (s.projection == Projection::Perspective) {
        if (!(s.fovDegrees > 0.0 && s.fovDegrees < 180.0))
            fail("fov_degrees", "the field of view must lie strictly between 0 and 180 degrees");
        const double F = 0.5 * H / std::tan(0.5 * s.fovDegrees * M_PI / 180.0);
        // hw = f.(P - E); hx = W/2 hw + F r.(P - E); hy = H/2 hw - F u.(P - E)
        const glm::dvec3 a0 = 0.5 * W * f + F * r, a1 = 0.5 * H * f - F * u;
        setRow(c.rows_[0], a0, -glm::dot(a0, s.eye));
        setRow(c.rows_[1], a1, -glm::dot(a1, s.eye));
        setRow(c.rows_[2], f, -glm::dot(f, s.eye));
    } else {
        if (!std::isfinite(s.viewHeight) || !(s.viewHeight > 0.0))
            fail("view_height", "must be a positive number of world units");
        const double k = H / s.viewHeight;
        // x = W/2 + k r.(P - E); y = H/2 - k u.(P - E)
        setRow(c.rows_[0], k * r, 0.5 * W - k * glm::dot(r, s.eye));
        setRow(c.rows_[1], -k * u, 0.5 * H + k * glm::dot(u, s.eye));
        setRow(c.rows_[2], glm::dvec3(0.0), 1.0);
    }
    c.clip_[0] = f.x;
    c.clip_[1] = f.y;
    c.clip_[2] = f.z;
    c.clip_[3] = -glm::dot(f, s.eye) - s.near;
    return c;
}

glm::dvec2 Camera::project(const glm::dvec3& p) const {
    double h[3];
    for (int k = 0; k < 3; ++k) h[k] = rows_[k][0] * p.x + rows_[k][1] * p.y + rows_[k][2] * p.z + rows_[k][3];
    return {h[0] / h[2], h[1] / h[2]};
}

}  // namespace shapevo
