#pragma once
// Technique "map": what a frame's maps are drawn from, as one number, so
// that a frame whose inputs did not change keeps the previous frame's maps
// (RenderOptions::cacheShadowMaps).
#include "techniques/Technique.h"

#include <shadowlab/MapOptions.h>

#include <cstdint>
#include <map>
#include <string>

namespace shadowlab::map {

/// FNV-1a, 64 bits: what the module's caches key on (mapInputs, the
/// atlas's tiles, the caster batch).
struct Hash {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    }
    template <class T>
    Hash& value(const T& v) {
        bytes(&v, sizeof v);
        return *this;
    }
    void text(const std::string& s) {
        value(s.size());
        bytes(s.data(), s.size());
    }
};

/// A hash of everything the maps of the lights in `options` (index -> the
/// frame's options, MapLight::options) depend on: each light's type,
/// position, direction, cone, range and those options; every item's
/// mesh, transform, shadow flags and alpha material (casters, and the
/// receivers the fits take); the camera and the frame's size (the fits
/// follow the view); the scene's upload. Equal inputs give equal hashes.
std::uint64_t mapInputs(const FrameInfo& frame, const std::map<int, MapOptions>& options);

} // namespace shadowlab::map
