// Loading triangle meshes from Wavefront OBJ and glTF 2.0 files (see MeshFile.h).
//
// uv convention: v = 0 is the top row of the image (glTF's convention, and
// ImageRGBA8 stores rows top to bottom). OBJ's vt has v = 0 at the bottom,
// so OBJ texture coordinates are flipped on import (v' = 1 - v).
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string_view>
#include <unordered_map>

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

std::string displayName(const fs::path& path) { return path.string(); }

/// Throws "<file>: file not found" (or not a regular file) before parsing.
void requireRegularFile(const fs::path& path) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (!fs::exists(status)) throw Error(displayName(path) + ": file not found");
    if (!fs::is_regular_file(status)) throw Error(displayName(path) + ": not a regular file");
}

std::string readWholeFile(const fs::path& path) {
    requireRegularFile(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(displayName(path) + ": cannot open file for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw Error(displayName(path) + ": read error");
    return std::move(ss).str();
}

std::string lowercaseExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

/// Area-weighted vertex normals: each triangle adds cross(b-a, c-a), whose
/// length is twice its area, to its three vertices; the sums are normalised.
std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    std::vector<glm::vec3> sums(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        sums[a] += n;
        sums[b] += n;
        sums[c] += n;
    }
    for (glm::vec3& n : sums) {
        const float len = glm::length(n);
        n = (std::isfinite(len) && len > 0.0f) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f); // unused or degenerate vertex
    }
    return sums;
}

// ---------------------------------------------------------------------------
// Wavefront OBJ

std::string_view trim(std::string_view s) {
    const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> splitWords(std::string_view s) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
        if (i > start) words.push_back(s.substr(start, i - start));
    }
    return words;
}

/// "1 vertex", "12 vertices", "0 normals", ...
std::string countOf(std::size_t count, std::string_view kind) {
    std::string s = std::to_string(count) + " " + std::string(kind);
    if (count != 1) s = kind == "vertex" ? std::to_string(count) + " vertices" : s + "s";
    return s;
}

struct ObjParser {
    std::string file; // for messages
    int line = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(file + ":" + std::to_string(line) + ": " + what);
    }

    float number(std::string_view word, std::string_view keyword) const {
        std::string_view digits = word;
        if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1); // from_chars rejects '+'
        float value = 0.0f;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if ((ec != std::errc() && ec != std::errc::result_out_of_range) || end != digits.data() + digits.size())
            fail("bad number '" + std::string(word) + "' after '" + std::string(keyword) + "'");
        if (ec == std::errc::result_out_of_range) // overflow becomes +-inf (rejected below), underflow 0 or denormal
            value = std::strtof(std::string(digits).c_str(), nullptr);
        if (!std::isfinite(value)) fail("non-finite number '" + std::string(word) + "' after '" + std::string(keyword) + "'");
        return value;
    }

    /// Reads at least `minCount` (at most maxCount are used) numbers after the keyword.
    std::vector<float> numbers(const std::vector<std::string_view>& words, std::size_t minCount, std::size_t maxCount) const {
        if (words.size() - 1 < minCount)
            fail("expected " + std::to_string(minCount) + " numbers after '" + std::string(words[0]) + "', got " + std::to_string(words.size() - 1));
        std::vector<float> values;
        for (std::size_t i = 1; i < words.size() && values.size() < maxCount; ++i) values.push_back(number(words[i], words[0]));
        return values;
    }

    /// Parses one OBJ index (1-based, or negative = relative to the `count`
    /// elements defined so far) into a 0-based index; range against the
    /// final count is checked later (positive indices may refer forward).
    int index(std::string_view text, std::string_view corner, int count, const char* kind) const {
        int value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || text.empty())
            fail("bad " + std::string(kind) + " index '" + std::string(text) + "' in face corner '" + std::string(corner) + "'");
        if (value == 0) fail(std::string(kind) + " index 0 is invalid (OBJ indices start at 1)");
        if (value > 0) return value - 1;
        if (count + value < 0)
            fail(std::string(kind) + " index " + std::to_string(value) + " out of range (" + countOf(static_cast<std::size_t>(count), kind) + " defined so far)");
        return count + value;
    }
};

