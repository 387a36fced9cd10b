#pragma once
/// @file Limits.h
/// The frame sizes a run may ask for: estimated memory against the host's
/// and the device's, GL's own size limits and the reference's rays,
/// checked before the first frame so that a size too large fails in one
/// line. The messages name the CLI's flags (--width, --height, --samples),
/// which the Python module says as its arguments.
#include <shadowlab/Context.h>

#include <cstddef>
#include <shadowlab/Export.h>

namespace shadowlab {

/// Refuses a frame (or the viewer's window) of `width` x `height` whose
/// estimated memory exceeds half of physical memory (llvmpipe keeps its
/// targets there), before any GL object is created.
/// SHADOWLAB_MEMORY_LIMIT_BYTES, when set, is the budget instead (the tests
/// check this path with a small one). Throws Error naming --width --height.
SHADOWLAB_API void checkMemory(int width, int height);
/// Refuses a reference of more than 2^31 rays per soft light (--samples
/// rays a pixel at width x height; about two minutes here), naming --samples.
SHADOWLAB_API void checkReferenceRays(int width, int height, int samples);
/// Refuses a whole reference of more than 2^32 rays: checkReferenceRays
/// for each of `softLights` soft lights together (about four minutes
/// here; 64 soft lights at --samples 65536 would trace 6e10), naming
/// --samples.
SHADOWLAB_API void checkSceneReferenceRays(int width, int height, int samples, std::size_t softLights);

/// Refuses a frame past GL's limits (texture and viewport size) or whose
/// estimated memory exceeds the device memory the driver reports
/// (GlInfo::deviceMemoryBytes: GL_NVX_gpu_memory_info or GL_ATI_meminfo;
/// llvmpipe reports none). Throws Error naming --width or --height.
SHADOWLAB_API void checkSize(int width, int height, const GlInfo& info);

} // namespace shadowlab
