// Loading triangle meshes from Wavefront OBJ and glTF 2.0 files (see MeshFile.h).
//
// uv convention: v = 0 is the top row of the image (glTF's convention, and
// ImageRGBA8 stores rows top to bottom). OBJ's vt has v = 0 at the bottom,
// so OBJ texture coordinates are flipped on import (v' = 1 - v).
#include "scene/MeshFile.h"

#include <shadowlab/Text.h>

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

namespace fs = std::filesystem;

namespace meshfile {

std::string displayName(const fs::path& path) { return path.string(); }

void requireRegularFile(const fs::path& path) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (status.type() == fs::file_type::none) throw Error(displayName(path) + ": " + ec.message());
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

} // namespace meshfile

namespace {

using namespace meshfile;

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
        throw Error(text::escapeControl(file + ":" + std::to_string(line) + ": " + what));
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
        if (!std::isfinite(value))
            fail("number '" + std::string(word) + "' after '" + std::string(keyword) + "' is not finite or past a 32-bit float's range (about 3.4e38)");
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

// What an OBJ file defines, line by line: its vertex data, faces and names.
struct ObjData {
    std::vector<glm::vec3> positions, normals;
    std::vector<bool> normalValid; // false for zero-length vn (treated as absent)
    std::vector<glm::vec2> texcoords;
    std::vector<ObjFace> faces;
    std::string objectName, groupName;
};

// An "f" line's corners (words[0] is "f"), indexed against what `obj`
// defines so far.
ObjFace readFace(const ObjParser& p, const std::vector<std::string_view>& words, const ObjData& obj) {
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
        c.v = p.index(parts[0], corner, static_cast<int>(obj.positions.size()), "vertex");
        if (!parts[1].empty()) c.vt = p.index(parts[1], corner, static_cast<int>(obj.texcoords.size()), "texture coordinate");
        if (!parts[2].empty()) c.vn = p.index(parts[2], corner, static_cast<int>(obj.normals.size()), "normal");
        face.corners.push_back(c);
    }
    return face;
}

// One line of the file (line p.line) into `obj`.
void readLine(const ObjParser& p, std::string_view lineText, ObjData& obj) {
    if (const std::size_t hash = lineText.find('#'); hash != std::string_view::npos) lineText = lineText.substr(0, hash);
    lineText = trim(lineText);
    if (lineText.empty()) return;
    const std::vector<std::string_view> words = splitWords(lineText);
    const std::string_view key = words[0];

    if (key == "v") {
        const auto v = p.numbers(words, 3, 3); // optional w / vertex colours ignored
        obj.positions.emplace_back(v[0], v[1], v[2]);
    } else if (key == "vt") {
        const auto t = p.numbers(words, 1, 2); // v defaults to 0, w ignored
        obj.texcoords.emplace_back(t[0], 1.0f - (t.size() > 1 ? t[1] : 0.0f));
    } else if (key == "vn") {
        const auto n = p.numbers(words, 3, 3);
        const glm::vec3 v(n[0], n[1], n[2]);
        const float len = glm::length(v);
        const bool ok = std::isfinite(len) && len > 0.0f;
        obj.normals.push_back(ok ? v / len : glm::vec3(0.0f));
        obj.normalValid.push_back(ok);
    } else if (key == "f") {
        obj.faces.push_back(readFace(p, words, obj));
    } else if (key == "o") {
        if (obj.objectName.empty() && words.size() > 1) obj.objectName = std::string(trim(lineText.substr(1)));
    } else if (key == "g") {
        if (obj.groupName.empty() && words.size() > 1) obj.groupName = std::string(trim(lineText.substr(1)));
    }
    // Everything else (mtllib, usemtl, s, l, p, vp, curves, ...) is ignored.
}

// The whole file, line by line (p.line counts them).
ObjData readObj(std::string_view text, ObjParser& p) {
    ObjData obj;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string::npos) eol = text.size();
        std::string_view lineText(text.data() + pos, eol - pos);
        pos = eol + 1;
        ++p.line;
        readLine(p, lineText, obj);
    }
    return obj;
}