struct ObjCorner {
    int v = -1, vt = -1, vn = -1;
    bool operator==(const ObjCorner&) const = default;
};

struct ObjCornerHash {
    std::size_t operator()(const ObjCorner& c) const {
        std::size_t h = std::hash<int>()(c.v);
        h = h * 1000003u ^ std::hash<int>()(c.vt);
        h = h * 1000003u ^ std::hash<int>()(c.vn);
        return h;
    }
};

struct ObjFace {
    int line = 0;
    std::vector<ObjCorner> corners;
};

} // namespace

ImportedModel loadObj(const fs::path& path) {
    const std::string text = readWholeFile(path);
    ObjParser p{displayName(path)};
    // OBJ is text; a NUL byte means some other file with an .obj name.
    if (text.find('\0') != std::string::npos) throw Error(p.file + ": not a Wavefront OBJ file (binary data)");

    std::vector<glm::vec3> positions, normals;
    std::vector<bool> normalValid; // false for zero-length vn (treated as absent)
    std::vector<glm::vec2> texcoords;
    std::vector<ObjFace> faces;
    std::string objectName, groupName;

    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string::npos) eol = text.size();
        std::string_view lineText(text.data() + pos, eol - pos);
        pos = eol + 1;
        ++p.line;

        if (const std::size_t hash = lineText.find('#'); hash != std::string_view::npos) lineText = lineText.substr(0, hash);
        lineText = trim(lineText);
        if (lineText.empty()) continue;
        const std::vector<std::string_view> words = splitWords(lineText);
        const std::string_view key = words[0];

        if (key == "v") {
            const auto v = p.numbers(words, 3, 3); // optional w / vertex colours ignored
            positions.emplace_back(v[0], v[1], v[2]);
        } else if (key == "vt") {
            const auto t = p.numbers(words, 1, 2); // v defaults to 0, w ignored
            texcoords.emplace_back(t[0], 1.0f - (t.size() > 1 ? t[1] : 0.0f));
        } else if (key == "vn") {
            const auto n = p.numbers(words, 3, 3);
            const glm::vec3 v(n[0], n[1], n[2]);
            const float len = glm::length(v);
            const bool ok = std::isfinite(len) && len > 0.0f;
            normals.push_back(ok ? v / len : glm::vec3(0.0f));
            normalValid.push_back(ok);
        } else if (key == "f") {
            if (words.size() < 4) p.fail("face needs at least 3 vertices, got " + std::to_string(words.size() - 1));
            ObjFace face{p.line, {}};
            for (std::size_t i = 1; i < words.size(); ++i) {
                // Forms: v, v/vt, v//vn, v/vt/vn.
                const std::string_view corner = words[i];
                std::array<std::string_view, 3> parts{};
                std::size_t part = 0, start = 0;
                for (std::size_t k = 0; k <= corner.size(); ++k) {
                    if (k == corner.size() || corner[k] == '/') {
                        if (part == 3) p.fail("bad face corner '" + std::string(corner) + "'");
                        parts[part++] = corner.substr(start, k - start);
                        start = k + 1;
                    }
                }
                ObjCorner c;
                c.v = p.index(parts[0], corner, static_cast<int>(positions.size()), "vertex");
                if (!parts[1].empty()) c.vt = p.index(parts[1], corner, static_cast<int>(texcoords.size()), "texture coordinate");
                if (!parts[2].empty()) c.vn = p.index(parts[2], corner, static_cast<int>(normals.size()), "normal");
                face.corners.push_back(c);
            }
            faces.push_back(std::move(face));
        } else if (key == "o") {
            if (objectName.empty() && words.size() > 1) objectName = std::string(trim(lineText.substr(1)));
        } else if (key == "g") {
            if (groupName.empty() && words.size() > 1) groupName = std::string(trim(lineText.substr(1)));
        }
        // Everything else (mtllib, usemtl, s, l, p, vp, curves, ...) is ignored.
    }

    // Range-check the indices against the whole file (forward references are legal).
    const auto checkRange = [&](int line, int index, std::size_t count, const char* kind) {
        if (index >= static_cast<int>(count)) {
            p.line = line;
            p.fail(std::string(kind) + " index " + std::to_string(index + 1) + " out of range (file has " + countOf(count, kind) + ")");
        }
    };
    bool anyTexcoords = false;
    for (const ObjFace& f : faces) {
        for (const ObjCorner& c : f.corners) {
            checkRange(f.line, c.v, positions.size(), "vertex");
            checkRange(f.line, c.vt, texcoords.size(), "texture coordinate");
            checkRange(f.line, c.vn, normals.size(), "normal");
            anyTexcoords = anyTexcoords || c.vt >= 0;
        }
    }
    if (faces.empty()) throw Error(p.file + ": no triangles");

    Mesh mesh;
    mesh.name = !objectName.empty() ? objectName : !groupName.empty() ? groupName : path.stem().string();
    std::unordered_map<ObjCorner, std::uint32_t, ObjCornerHash> shared; // dedup of (v, vt, vn)
    const auto addVertex = [&](const ObjCorner& c, const glm::vec3& normal) {
        mesh.positions.push_back(positions[c.v]);
        mesh.normals.push_back(normal);
        if (anyTexcoords) mesh.uvs.push_back(c.vt >= 0 ? texcoords[c.vt] : glm::vec2(0.0f));
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };

    std::vector<std::uint32_t> ids;
    for (const ObjFace& f : faces) {
        ids.clear();
        const bool hasNormals = std::all_of(f.corners.begin(), f.corners.end(), [&](const ObjCorner& c) { return c.vn >= 0 && normalValid[c.vn]; });
        if (hasNormals) {
            for (const ObjCorner& c : f.corners) {
                const auto [it, inserted] = shared.try_emplace(c, 0u);
                if (inserted) it->second = addVertex(c, normals[c.vn]);
                ids.push_back(it->second);
            }
        } else {
            // Flat normal of the polygon by Newell's method (exact for planar
            // polygons, a sensible average otherwise); the face gets its own vertices.
            glm::vec3 n(0.0f);
            for (std::size_t i = 0; i < f.corners.size(); ++i) {
                const glm::vec3& a = positions[f.corners[i].v];
                const glm::vec3& b = positions[f.corners[(i + 1) % f.corners.size()].v];
                n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            }
            const float len = glm::length(n);
            n = (std::isfinite(len) && len > 0.0f) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f); // degenerate face
            for (const ObjCorner& c : f.corners) ids.push_back(addVertex(c, n));
        }
        for (std::size_t i = 1; i + 1 < ids.size(); ++i) // triangle fan
            mesh.indices.insert(mesh.indices.end(), {ids[0], ids[i], ids[i + 1]});
    }

    ImportedModel model;
    ImportedModel::Node node;
    node.name = mesh.name;
    node.primitives.push_back({0, -1});
    model.meshes.push_back(std::move(mesh));
    model.nodes.push_back(std::move(node));
    return model;
}

