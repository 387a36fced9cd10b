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
    {MapFilter::None, "none", "one nearest tap", true, true, never, false, false,  //
     [](const MapOptions&) { return 0.0f; }, [](const MapOptions&) { return 1.0f; }},
    {MapFilter::Hardware, "hardware", "one bilinear hardware compare", true, true, always, true, false,  //
     [](const MapOptions&) { return 1.0f; },  // the 2x2 bilinear footprint
     [](const MapOptions&) { return 1.5f; }},
    {MapFilter::Grid, "grid", "kernel x kernel taps (point lights: kernel^3 in a cube of side 2 diskRadius)", true, true, asGridTaps, false, false,
     [](const MapOptions& o) { return 0.5f * static_cast<float>(o.kernel - 1) * kSqrt2; },
     [](const MapOptions& o) { return 0.5f * static_cast<float>(o.kernel) + 1.0f; }},
    {MapFilter::Dither4, "dither4", "the lecture's dithered 4 taps (2D maps)", true, false, never, false, false,  //
     [](const MapOptions&) { return 1.5f * kSqrt2; }, [](const MapOptions&) { return 3.0f; }},
    {MapFilter::Poisson, "poisson", "a rotated disk", true, true, never, false, false,  //
     [](const MapOptions& o) { return o.radius; }, [](const MapOptions& o) { return o.radius + 1.0f; }},
    {MapFilter::Pcf20, "pcf20", "the lecture's 20 directions (point lights)", false, true, never, false, false,
     [](const MapOptions&) { return 0.0f; },  // point lights only (its kernel file computes theirs)
     [](const MapOptions&) { return 1.0f; }},
    {MapFilter::Pcss, "pcss", "soft shadows for the light's size (PCSS)", true, true, always, true, true,
     [](const MapOptions&) { return 0.0f; },  // each tap compares against the receiver's plane (its kernel file)
     [](const MapOptions& o) { return 0.125f * static_cast<float>(o.size) + 1.0f; }},  // its search and filter reach an eighth of the map
    {MapFilter::Box, "box", "four bilinear compares half a texel around the point, a tent over 3x3 texels (point lights: eight at the corners of a cube of side one texel)", true, true,
     always, true, false,  //
     [](const MapOptions&) { return 1.5f * kSqrt2; },  // the compared texels' centres, up to 1.5 texels on each axis
     [](const MapOptions&) { return 3.0f; }},
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
