#pragma once
// Technique "map": its filters as data. One row per MapFilter value, in
// enum order, says everything the C++ side needs of a filter: its name and
// doc (the options table's "filter" row is made from them), its GLSL
// kernel file (the light pass's "@map_filter" slot; the variant's
// SL_MAP_FILTER_* values come from the names), the sampler it reads
// through, and how far its taps reach. Adding a filter: its enum value in
// MapOptions.h, its row here, its kernel file shaders/shadow_map_filter_<name>.glsl,
// its test.
#include <shadowlab/MapOptions.h>

#include <span>
#include <string>

namespace shadowlab::map {

struct FilterInfo {
    MapFilter filter;
    const char* name;        ///< the JSON value, and the kernel file's and SL_MAP_FILTER_<NAME>'s
    const char* doc;         ///< a clause of the "filter" option's doc
    bool for2D;              ///< has a kernel for 2D maps (directional and spot lights, cascades)
    bool forCube;            ///< has a kernel for point lights' cube maps
    /// Whether the taps are bilinear hardware compares (2D maps; the grid
    /// asks `bilinearGrid`), and on a cube.
    bool (*linear2D)(bool bilinearGrid);
    bool linearCube;
    bool rawDepth;           ///< also reads the stored depths without comparison (PCSS's blocker search)
    /// Texels from the filter's centre to its farthest tap, for the
    /// receiver-plane bias (2D maps; a cube's kernel says its own).
    float (*reach)(const MapOptions& o);
    /// Texels around the fitted region that the filter may read.
    float (*footprint)(const MapOptions& o);
};

/// Every filter, in MapFilter's order.
std::span<const FilterInfo> filters();
const FilterInfo& filterInfo(MapFilter f);
/// The light pass's kernel file of `f` (moment maps have their own, shadow_map_moments.glsl).
std::string kernelFile(MapFilter f);

} // namespace shadowlab::map
