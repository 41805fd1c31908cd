// View cameras: view names, the bounding sphere and orthographic framing (view_camera.hpp).
#include "report/render/view_camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "base/input_error.hpp"
#include "mesh/corner_box.hpp"

namespace shapevo {

namespace {

/// Margin on each side of the framed sphere, as a fraction of the picture's smaller side.
constexpr float kMargin = 0.05f;

}  // namespace

const char* viewName(View v) {
    switch (v) {
        case View::ThreeQuarter: return "three-quarter";
        case View::Front: return "front";
        case View::Side: return "side";
        case View::Top: return "top";
    }
    return "?";
}

std::vector<View> parseViews(const std::string& text, const std::string& option) {
    if (text == "three") return {View::Front, View::Side, View::Top};
    for (View v : {View::ThreeQuarter, View::Front, View::Side, View::Top})
        if (text == viewName(v)) return {v};
    throw InputError(option, "", "unknown view \"" + shortened(text) +
                                     "\" (expected three-quarter, front, side, top, or three for front, side and top side by side)");
}

BoundingSphere boundingSphere(const Mesh& mesh) {
    BoundingSphere s;
    if (mesh.triangles.empty()) return s;
    const CornerBox box = cornerBox(mesh);
    s.centre = 0.5f * (box.lo + box.hi);
    float r2 = 0.0f;
    for (const auto& t : mesh.triangles)
        for (std::uint32_t i : t) {
            const glm::vec3 d = mesh.vertices[i] - s.centre;
            r2 = std::max(r2, glm::dot(d, d));
        }
    s.radius = std::sqrt(r2);
    return s;
}

glm::vec3 ViewCamera::project(const glm::vec3& p) const {
    const glm::vec3 d = p - centre;
    return {0.5f * float(width) + glm::dot(d, right) * pixelsPerUnit, 0.5f * float(height) - glm::dot(d, up) * pixelsPerUnit,
            -glm::dot(d, toward)};
}

ViewCamera frameView(View v, const BoundingSphere& bounds, int width, int height) {
    ViewCamera c;
    c.width = width;
    c.height = height;
    c.centre = bounds.centre;
    switch (v) {
        case View::Front: break;  // the defaults
        case View::Side:
            c.right = {0, 0, -1};
            c.toward = {1, 0, 0};
            break;
        case View::Top:
            c.up = {0, 0, -1};
            c.toward = {0, 1, 0};
            break;
        case View::ThreeQuarter: {
            const float azimuth = glm::radians(45.0f), elevation = glm::radians(30.0f);
            c.toward = {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
            c.right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), c.toward));
            c.up = glm::cross(c.toward, c.right);
            break;
        }
    }
    const float side = float(std::min(width, height)) * (1.0f - 2.0f * kMargin);
    if (bounds.radius > 0.0f && std::isfinite(bounds.radius)) c.pixelsPerUnit = side / (2.0f * bounds.radius);
    return c;
}

}  // namespace shapevo
