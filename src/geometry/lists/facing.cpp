// facing (facing.hpp): the best angle per segment in closed form; occlusion by sampled lines of
// sight through the box tree.
#include "geometry/lists/facing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace shapevo::lists {

StreetSegment streetOfScope(const Scope& s) {
    const glm::dvec3 origin(s.origin), half = glm::dvec3(s.axes[0]) * (0.5 * double(s.size.x));
    return {origin - half, origin + half};
}

namespace {

/// cos of the angle between n and v, or -2 when v is 0.
double viewCosine(const glm::dvec3& normal, const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? glm::dot(normal, v) / length : -2.0;
}

}  // namespace

double bestViewCosine(const glm::dvec3& c, const glm::dvec3& normal, const StreetSegment& street, double& bestT) {
    const glm::dvec3 w = street.a - c, u = street.b - street.a;
    // cos(t) = (alpha + beta t) / sqrt(gamma + 2 delta t + epsilon t^2) has one critical point.
    const double alpha = glm::dot(normal, w), beta = glm::dot(normal, u);
    const double gamma = glm::dot(w, w), delta = glm::dot(w, u), epsilon = glm::dot(u, u);
    double best = viewCosine(normal, w);
    bestT = 0.0;
    auto consider = [&](double t) {
        const double cosine = viewCosine(normal, w + u * t);
        if (cosine > best) best = cosine, bestT = t;
    };
    consider(1.0);
    const double denominator = beta * delta - alpha * epsilon;
    if (denominator != 0.0) {
        const double t = (alpha * delta - beta * gamma) / denominator;
        if (t > 0.0 && t < 1.0) consider(t);
    }
    return best;
}

void facing(std::span<const Scope> shapes, std::span<const StreetSegment> streets, const FacingOptions& options,
            BoxTree& tree, std::span<std::uint8_t> out) {
    const double cosTolerance = std::cos(options.toleranceDegrees * std::numbers::pi / 180.0);
    const std::uint32_t samples = std::max(options.samples, 2u);
    if (options.unoccluded) tree.build(shapes);
    for (std::uint32_t i = 0; i < shapes.size(); ++i) {
        const glm::dvec3 c(shapes[i].origin), normal = glm::normalize(glm::dvec3(shapes[i].axes[2]));
        // A point p in view and (if asked) unoccluded.
        auto sees = [&](const glm::dvec3& p) {
            const glm::dvec3 v = p - c;
            if (!(viewCosine(normal, v) >= cosTolerance)) return false;
            if (!options.unoccluded) return true;
            const double length = glm::length(v);
            return !tree.anyBefore(c, v / length, length, i);
        };
        bool found = false;
        for (const StreetSegment& street : streets) {
            double bestT = 0.0;
            if (!(bestViewCosine(c, normal, street, bestT) >= cosTolerance)) continue;  // no point in view
            if (!options.unoccluded) {
                found = true;
                break;
            }
            const glm::dvec3 u = street.b - street.a;
            found = sees(street.a + u * bestT);
            for (std::uint32_t k = 0; k < samples && !found; ++k) found = sees(street.a + u * (double(k) / double(samples - 1)));
            if (found) break;
        }
        out[i] = found ? 1 : 0;
    }
}

}  // namespace shapevo::lists
