#pragma once
// Planar meshes: a floor, a wall, a quad. A planar mesh cannot shadow
// itself and shadows only what lies behind its plane as seen from the
// light, so shadow maps leave it out of their pass when nothing visible is
// there (and planar shadows, Wolberg's lecture, take such meshes as receivers).
// GPU-free.
#include "core/Bounds.h"

#include <shadowlab/Scene.h>

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace shadowlab {

/// The plane (n, d) with unit n and dot(n, x) + d = 0 through every vertex
/// of `mesh` (within 1e-5 of its bounds' diagonal), or nothing when the
/// mesh is not planar or has no triangle of non-zero area.
std::optional<glm::vec4> meshPlane(const Mesh& mesh);

/// The distinct planes of a convex mesh's triangles (unit normals facing
/// out of the mesh: every vertex on or behind each plane, within 1e-5 of the
/// bounds' diagonal), or nothing when the mesh is not convex, is planar, or
/// has more than `maxTriangles` triangles (the check costs triangles x
/// vertices). A light inside a convex mesh (a room) cannot be shadowed by it
/// on anything inside it.
std::vector<glm::vec4> convexPlanes(const Mesh& mesh, std::size_t maxTriangles = 1024);

/// True when `point` is strictly inside every plane (by more than `margin`).
bool strictlyInside(const std::vector<glm::vec4>& planes, const glm::vec3& point, float margin);

/// True when every corner of `box` is on or inside every plane (within `margin`).
bool boxInside(const std::vector<glm::vec4>& planes, const Bounds& box, float margin);

/// `plane` (object space) moved by the affine `worldFromObject`.
glm::vec4 transformPlane(const glm::vec4& plane, const glm::mat4& worldFromObject);

/// True when some corner of `box` lies behind `plane` as seen from the
/// light by more than `margin`: on the side away from `towardsLight` (a
/// point light's or spot's position with w = 1, or the direction towards a
/// directional light with w = 0). Only then can the plane's mesh shadow
/// anything in the box.
bool reachesBehind(const glm::vec4& plane, const glm::vec4& towardsLight, const Bounds& box, float margin);

} // namespace shadowlab