// ---------------------------------------------------------------------------
// glTF 2.0

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

class GltfImporter {
public:
    GltfImporter(const fs::path& path, const tinygltf::Model& gltf) : file_(displayName(path)), gltf_(gltf) {}

    ImportedModel run() {
        for (const tinygltf::Material& m : gltf_.materials) out_.materials.push_back(material(m));

        // Roots: the default scene, else scene 0, else every node no one references.
        std::vector<int> roots;
        if (!gltf_.scenes.empty()) {
            const int scene = gltf_.defaultScene >= 0 && gltf_.defaultScene < static_cast<int>(gltf_.scenes.size()) ? gltf_.defaultScene : 0;
            roots = gltf_.scenes[scene].nodes;
        } else {
            std::vector<bool> isChild(gltf_.nodes.size(), false);
            for (const tinygltf::Node& n : gltf_.nodes)
                for (int c : n.children)
                    if (c >= 0 && c < static_cast<int>(isChild.size())) isChild[c] = true;
            for (std::size_t i = 0; i < gltf_.nodes.size(); ++i)
                if (!isChild[i]) roots.push_back(static_cast<int>(i));
            if (roots.empty() && !gltf_.nodes.empty()) fail("node hierarchy has no root node (cycle)");
        }
        visited_.assign(gltf_.nodes.size(), false);
        for (int r : roots) addNode(r, -1);

        std::size_t triangles = 0;
        for (const Mesh& m : out_.meshes) triangles += m.triangleCount();
        if (triangles == 0) throw Error(file_ + ": no triangles");
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(file_ + ": " + what); }

