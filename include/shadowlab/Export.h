#pragma once
/// @file Export.h
/// SHADOWLAB_API marks the library's public API. The shared library is built
/// with symbols hidden by default (-fvisibility=hidden), so only what carries
/// this macro, the declarations in include/shadowlab/, is exported:
/// `nm -D --defined-only libshadowlab.so` lists the public API and nothing
/// else. Internal code (src/) is reachable only by linking the internal
/// static library, as the tests and fuzz targets do.
#if defined(_WIN32)
#  define SHADOWLAB_API
#else
#  define SHADOWLAB_API __attribute__((visibility("default")))
#endif

/// SHADOWLAB_HIDDEN marks a library-internal class nested in a public one
/// (the `Impl` behind a public class's pointer), which would otherwise take
/// the exported visibility of the class it is declared in.
#if defined(_WIN32)
#  define SHADOWLAB_HIDDEN
#else
#  define SHADOWLAB_HIDDEN __attribute__((visibility("hidden")))
#endif
