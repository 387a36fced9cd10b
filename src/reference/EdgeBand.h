#pragma once
// compare's pixel classes (EdgeBand.cpp): which surface pixels receive a
// light, their true class, and the edge band (receivers the exact shadow
// boundary passes within a pixel of), which compare scores apart.
#include "reference/RayTracer.h"

#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/Scene.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab::reference {

/// A surface pixel's plane extended under a neighbour's pixel centre.
struct Extension {
    std::size_t pixel = 0;  ///< the surface pixel whose plane is extended
    std::size_t index = 0;  ///< into the traced extension samples
    glm::vec3 position{0.0f};
};

/// For each surface pixel and each 8-neighbour not on the same surface (no
/// surface, or one off the pixel's tangent plane or turned from it): the
/// point where the camera ray through the neighbour's centre meets the
/// pixel's plane.
std::vector<Extension> surfaceExtensions(const Scene& scene, const SurfaceBuffer& surfaces, const std::vector<SurfaceSample>& samples);

/// Per pixel of a w x h image, for one light: its receivers, the
/// reference's classes and the edge band.
struct PixelClasses {
    int w = 0, h = 0;
    std::vector<std::uint8_t> receiver, exactLit, edge;
};

/// Receivers (reached by the light, facing it, receiving shadows) and the
/// reference's classes (lit at `exact` >= litThreshold); `reach` shows the receivers.
PixelClasses classify(const Light& light, const std::vector<SurfaceSample>& samples, const SurfaceBuffer& surfaces, const std::vector<float>& exact,
                      float litThreshold, ImageGray8& reach);

/// The edge band: receivers the exact shadow boundary passes within a
/// pixel of. A receiver is in it when an 8-neighbour receiver has the
/// other true class, or when a neighbour lies on another surface (a
/// silhouette in between) and the pixel's own surface, extended under
/// that neighbour's pixel centre, has the other true class there
/// (`extensionExact`, the reference at the extensions): the boundary then
/// runs on past the pixel, hidden behind what is drawn next to it.
void markEdgeBand(PixelClasses& classes, const std::vector<Extension>& extensions, const std::vector<float>& extensionExact, float litThreshold);

/// The band widened to `band` pixels (CompareOptions::edgeBand): a receiver
/// within band - 1 pixels (Chebyshev distance) of one in the 1-pixel band
/// joins it; each pass grows it by one pixel.
void widenEdgeBand(PixelClasses& classes, int band);

} // namespace shadowlab::reference
