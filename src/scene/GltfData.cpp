// A glTF model's primitives, materials and images made shadowlab's
// (GltfImporter.h): every accessor's offset, stride and count checked before
// a byte is read.
#include "scene/GltfImporter.h"

#include <stb_image.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace shadowlab::gltf {

using namespace meshfile;

namespace {

const char* componentTypeName(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_INT: return "int";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "double";
    default: return "unknown";
    }
}

} // namespace

int GltfImporter::primitiveMesh(int m, int p) {
    const auto key = std::make_pair(m, p);
    if (auto it = meshCache_.find(key); it != meshCache_.end()) return it->second;
    const tinygltf::Mesh& src = gltf_.meshes[m];
    const tinygltf::Primitive& prim = src.primitives[static_cast<std::size_t>(p)];
    int result = -1;
    if (prim.mode == -1 || prim.mode == TINYGLTF_MODE_TRIANGLES) { // other modes are skipped
        Mesh mesh = readPrimitive(src, prim, p);
        if (mesh.triangleCount() > 0) {
            result = static_cast<int>(out_.meshes.size());
            out_.meshes.push_back(std::move(mesh));
        }
    }
    meshCache_[key] = result;
    return result;
}

Mesh GltfImporter::readPrimitive(const tinygltf::Mesh& src, const tinygltf::Primitive& prim, int p) {
    const std::string where = "mesh '" + src.name + "' primitive " + std::to_string(p);
    Mesh mesh;
    mesh.name = src.primitives.size() > 1 ? src.name + "#" + std::to_string(p) : src.name;

    const auto attribute = [&](const char* name) {
        const auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    };
    const int posAccessor = attribute("POSITION");
    if (posAccessor < 0) fail(where + ": no POSITION attribute");
    mesh.positions = readVectors<3>(posAccessor, "POSITION");
    const std::size_t count = mesh.positions.size();

    if (prim.indices >= 0) {
        mesh.indices = readIndices(prim.indices, count);
    } else {
        mesh.indices.resize(count);
        for (std::size_t i = 0; i < count; ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
    }
    if (mesh.indices.size() % 3 != 0)
        fail(where + ": " + std::to_string(mesh.indices.size()) + " indices is not a multiple of 3");

    if (const int a = attribute("TEXCOORD_0"); a >= 0) {
        mesh.uvs = readVectors<2>(a, "TEXCOORD_0");
        if (mesh.uvs.size() != count) fail(where + ": TEXCOORD_0 count differs from POSITION count");
    }
    if (const int a = attribute("NORMAL"); a >= 0) {
        mesh.normals = readVectors<3>(a, "NORMAL");
        if (mesh.normals.size() != count) fail(where + ": NORMAL count differs from POSITION count");
        // Renormalise; zero-length normals are replaced by computed ones.
        std::vector<glm::vec3> computed;
        for (glm::vec3& n : mesh.normals) {
            const float len = glm::length(n);
            if (len > 0.0f) {
                n /= len;
            } else {
                if (computed.empty()) computed = smoothNormals(mesh.positions, mesh.indices);
                n = computed[static_cast<std::size_t>(&n - mesh.normals.data())];
            }
        }
    } else {
        mesh.normals = smoothNormals(mesh.positions, mesh.indices);
    }
    return mesh;
}

std::pair<const unsigned char*, std::size_t> GltfImporter::locate(const tinygltf::Accessor& acc, int index, const std::string& what, std::size_t elementSize) const {
    (void)index;
    if (acc.sparse.isSparse) fail(what + ": sparse accessors are not supported");
    if (acc.count > kMaxAccessorElements)
        fail(what + ": count " + std::to_string(acc.count) + " exceeds the limit of " + std::to_string(kMaxAccessorElements) + " elements");
    if (acc.bufferView < 0) return {nullptr, 0}; // all zeros by the spec
    if (acc.bufferView >= static_cast<int>(gltf_.bufferViews.size())) fail(what + ": bufferView out of range");
    const tinygltf::BufferView& view = gltf_.bufferViews[acc.bufferView];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(gltf_.buffers.size())) fail(what + ": buffer out of range");
    const tinygltf::Buffer& buffer = gltf_.buffers[view.buffer];
    if (view.byteStride != 0 && view.byteStride < elementSize)
        fail(what + ": bufferView " + std::to_string(acc.bufferView) + " byteStride " + std::to_string(view.byteStride) +
             " is smaller than an element (" + std::to_string(elementSize) + " bytes)");
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    // Each comparison subtracts only what is known to be smaller, so no
    // offset near 2^64 can wrap around and pass.
    const std::size_t size = buffer.data.size();
    if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
        fail(what + ": bufferView " + std::to_string(acc.bufferView) + " (byteOffset " + std::to_string(view.byteOffset) +
             ", byteLength " + std::to_string(view.byteLength) + ") lies past the end of its buffer (" + std::to_string(size) + " bytes)");
    const bool fits = acc.byteOffset <= view.byteLength &&
                      (acc.count == 0 || (elementSize <= view.byteLength - acc.byteOffset &&
                                          acc.count - 1 <= (view.byteLength - acc.byteOffset - elementSize) / stride));
    if (!fits)
        fail(what + ": byteOffset " + std::to_string(acc.byteOffset) + " and count " + std::to_string(acc.count) +
             " read past the end of bufferView " + std::to_string(acc.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
    return {buffer.data.data() + view.byteOffset + acc.byteOffset, stride};
}

template <int N>
std::vector<glm::vec<N, float>> GltfImporter::readVectors(int index, const char* semantic) const {
    const std::string what = "accessor " + std::to_string(index) + " (" + semantic + ")";
    if (index < 0 || index >= static_cast<int>(gltf_.accessors.size())) fail(what + ": accessor index out of range");
    const tinygltf::Accessor& acc = gltf_.accessors[index];
    const int expectedType = N == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || acc.normalized || acc.type != expectedType)
        fail(what + ": expected float VEC" + std::to_string(N) + ", got " + (acc.normalized ? "normalized " : "") +
             componentTypeName(acc.componentType) + " with " + std::to_string(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type))) +
             " components (quantized/normalized attributes are not supported)");
    const auto [data, stride] = locate(acc, index, what, N * sizeof(float));
    std::vector<glm::vec<N, float>> values(acc.count, glm::vec<N, float>(0.0f));
    if (!data) return values;
    for (std::size_t i = 0; i < acc.count; ++i) {
        std::memcpy(glm::value_ptr(values[i]), data + i * stride, N * sizeof(float)); // unaligned-safe
        for (int k = 0; k < N; ++k)
            if (!std::isfinite(values[i][k])) fail(what + ": non-finite value in element " + std::to_string(i));
    }
    return values;
}

