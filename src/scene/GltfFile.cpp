// Loading glTF 2.0 (.gltf, .glb) through tinygltf (see MeshFile.h).
//
// Every index, offset, stride and count read from the file is checked in
// overflow-safe arithmetic before any byte is read; the node graph is walked
// with an explicit stack, so a deep hierarchy cannot overflow the call stack.
#include "scene/GltfImporter.h"
#include "scene/GltfSchema.h"
#include "scene/MeshFile.h"

#include <shadowlab/Text.h>

#include <shadowlab/Error.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>

namespace shadowlab {

namespace fs = std::filesystem;
using namespace meshfile;
using gltf::GltfImporter;

namespace {

/// tinygltf's error text as one line: newlines become "; " and embedded
/// base64 payloads (tinygltf quotes whole data URIs) are shortened.
std::string oneLine(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    // nlohmann's "[json.exception.parse_error.101] " prefix says nothing to a user.
    if (const auto pos = s.find("[json.exception."); pos != std::string::npos) {
        const auto end = s.find("] ", pos);
        if (end != std::string::npos) s.erase(pos, end + 2 - pos);
    }
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '\r') continue;
        if (c != '\n' && (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)) {
            out += '?';  // bytes quoted from a binary file must not break the line
        } else if (c == '\n') {
            out += "; ";
        } else if (c == ',' && out.size() >= 6 && out.compare(out.size() - 6, 6, "base64") == 0) {
            std::size_t end = i + 1;
            while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '+' || s[end] == '/' || s[end] == '='))
                ++end;
            out += ',';
            out.append(s, i + 1, std::min<std::size_t>(end - i - 1, 16));
            if (end - i - 1 > 16) out += "...";
            i = end - 1;
        } else {
            out += c;
        }
    }
    return out;
}



} // namespace

namespace {

/// tinygltf's image loader, after a look at the header: an image past
/// kMaxImageSide or kMaxImagePixels is refused before it is decoded, so a
/// small PNG declaring 60000x60000 pixels cannot exhaust memory.
bool loadImageChecked(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int reqWidth, int reqHeight,
                      const unsigned char* bytes, int size, void* user) {
    int w = 0, h = 0, channels = 0;
    if (stbi_info_from_memory(bytes, size, &w, &h, &channels) &&
        (w > kMaxImageSide || h > kMaxImageSide || static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > kMaxImagePixels)) {
        if (err)
            *err += "image " + std::to_string(index) + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " +
                    std::to_string(kMaxImageSide) + " pixels per side and " + std::to_string(kMaxImagePixels) + " pixels\n";
        return false;
    }
    return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size, user);
}

/// tinygltf's file access for external URIs, limited to regular files: its
/// own reader takes a directory's size as 2^63 - 1 and allocates that.
bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return fs::exists(path, ec); // a directory exists; reading it is the error
}

bool readWholeFileChecked(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        if (err) *err += "'" + path + "' is not a regular file\n";
        return false;
    }
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec || size > kMaxExternalFileBytes) {
        if (err) *err += "'" + path + "': " + (ec ? ec.message() : "larger than " + std::to_string(kMaxExternalFileBytes) + " bytes") + "\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(static_cast<std::size_t>(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        if (err) *err += "'" + path + "': read error\n";
        return false;
    }
    return true;
}

std::uint32_t readLittleEndian32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<std::uint8_t>(bytes[at + static_cast<std::size_t>(k)]);
    return v;
}

/// The JSON text of a .gltf, or the JSON chunk of a .glb (glTF 2.0, section 4.4), for the depth check.
std::string_view jsonPart(const std::string& bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20) return {};
    const std::size_t length = readLittleEndian32(bytes, 12);
    return std::string_view(bytes).substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

} // namespace

ImportedModel loadGltf(const fs::path& path) {
    const bool binary = lowercaseExtension(path) == ".glb";
    const fs::path dir = path.parent_path();
    return parseGltf(readWholeFile(path), displayName(path), dir.empty() ? fs::path(".") : dir, binary);
}

ImportedModel parseGltf(const std::string& bytes, const std::string& file, const fs::path& baseDir, bool binary) {
    if (binary) {
        if (bytes.size() < 4 || std::memcmp(bytes.data(), "glTF", 4) != 0)
            throw Error(file + ": not a binary glTF file (missing 'glTF' magic)");
        if (bytes.size() >= 8) {
            std::uint32_t version = 0;
            std::memcpy(&version, bytes.data() + 4, 4);  // little-endian, as the format and this machine are
            if (version != 2) throw Error(file + ": binary glTF version " + std::to_string(version) + " (expected 2)");
        }
    } else {
        const std::size_t first = bytes.find_first_not_of(" \t\r\n\f\v");
        if (first == std::string::npos || bytes[first] != '{') throw Error(file + ": not a glTF JSON file (expected '{' at the start)");
    }
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) throw Error(file + ": larger than 4 GB");
    if (text::jsonDepth(jsonPart(bytes, binary)) > text::kMaxJsonDepth)
        throw Error(file + ": JSON nested deeper than " + std::to_string(text::kMaxJsonDepth) + " levels");
    checkGltfTypes(jsonPart(bytes, binary), file);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&loadImageChecked, nullptr);
    loader.SetFsCallbacks({&fileExists, &tinygltf::ExpandFilePath, &readWholeFileChecked, &tinygltf::WriteWholeFile, nullptr});
    tinygltf::Model model;
    std::string err, warn;
    const auto length = static_cast<unsigned int>(bytes.size());
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), length,
                                                  baseDir.string())
                    : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), length, baseDir.string());
    } catch (const std::exception& e) {
        // tinygltf can throw from inside its loader (found by fuzzing: a
        // buffer of byteLength 0 beside a BIN chunk reaches vector::at on
        // an empty vector); every such failure is this file's named error.
        throw Error(text::escapeControl(file + ": not a valid glTF file (the glTF loader failed: " + oneLine(e.what()) + ")"));
    }
    if (!ok) throw Error(text::escapeControl(file + ": " + (err.empty() ? std::string("failed to load glTF") : oneLine(err))));
    return GltfImporter(file, model).run();
}

} // namespace shadowlab
