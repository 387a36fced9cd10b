#pragma once
// The pieces the light cameras' fits share (LightCamera.cpp, Cascades.cpp):
// the scene's box, the receivers the view may see, a directional light's
// view before its box, the nearest part of a box in a view's pyramid
// (LightFitParts.cpp).
#include "geometry/LightCamera.h"

#include <glm/glm.hpp>

namespace shadowlab::fitparts {

/// The box of every item.
Bounds all(const FitInput& in);
/// Bounds (in `to` space) of the receivers the camera may see.
Bounds visibleReceivers(const FitInput& in, const glm::mat4& to);
/// The scene box's diagonal (1 for an empty scene, at least 10^-3).
float diagonalOf(const Bounds& scene);
/// A directional light's view: looking along `direction` from the scene's
/// centre moved back by `diagonal` (every depth negative in view space;
/// fixed while the scene is); `up`: the view's +y (a warp's axis),
/// lightCameraUp's when not given.
glm::mat4 lightViewOf(const glm::vec3& direction, const Bounds& scene, float diagonal, const glm::vec3* up = nullptr);
/// A directional light's camera before its box: lightViewOf's view, with
/// the casters that matter for what `in`'s camera sees.
LightCamera directionalView(const glm::vec3& direction, const FitInput& in, const Bounds& scene, float diagonal, const glm::vec3* up = nullptr);

/// The nearest distance along a camera's axis (-z of `view`) of the part of
/// world box `box` inside the pyramid |x| <= tanX (-z), |y| <= tanY (-z) of
/// that view; infinity when none of it is inside. Exact: a vertex of the
/// box cut by the pyramid is a vertex of a box face clipped by the
/// pyramid's four sides (or the apex, inside the box).
float nearestInPyramid(const Bounds& box, const glm::mat4& view, float tanX, float tanY);

} // namespace shadowlab::fitparts
