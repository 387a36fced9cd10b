#pragma once
// The frame sizes a subcommand may ask for: estimated memory against the
// host's and the device's, and GL's own size limits, checked before the
// first frame so that a size too large fails in one line naming the flags.
#include <shadowlab/Context.h>

namespace shadowlab::tool {

/// Refuses a frame (or the viewer's window) of `width` x `height` whose
/// estimated memory exceeds half of physical memory (llvmpipe keeps its
/// targets there), before any GL object is created.
/// SHADOWLAB_MEMORY_LIMIT_BYTES, when set, is the budget instead (the tests
/// check this path with a small one). Throws Error naming --width --height.
void checkMemory(int width, int height);
/// Refuses a reference of more than 2^31 rays per soft light (--samples
/// rays a pixel at width x height; about two minutes here), naming --samples.
void checkReferenceRays(int width, int height, int samples);

/// Refuses a frame past GL's limits (texture and viewport size) or whose
/// estimated memory exceeds the device memory the driver reports
/// (GlInfo::deviceMemoryBytes: GL_NVX_gpu_memory_info or GL_ATI_meminfo;
/// llvmpipe reports none). Throws Error naming --width or --height.
void checkSize(int width, int height, const GlInfo& info);

} // namespace shadowlab::tool