    void addNode(int index, int parent) {
        if (index < 0 || index >= static_cast<int>(gltf_.nodes.size())) fail("node index " + std::to_string(index) + " out of range");
        if (visited_[index]) fail("node " + std::to_string(index) + " is referenced more than once (cycle or shared node)");
        visited_[index] = true;
        const tinygltf::Node& src = gltf_.nodes[index];

        ImportedModel::Node node;
        node.name = src.name;
        node.parent = parent;
        if (src.matrix.size() == 16) {
            glm::mat4 m;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(src.matrix[static_cast<std::size_t>(c * 4 + r)]); // column-major
            glm::vec3 skew;
            glm::vec4 perspective;
            if (!glm::decompose(m, node.scale, node.rotation, node.translation, skew, perspective))
                fail("node " + std::to_string(index) + " ('" + src.name + "'): matrix cannot be decomposed");
        } else {
            if (src.translation.size() == 3)
                node.translation = glm::vec3(static_cast<float>(src.translation[0]), static_cast<float>(src.translation[1]), static_cast<float>(src.translation[2]));
            if (src.rotation.size() == 4) // glTF stores x, y, z, w; glm::quat's constructor takes w first
                node.rotation = glm::normalize(glm::quat(static_cast<float>(src.rotation[3]), static_cast<float>(src.rotation[0]),
                                                         static_cast<float>(src.rotation[1]), static_cast<float>(src.rotation[2])));
            if (src.scale.size() == 3)
                node.scale = glm::vec3(static_cast<float>(src.scale[0]), static_cast<float>(src.scale[1]), static_cast<float>(src.scale[2]));
        }
        if (src.mesh >= 0) {
            if (src.mesh >= static_cast<int>(gltf_.meshes.size())) fail("node " + std::to_string(index) + ": mesh index out of range");
            const tinygltf::Mesh& mesh = gltf_.meshes[src.mesh];
            for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
                const int imported = primitiveMesh(src.mesh, static_cast<int>(p));
                if (imported < 0) continue;
                int mat = mesh.primitives[p].material;
                if (mat >= static_cast<int>(out_.materials.size())) fail("mesh '" + mesh.name + "': material index " + std::to_string(mat) + " out of range");
                node.primitives.push_back({imported, mat < 0 ? -1 : mat});
            }
        }
        const int self = static_cast<int>(out_.nodes.size());
        out_.nodes.push_back(std::move(node));
        for (int child : src.children) addNode(child, self); // parents before children
    }

    /// Imports (once) primitive p of glTF mesh m; -1 if it has no triangles.
    int primitiveMesh(int m, int p) {
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

    Mesh readPrimitive(const tinygltf::Mesh& src, const tinygltf::Primitive& prim, int p) {
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

    /// Checks that accessor elements of `elementSize` bytes lie inside their
    /// buffer; returns the first byte and the stride (0 if no buffer view).
    std::pair<const unsigned char*, std::size_t> locate(const tinygltf::Accessor& acc, int index, const std::string& what,
                                                        std::size_t elementSize) const {
        if (acc.sparse.isSparse) fail(what + ": sparse accessors are not supported");
        if (acc.bufferView < 0) return {nullptr, 0}; // all zeros by the spec
        if (acc.bufferView >= static_cast<int>(gltf_.bufferViews.size())) fail(what + ": bufferView out of range");
        const tinygltf::BufferView& view = gltf_.bufferViews[acc.bufferView];
        if (view.buffer < 0 || view.buffer >= static_cast<int>(gltf_.buffers.size())) fail(what + ": buffer out of range");
        const tinygltf::Buffer& buffer = gltf_.buffers[view.buffer];
        const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
        const std::size_t needed = acc.count == 0 ? 0 : acc.byteOffset + stride * (acc.count - 1) + elementSize;
        if (view.byteOffset + view.byteLength > buffer.data.size() || needed > view.byteLength)
            fail(what + ": accessor " + std::to_string(index) + " reads past the end of its buffer");
        return {buffer.data.data() + view.byteOffset + acc.byteOffset, stride};
    }

    template <int N>
    std::vector<glm::vec<N, float>> readVectors(int index, const char* semantic) const {
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

    std::vector<std::uint32_t> readIndices(int index, std::size_t vertexCount) const {
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

    Material material(const tinygltf::Material& src) {
        Material m;
        m.name = src.name;
        const auto& pbr = src.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() >= 3) // alpha ignored
            m.baseColor = glm::vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
                                    static_cast<float>(pbr.baseColorFactor[2]));
        const int tex = pbr.baseColorTexture.index;
        if (tex >= 0 && tex < static_cast<int>(gltf_.textures.size())) {
            const int source = gltf_.textures[tex].source;
            if (source >= 0) m.baseColorTexture = image(source); // -1 e.g. for extension-only (KTX2) sources
        }
        return m;
    }

    /// Converts (once) image `index` to RGBA8 and returns its index in out_.textures.
    int image(int index) {
        if (auto it = imageCache_.find(index); it != imageCache_.end()) return it->second;
        if (index >= static_cast<int>(gltf_.images.size())) fail("image index " + std::to_string(index) + " out of range");
        const tinygltf::Image& src = gltf_.images[index];
        const std::string what = "image " + std::to_string(index) + " ('" + (src.name.empty() ? src.uri : src.name) + "')";
        const int channels = src.component, bytesPerChannel = src.bits == 16 ? 2 : 1;
        if (src.width <= 0 || src.height <= 0 || channels < 1 || channels > 4 || (src.bits != 8 && src.bits != 16))
            fail(what + ": no decoded pixel data");
        const std::size_t pixels = static_cast<std::size_t>(src.width) * static_cast<std::size_t>(src.height);
        if (src.image.size() < pixels * static_cast<std::size_t>(channels * bytesPerChannel)) fail(what + ": truncated pixel data");

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
        imageCache_[index] = result;
        return result;
    }

    std::string file_;
    const tinygltf::Model& gltf_;
    ImportedModel out_;
    std::vector<bool> visited_;
    std::map<std::pair<int, int>, int> meshCache_;
    std::map<int, int> imageCache_;
};

} // namespace

ImportedModel loadGltf(const fs::path& path) {
    requireRegularFile(path);
    const std::string file = displayName(path);
    const bool binary = lowercaseExtension(path) == ".glb";
    if (binary) {
        std::ifstream in(path, std::ios::binary);
        char magic[4] = {};
        if (!in.read(magic, 4) || std::memcmp(magic, "glTF", 4) != 0)
            throw Error(file + ": not a binary glTF file (missing 'glTF' magic)");
    } else {
        std::ifstream in(path, std::ios::binary);
        char first = 0;
        while (in.get(first) && std::isspace(static_cast<unsigned char>(first))) {}
        if (first != '{') throw Error(file + ": not a glTF JSON file (expected '{' at the start)");
    }
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                           : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
    if (!ok) throw Error(file + ": " + (err.empty() ? std::string("failed to load glTF") : oneLine(err)));
    return GltfImporter(path, model).run();
}

ImportedModel loadMeshFile(const fs::path& path) {
    const std::string ext = lowercaseExtension(path);
    if (ext == ".obj") return loadObj(path);
    if (ext == ".gltf" || ext == ".glb") return loadGltf(path);
    throw Error(displayName(path) + ": unsupported mesh format (expected .obj, .gltf or .glb)");
}

} // namespace shadowlab
