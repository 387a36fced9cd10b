#pragma once
// Technique "map": what a frame's maps are drawn from, as one number, so
// that a frame whose inputs did not change keeps the previous frame's maps
// (RenderOptions::cacheShadowMaps).
#include "techniques/Technique.h"

#include <cstdint>
#include <span>

namespace shadowlab::map {

/// A hash of everything the maps of `lights` depend on: each light's type,
/// position, direction, cone, range and effective map options; every item's
/// mesh, transform, shadow flags and alpha material (casters, and the
/// receivers the fits take); the camera and the frame's size (the fits
/// follow the view); the scene's upload. Equal inputs give equal hashes.
std::uint64_t mapInputs(const FrameInfo& frame, std::span<const int> lights);

} // namespace shadowlab::map
