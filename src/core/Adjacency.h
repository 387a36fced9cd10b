#pragma once
// Triangle adjacency for silhouette work (shadow volumes, geometry-shader
// extrusion): GL_TRIANGLES_ADJACENCY index lists. GPU-free.
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

/// Per vertex, the first vertex with the same position (meshes split
/// vertices for normals and uvs; welding finds the surface's own). Same as
/// == compares: +0 and -0 are one, a position with a NaN is only its own.
std::vector<std::uint32_t> weldByPosition(const std::vector<glm::vec3>& positions);

/// For each triangle (a, b, c) of `indices` the six indices
/// a, n(ab), b, n(bc), c, n(ca) in GL_TRIANGLES_ADJACENCY order, where n(xy)
/// is the vertex opposite edge xy in the triangle across that edge.
/// Vertices are matched by position (meshes split vertices for normals and
/// uvs, so indices alone would see every edge as open). An open edge, or one
/// shared by more than two triangles, gets the triangle's own opposite
/// vertex, i.e. a neighbour lying in the triangle's own plane: silhouette
/// code that tests "front-facing here, back-facing there" then sees it as
/// an edge between two coplanar faces and must treat it as a silhouette
/// itself (count such edges with openEdges()).
std::vector<std::uint32_t> adjacencyIndices(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

/// Edges (after welding by position) used by exactly one triangle, or by
/// more than two: 0 for a closed manifold mesh.
std::size_t openEdges(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

/// Which way a closed mesh's triangles turn: +1 when it has no open edge
/// (openEdges() == 0: every edge walked once each way, so the triangles
/// wind one way round an inside) and its counter-clockwise sides face out
/// (a positive signed volume), -1 when they face in, 0 for any other mesh
/// (open, none, or enclosing no volume, as a plane drawn from both sides).
/// A ray from outside such a mesh meets a side facing it first: a depth
/// pass from a light outside it may leave the far sides out.
int closedWinding(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

} // namespace shadowlab
