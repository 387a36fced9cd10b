#pragma once
// Technique "map", fit "sdsm" (Lauritzen et al., "Sample Distribution Shadow
// Maps", 2011): the points the camera sees, from a depth pre-pass of the
// frame (once a frame, shared by the lights that ask, drawn into the
// frame's own depth, which the base pass keeps: TechniqueHost::
// beginDepthPrepass), bounded in a light's view (or, for cascades, the
// camera's) by a fragment reduction of 8x8-pixel blocks
// (shaders/shadow_map_sdsm_reduce.frag) that the CPU merges. The tight
// fit then takes those bounds (FitInput::visibleSamples) instead of the boxes
// of the receivers in view; cascades end where the depths they span do,
// and slices not stabilised take their own bounds, a reduction a slice
// counting only the pixels at its distances. The bounds
// come back to the CPU, which fits the light camera: a read-back the frame
// waits for (on a GPU a pipeline bubble; the camera fitted on the GPU is
// left for later).
#include "core/Bounds.h"
#include "techniques/Technique.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab::map {

class SampleBounds {
public:
    /// Draws the frame's depth pre-pass (TechniqueHost::beginDepthPrepass)
    /// unless this frame already has it.
    void prepass(TechniqueHost& host, const FrameInfo& frame);
    /// The pre-pass's receiver points in `lightFromWorld` space; empty when
    /// the camera sees no receiver. With `distances` (along the view,
    /// [near, far]: a slice of cascades), only the points at those.
    Bounds reduce(TechniqueHost& host, const FrameInfo& frame, const glm::mat4& lightFromWorld,
                  const glm::vec2* distances = nullptr);

    /// Meshes of more triangles than this are not drawn in the pre-pass:
    /// their boxes, cut to the view's, join the bounds on the CPU instead
    /// (every point of theirs the camera can see lies in both). Bounds that
    /// way are never smaller than the points seen, a little larger where a
    /// large mesh hid what lies behind it; the pre-pass, which the vertex
    /// stage bounds on a large scene, then costs what the small meshes do.
    static constexpr std::size_t kBoxedTriangles = 4096;

private:
    gl::Sampler sampler_{gl::NoCreate};  ///< the frame's depth, nearest, clamped
    static constexpr int kBlock = 8;  ///< pixels per side of a block (shadow_map_sdsm_reduce.frag)
    gl::Texture lo_{gl::NoCreate}, hi_{gl::NoCreate};
    gl::Framebuffer reduceFbo_{gl::NoCreate};
    glm::ivec2 blocks_{0};
    glm::ivec2 size_{0};
    std::vector<std::size_t> boxed_;  ///< items in view left out of the pre-pass (kBoxedTriangles)
};

} // namespace shadowlab::map
