// View cameras for pictures of a model: where a picture looks from and how the model is framed.
// Promises: orthographic projection (no perspective, so parallel edges stay parallel and the
// three standard views can be compared side by side); the world's +y is up in every view but
// `top`; a model is framed by its bounding sphere (the centre of its bounding box, the farthest
// vertex) so that the sphere fits the picture's smaller side with a 5 % margin on each side,
// whatever the direction: every view of one model has the same scale. Pixel (i, j) covers
// [i, i+1) x [j, j+1), row 0 at the top.
//   three-quarter  from the front right, 45 degrees round from the front, 30 degrees up (default)
//   front          from +z looking towards -z: +x right, +y up
//   side           from +x looking towards -x: -z right, +y up
//   top            from +y looking down: +x right, -z up (the front at the bottom)
//   three          front, side and top side by side (parseViews only)
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace shapevo {

enum class View { ThreeQuarter, Front, Side, Top };

/// The name a user types for `v` ("three-quarter", "front", "side", "top").
const char* viewName(View v);

/// The views one --view option names, left to right: one view, or front, side, top for "three".
/// @throw InputError(option) naming the accepted names for anything else.
std::vector<View> parseViews(const std::string& text, const std::string& option = "--view");

/// A sphere around the vertices that triangles use; radius 0 for one point, and centre 0,
/// radius 0 for a mesh without triangles.
struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};
BoundingSphere boundingSphere(const Mesh& mesh);

/// An orthographic camera for a `width` x `height` picture.
struct ViewCamera {
    int width = 0, height = 0;
    glm::vec3 right{1, 0, 0}, up{0, 1, 0}, toward{0, 0, 1};  ///< orthonormal; toward points at the viewer
    glm::vec3 centre{0.0f};                                   ///< shown at the picture's centre
    float pixelsPerUnit = 1.0f;

    /// Picture coordinates of world point p: x to the right, y down, in pixels; z is depth
    /// (smaller = nearer the viewer).
    glm::vec3 project(const glm::vec3& p) const;
};

/// The camera of view `v` framing `bounds` in a width x height picture (both > 0). A sphere of
/// radius 0 is shown at 1 pixel per unit.
ViewCamera frameView(View v, const BoundingSphere& bounds, int width, int height);

}  // namespace shapevo