std::vector<std::uint32_t> GltfImporter::readIndices(int index, std::size_t vertexCount) const {
    const std::string what = "accessor " + std::to_string(index) + " (indices)";
    if (index >= static_cast<int>(gltf_.accessors.size())) fail(what + ": accessor index out of range");
    const tinygltf::Accessor& acc = gltf_.accessors[index];
    std::size_t size = 0;
    switch (acc.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
    default: fail(what + ": expected unsigned byte/short/int indices, got " + componentTypeName(acc.componentType));
    }
    if (acc.type != TINYGLTF_TYPE_SCALAR) fail(what + ": expected SCALAR indices");
    const auto [data, stride] = locate(acc, index, what, size);
    std::vector<std::uint32_t> indices(acc.count, 0u);
    for (std::size_t i = 0; data && i < acc.count; ++i) {
        const unsigned char* e = data + i * stride;
        if (size == 1) {
            indices[i] = e[0];
        } else if (size == 2) {
            std::uint16_t v;
            std::memcpy(&v, e, 2);
            indices[i] = v;
        } else {
            std::memcpy(&indices[i], e, 4);
        }
    }
    for (std::uint32_t i : indices)
        if (i >= vertexCount) fail(what + ": index " + std::to_string(i) + " out of range (" + std::to_string(vertexCount) + " vertices)");
    return indices;
}

void GltfImporter::blinnPhongExtras(const tinygltf::Value& extras, const std::string& at, Material& m) const {
    if (!extras.IsObject() || !extras.Has("shadowlab")) return;
    const tinygltf::Value& own = extras.Get("shadowlab");
    const std::string where = at + ".extras.shadowlab";
    if (!own.IsObject()) fail(where + ": expected an object");
    auto number = [&](const tinygltf::Value& v, const std::string& key) {
        if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()) || v.GetNumberAsDouble() < 0.0) fail(where + "." + key + ": expected a number of at least 0");
        return static_cast<float>(v.GetNumberAsDouble());
    };
    for (const auto& [key, field] : {std::pair{"ambient", &m.ambient}, std::pair{"diffuse", &m.diffuse}, std::pair{"specular", &m.specular}}) {
        if (!own.Has(key)) continue;
        const tinygltf::Value& v = own.Get(key);
        if (!v.IsArray() || v.ArrayLen() != 3) fail(where + "." + key + ": expected 3 numbers");
        for (int c = 0; c < 3; ++c) (*field)[c] = number(v.Get(c), key);
    }
    if (own.Has("shininess")) {
        m.shininess = number(own.Get("shininess"), "shininess");
        if (!(m.shininess > 0.0f)) fail(where + ".shininess: expected a number greater than 0");
    }
}

