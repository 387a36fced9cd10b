// Fuzz target: a glTF file, JSON (.gltf) or, with SHADOWLAB_FUZZ_GLB=1,
// binary (.glb). External URIs resolve in fuzz/corpus/files/. Expected
// failures throw shadowlab::Error.
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        shadowlab::parseGltf(std::string(reinterpret_cast<const char*>(data), size), SHADOWLAB_FUZZ_GLB ? "fuzz.glb" : "fuzz.gltf",
                             SHADOWLAB_FUZZ_FILES_DIR, SHADOWLAB_FUZZ_GLB);
    } catch (const shadowlab::Error&) {
    }
    return 0;
}
