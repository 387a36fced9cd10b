#pragma once
// The order a mesh's triangles are drawn in, for the rasteriser's caches.
// GPU-free.
//
// A vertex stage shades an index once while it is in its cache, and
// llvmpipe fetches and shades each batch of indices over the range of
// vertices they span: a triangle's neighbours reuse its vertices only if
// they come soon after it, and a batch is cheap only if its vertices lie
// close together in the buffer. A mesh file may list its triangles in no
// spatial order (glmark2's bunny.obj: any 128 consecutive triangles span
// 0.89 of its diagonal); drawn in Morton order of their centroids, with
// the vertices numbered in the order the triangles first use them,
// neighbours come together in both. The same triangles, each with its own
// winding: a depth test keeps the same nearest surface whatever the order,
// so the image is the same but where two triangles of one mesh tie in
// depth. A repeated triangle is drawn once. (Triangles reordered over the file's vertex numbers made
// cascades-field's unshadowed frame slower, 36 -> 41 ms, not faster.)
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

/// `indices` (triangles over `positions`) reordered by the Morton code of
/// each triangle's centroid in the mesh's bounds (10 bits an axis), ties
/// kept in their order; a trailing partial triangle is dropped, and so is
/// each repeat of a triangle (the same three positions, turning the same
/// way) after its first: drawn again it adds no depth the first did not
/// (the depth test keeps the first), only its fill (a million copies of a
/// triangle filled a shadow map a million times over).
std::vector<std::uint32_t> spatialTriangleOrder(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

/// A mesh's draw order: its triangles in spatial order over its vertices
/// renumbered as they are first used (those no triangle uses last, in
/// their order).
struct DrawOrder {
    std::vector<std::uint32_t> indices; ///< over the new numbers
    std::vector<std::uint32_t> remap;   ///< per vertex of the mesh: its new number
};
DrawOrder spatialDrawOrder(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

} // namespace shadowlab