Material GltfImporter::material(const tinygltf::Material& src, std::size_t index) {
    Material m;
    m.name = src.name;
    const std::string at = "materials[" + std::to_string(index) + "]";
    const auto& pbr = src.pbrMetallicRoughness;
    for (std::size_t c = 0; c < pbr.baseColorFactor.size(); ++c)
        if (!(pbr.baseColorFactor[c] >= 0.0 && pbr.baseColorFactor[c] <= 1.0))
            fail(at + ".pbrMetallicRoughness.baseColorFactor[" + std::to_string(c) + "]: expected a number in 0..1, got " +
                 text::numberText(pbr.baseColorFactor[c]));
    if (pbr.baseColorFactor.size() >= 3)
        m.baseColor = glm::vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
                                static_cast<float>(pbr.baseColorFactor[2]));
    if (pbr.baseColorFactor.size() >= 4) m.alpha = static_cast<float>(pbr.baseColorFactor[3]);
    // glTF's alphaMode ("OPAQUE" when absent) and alphaCutoff (0.5 by default, >= 0).
    if (src.alphaMode != "OPAQUE" && src.alphaMode != "MASK" && src.alphaMode != "BLEND" && !src.alphaMode.empty())
        fail(at + ".alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\", got \"" + src.alphaMode + "\"");
    m.alphaMode = src.alphaMode == "MASK" ? AlphaMode::Mask : src.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
    if (!(src.alphaCutoff >= 0.0 && src.alphaCutoff <= 1.0))
        fail(at + ".alphaCutoff: expected a number in 0..1, got " + text::numberText(src.alphaCutoff));
    m.alphaCutoff = static_cast<float>(src.alphaCutoff);
    blinnPhongExtras(src.extras, at, m);
    const int tex = pbr.baseColorTexture.index;
    if (tex >= 0 && tex < static_cast<int>(gltf_.textures.size())) {
        const int source = gltf_.textures[tex].source;
        if (source >= 0) m.baseColorTexture = image(source); // -1 e.g. for extension-only (KTX2) sources
    }
    return m;
}

int GltfImporter::image(int index) {
    if (auto it = imageCache_.find(index); it != imageCache_.end()) return it->second;
    if (index >= static_cast<int>(gltf_.images.size())) fail("image index " + std::to_string(index) + " out of range");
    const tinygltf::Image& src = gltf_.images[index];
    const std::string uri = src.uri.rfind("data:", 0) == 0 ? "data URI" : src.uri; // a data URI is megabytes of base64
    const std::string what = "image " + std::to_string(index) + " ('" + (src.name.empty() ? uri : src.name) + "')";
    const int channels = src.component, bytesPerChannel = src.bits == 16 ? 2 : 1;
    if (src.width <= 0 || src.height <= 0 || channels < 1 || channels > 4 || (src.bits != 8 && src.bits != 16))
        fail(what + ": no decoded pixel data");
    if (src.width > kMaxImageSide || src.height > kMaxImageSide)
        fail(what + ": " + std::to_string(src.width) + "x" + std::to_string(src.height) + " exceeds the limit of " +
             std::to_string(kMaxImageSide) + " pixels per side");
    const std::size_t pixels = static_cast<std::size_t>(src.width) * static_cast<std::size_t>(src.height);
    if (pixels > kMaxImagePixels) fail(what + ": " + std::to_string(pixels) + " pixels exceeds the limit of " + std::to_string(kMaxImagePixels));
    if (src.image.size() / static_cast<std::size_t>(channels * bytesPerChannel) < pixels) fail(what + ": truncated pixel data");

    ImageRGBA8 img;
    img.width = src.width;
    img.height = src.height;
    img.pixels.resize(pixels * 4);
    const auto channel = [&](std::size_t pixel, int c) -> std::uint8_t {
        const std::size_t at = (pixel * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)) * static_cast<std::size_t>(bytesPerChannel);
        if (bytesPerChannel == 1) return src.image[at];
        std::uint16_t v;
        std::memcpy(&v, &src.image[at], 2);                  // stb returns native-endian uint16
        return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u); // round to nearest 8-bit value
    };
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint8_t* d = &img.pixels[i * 4];
        if (channels <= 2) { // grey (+ alpha)
            d[0] = d[1] = d[2] = channel(i, 0);
            d[3] = channels == 2 ? channel(i, 1) : 255;
        } else {
            d[0] = channel(i, 0);
            d[1] = channel(i, 1);
            d[2] = channel(i, 2);
            d[3] = channels == 4 ? channel(i, 3) : 255;
        }
    }
    const int result = static_cast<int>(out_.textures.size());
    out_.textures.push_back(std::move(img));
    out_.textureSources.push_back(what);
    imageCache_[index] = result;
    return result;
}

} // namespace shadowlab::gltf
