// Fuzz target: a Wavefront OBJ file. Expected failures throw shadowlab::Error.
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        shadowlab::parseObj(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
    } catch (const shadowlab::Error&) {
    }
    return 0;
}
