// Camera: how a model is turned into a picture for image targets.
//  - perspective:  a pinhole at `eye` looking at `look_at`, `up` giving the picture's up;
//                  `fov_degrees` is the vertical field of view (the papers: 800 x 600, 60 deg,
//                  near 0.1); pixels are square.
//  - orthographic: the same frame, parallel rays; `view_height` world units span the picture's
//                  height.
//  - shadow:       the model's shadow on the ground plane y = ground_y, cast by a distant light
//                  whose rays travel along `light` (pointing down, from the light to the ground);
//                  the ground rectangle ground_min..ground_max (x, z) fills the picture: x grows
//                  to the right, z grows downwards (row 0 = ground_min.z), as seen from above.
//                  Ground pixels are square: when the rectangle's aspect differs from the
//                  picture's (width / height) by more than 0.1 %, its shorter side is extended
//                  about its centre to the picture's aspect, so everything the rectangle holds
//                  stays in view and a picture fitted with its aspect kept keeps it on the ground
//                  (groundMin()/groundMax() give the rectangle used, groundExtended() says so).
// What is not seen: for perspective and orthographic cameras everything closer to the eye than
// `near` along the view direction (there is no far plane); for shadows everything below the
// ground. Primitives that cross that plane are cut by it (see silhouette_outline.hpp).
//
// Pixel (i, j) (row j from the top) has its centre at (i + 0.5, j + 0.5). A world point P maps
// to homogeneous pixel coordinates (hx, hy, hw) = rows * (P, 1) and to the pixel position
// (hx / hw, hy / hw); hw is the depth along the view direction (perspective) or 1 (parallel).
#pragma once
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shapevo {

enum class Projection { Perspective, Orthographic, Shadow };

/// The settings as a config gives them; Camera::compile checks them.
struct CameraSpec {
    Projection projection = Projection::Perspective;
    int width = 800, height = 600;
    glm::dvec3 eye{0.0, 0.0, 10.0}, lookAt{0.0}, up{0.0, 1.0, 0.0};
    double fovDegrees = 60.0;  ///< perspective: vertical field of view, in (0, 180)
    double viewHeight = 10.0;  ///< orthographic: world units across the picture's height
    double near = 0.1;         ///< perspective, orthographic: distance of the near plane from the eye
    glm::dvec3 light{0.0, -1.0, 0.0};  ///< shadow: direction of the light's rays
    double groundY = 0.0;
    glm::dvec2 groundMin{-5.0, -5.0}, groundMax{5.0, 5.0};  ///< shadow: (x, z) corners of the pictured ground
};

class Camera {
public:
    /// Check `spec` and build the projection. Throws InputError(file, section + "." + key, ...)
    /// naming the offending key (width, height, eye, look_at, up, fov_degrees, view_height, near,
    /// light, ground_y, ground_min, ground_max): sizes outside 1..16384, non-finite values,
    /// eye == look_at, up zero or parallel to the view direction, fov outside (0, 180),
    /// near <= 0, view_height <= 0, a light that is zero, parallel to the ground or pointing up,
    /// an empty ground rectangle.
    static Camera compile(const CameraSpec& spec, const std::string& file, const std::string& section = "camera");

    int width() const { return width_; }
    int height() const { return height_; }
    Projection projection() const { return projection_; }
    bool parallel() const { return projection_ != Projection::Perspective; }
    /// rows[k] = (a, b, c, d): homogeneous coordinate k of P is a*P.x + b*P.y + c*P.z + d.
    const double (&rows() const)[3][4] { return rows_; }
    /// The visible side: clip . (P, 1) >= 0 (in front of the near plane / above the ground).
    const double (&clipPlane() const)[4] { return clip_; }

    /// Shadow: the ground rectangle the picture shows (ground_min..ground_max, or that rectangle
    /// extended to the picture's aspect), and whether it was extended.
    glm::dvec2 groundMin() const { return groundMin_; }
    glm::dvec2 groundMax() const { return groundMax_; }
    bool groundExtended() const { return groundExtended_; }

    /// Pixel position of a world point (meaningful where clip >= 0).
    glm::dvec2 project(const glm::dvec3& p) const;
    bool visible(const glm::dvec3& p) const {
        return clip_[0] * p.x + clip_[1] * p.y + clip_[2] * p.z + clip_[3] >= 0.0;
    }

private:
    Projection projection_ = Projection::Perspective;
    int width_ = 0, height_ = 0;
    double rows_[3][4] = {};
    double clip_[4] = {};
    glm::dvec2 groundMin_{0.0}, groundMax_{0.0};
    bool groundExtended_ = false;
};

}  // namespace shapevo
