// Technique "map": its filters' table (options/Filters.h).
#include "techniques/map/options/Filters.h"

#include <iterator>
#include <cassert>

namespace shadowlab::map {

namespace {

bool never(bool) { return false; }
bool always(bool) { return true; }
bool asGridTaps(bool bilinearGrid) { return bilinearGrid; }
constexpr float kSqrt2 = 1.41421356f;

const FilterInfo kFilters[] = {
    {.filter = MapFilter::None, .name = "none", .doc = "one nearest tap", .for2D = true, .forCube = true, .linear2D = never, .linearCube = false,
     .rawDepth = false, .reach = [](const MapOptions&) { return 0.0f; }, .footprint = [](const MapOptions&) { return 1.0f; }},
    {.filter = MapFilter::Hardware, .name = "hardware", .doc = "one bilinear hardware compare", .for2D = true, .forCube = true, .linear2D = always,
     .linearCube = true, .rawDepth = false,
     .reach = [](const MapOptions&) { return 1.0f; },  // the 2x2 bilinear footprint
     .footprint = [](const MapOptions&) { return 1.5f; }},
    {.filter = MapFilter::Grid, .name = "grid", .doc = "kernel x kernel taps (point lights: kernel^3 in a cube of side 2 diskRadius)", .for2D = true,
     .forCube = true, .linear2D = asGridTaps, .linearCube = false, .rawDepth = false,
     .reach = [](const MapOptions& o) { return 0.5f * static_cast<float>(o.kernel - 1) * kSqrt2; },
     .footprint = [](const MapOptions& o) { return 0.5f * static_cast<float>(o.kernel) + 1.0f; }},
    {.filter = MapFilter::Dither4, .name = "dither4", .doc = "the lecture's dithered 4 taps (2D maps)", .for2D = true, .forCube = false,
     .linear2D = never, .linearCube = false, .rawDepth = false, .reach = [](const MapOptions&) { return 1.5f * kSqrt2; },
     .footprint = [](const MapOptions&) { return 3.0f; }},
    {.filter = MapFilter::Poisson, .name = "poisson", .doc = "a rotated disk", .for2D = true, .forCube = true, .linear2D = never, .linearCube = false,
     .rawDepth = false, .reach = [](const MapOptions& o) { return o.radius; }, .footprint = [](const MapOptions& o) { return o.radius + 1.0f; }},
    {.filter = MapFilter::Pcf20, .name = "pcf20", .doc = "the lecture's 20 directions (point lights)", .for2D = false, .forCube = true, .linear2D = never,
     .linearCube = false, .rawDepth = false,
     .reach = [](const MapOptions&) { return 0.0f; },  // point lights only (its kernel file computes theirs)
     .footprint = [](const MapOptions&) { return 1.0f; }},
    {.filter = MapFilter::Pcss, .name = "pcss", .doc = "soft shadows for the light's size (PCSS)", .for2D = true, .forCube = true, .linear2D = always,
     .linearCube = true, .rawDepth = true,
     .reach = [](const MapOptions&) { return 0.0f; },  // each tap compares against the receiver's plane (its kernel file)
     .footprint = [](const MapOptions& o) { return 0.125f * static_cast<float>(o.size) + 1.0f; }},  // its search and filter reach an eighth of the map
    {.filter = MapFilter::Box,
     .name = "box",
     .doc = "four bilinear compares half a texel around the point, a tent over 3x3 texels (point lights: eight at the corners of a cube of side one texel)",
     .for2D = true, .forCube = true, .linear2D = always, .linearCube = true, .rawDepth = false,
     .reach = [](const MapOptions&) { return 1.5f * kSqrt2; },  // the compared texels' centres, up to 1.5 texels on each axis
     .footprint = [](const MapOptions&) { return 3.0f; }},
};

} // namespace

std::span<const FilterInfo> filters() { return kFilters; }

const FilterInfo& filterInfo(MapFilter f) {
    const auto i = static_cast<std::size_t>(f);
    assert(i < std::size(kFilters) && kFilters[i].filter == f && "kFilters must list every MapFilter in enum order");
    return kFilters[i];
}

std::string kernelFile(MapFilter f) { return std::string("shadow_map_filter_") + filterInfo(f).name + ".glsl"; }

} // namespace shadowlab::map