// Range-checks the indices against the whole file (forward references are
// legal). Returns whether any corner has a texture coordinate.
bool checkRanges(ObjParser& p, const ObjData& obj) {
    const auto checkRange = [&](int line, int index, std::size_t count, const char* kind) {
        if (index >= static_cast<int>(count)) {
            p.line = line;
            p.fail(std::string(kind) + " index " + std::to_string(index + 1) + " out of range (file has " + countOf(count, kind) + ")");
        }
    };
    bool anyTexcoords = false;
    for (const ObjFace& f : obj.faces) {
        for (const ObjCorner& c : f.corners) {
            checkRange(f.line, c.v, obj.positions.size(), "vertex");
            checkRange(f.line, c.vt, obj.texcoords.size(), "texture coordinate");
            checkRange(f.line, c.vn, obj.normals.size(), "normal");
            anyTexcoords = anyTexcoords || c.vt >= 0;
        }
    }
    return anyTexcoords;
}

// Flat normal of the polygon by Newell's method (exact for planar
// polygons, a sensible average otherwise).
glm::vec3 newellNormal(const std::vector<glm::vec3>& positions, const ObjFace& f) {
    glm::vec3 n(0.0f);
    for (std::size_t i = 0; i < f.corners.size(); ++i) {
        const glm::vec3& a = positions[f.corners[i].v];
        const glm::vec3& b = positions[f.corners[(i + 1) % f.corners.size()].v];
        n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const float len = glm::length(n);
    n = (std::isfinite(len) && len > 0.0f) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f); // degenerate face
    return n;
}

// The mesh of the file `name`'s faces, as triangle fans: corners with the
// same (v, vt, vn) share a vertex, a face without (valid) normals gets its
// own vertices with its flat normal; uvs only when the file uses them.
Mesh buildMesh(const ObjData& obj, bool anyTexcoords, const std::string& name) {
    Mesh mesh;
    mesh.name = !obj.objectName.empty() ? obj.objectName : !obj.groupName.empty() ? obj.groupName : fs::path(name).stem().string();
    std::unordered_map<ObjCorner, std::uint32_t, ObjCornerHash> shared; // dedup of (v, vt, vn)
    const auto addVertex = [&](const ObjCorner& c, const glm::vec3& normal) {
        mesh.positions.push_back(obj.positions[c.v]);
        mesh.normals.push_back(normal);
        if (anyTexcoords) mesh.uvs.push_back(c.vt >= 0 ? obj.texcoords[c.vt] : glm::vec2(0.0f));
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };

    std::vector<std::uint32_t> ids;
    for (const ObjFace& f : obj.faces) {
        ids.clear();
        const bool hasNormals = std::all_of(f.corners.begin(), f.corners.end(), [&](const ObjCorner& c) { return c.vn >= 0 && obj.normalValid[c.vn]; });
        if (hasNormals) {
            for (const ObjCorner& c : f.corners) {
                const auto [it, inserted] = shared.try_emplace(c, 0u);
                if (inserted) it->second = addVertex(c, obj.normals[c.vn]);
                ids.push_back(it->second);
            }
        } else {
            // The face gets its own vertices, with its flat normal.
            const glm::vec3 n = newellNormal(obj.positions, f);
            for (const ObjCorner& c : f.corners) ids.push_back(addVertex(c, n));
        }
        for (std::size_t i = 1; i + 1 < ids.size(); ++i) // triangle fan
            mesh.indices.insert(mesh.indices.end(), {ids[0], ids[i], ids[i + 1]});
    }
    return mesh;
}

} // namespace

ImportedModel loadObj(const fs::path& path) { return parseObj(readWholeFile(path), displayName(path)); }

ImportedModel parseObj(std::string_view text, const std::string& name) {
    ObjParser p{name};
    // OBJ is text; a NUL byte means some other file with an .obj name.
    if (text.find('\0') != std::string_view::npos) throw Error(p.file + ": not a Wavefront OBJ file (binary data)");

    const ObjData obj = readObj(text, p);
    const bool anyTexcoords = checkRanges(p, obj);
    if (obj.faces.empty()) throw Error(p.file + ": no triangles");

    Mesh mesh = buildMesh(obj, anyTexcoords, name);
    ImportedModel model;
    ImportedModel::Node node;
    node.name = mesh.name;
    node.primitives.push_back({0, -1});
    model.meshes.push_back(std::move(mesh));
    model.nodes.push_back(std::move(node));
    return model;
}

ImportedModel loadMeshFile(const fs::path& path) {
    using meshfile::lowercaseExtension, meshfile::displayName;
    const std::string ext = lowercaseExtension(path);
    if (ext == ".obj") return loadObj(path);
    if (ext == ".gltf" || ext == ".glb") return loadGltf(path);
    throw Error(displayName(path) + ": unsupported mesh format (expected .obj, .gltf or .glb)");
}

} // namespace shadowlab
