#pragma once
/// @file AnalyticShadow.h
/// Closed-form shadows for testing: the exact shadow of a sphere on the
/// ground plane y = 0 under a directional light. Header-only, no GPU, no
/// Embree. Computed in double precision so that it is the exact answer
/// against which float renderers are judged.
#include <glm/glm.hpp>

#include <cmath>

namespace shadowlab {

/// True when the ray origin + t*direction, t > 0, hits the sphere (or the
/// origin lies inside it). `direction` need not be unit length.
///
/// Math: |o + t d - c|^2 = r^2 is the quadratic a t^2 + 2 b t + k = 0 with
/// a = d.d, b = d.(o - c), k = |o - c|^2 - r^2. It has real roots iff
/// b^2 - a k >= 0, and the larger root (-b + sqrt(b^2 - a k)) / a is > 0 iff
/// part of the line beyond o is inside the sphere.
inline bool rayHitsSphere(glm::vec3 origin, glm::vec3 direction, glm::vec3 centre, float radius) {
    const glm::dvec3 o(origin), d(direction), c(centre);
    const glm::dvec3 oc = o - c;
    const double a = glm::dot(d, d);
    if (!(a > 0.0)) return false;
    const double b = glm::dot(d, oc);
    const double k = glm::dot(oc, oc) - double(radius) * double(radius);
    const double discriminant = b * b - a * k;
    if (discriminant < 0.0) return false;
    return -b + std::sqrt(discriminant) > 0.0;
}

/// True when the ground point (on y = 0) is in the shadow of the sphere under
/// a directional light travelling along `lightDirection`: the ray from the
/// point towards -lightDirection hits the sphere. The set of such points is
/// the sphere's parallel projection onto the plane, an exact ellipse (a
/// circle for a vertical light) with the centre's projection as its centre.
inline bool inSphereShadowOnGround(glm::vec3 groundPoint, glm::vec3 sphereCentre, float radius,
                                   glm::vec3 lightDirection) {
    return rayHitsSphere(groundPoint, -lightDirection, sphereCentre, radius);
}

} // namespace shadowlab
