// Loading OBJ and glTF files written into a temporary directory: geometry,
// normals, uvs, hierarchy, materials and textures, and every error path.
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>

#include "ErrorText.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using shadowlab::ImportedModel;
using shadowlab::Mesh;

// ---------------------------------------------------------------------------
// Helpers

/// Expects a shadowlab::Error whose single-line message contains every part.
void expectError(const std::function<void()>& f, const std::vector<std::string>& parts) {
    const std::string msg = errorOf(f);
    for (const std::string& part : parts)
        EXPECT_NE(msg.find(part), std::string::npos) << "message: " << msg << "\nexpected to contain: " << part;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
}

class MeshFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::random_device rd;
        dir_ = fs::temp_directory_path() /
               ("shadowlab-meshfile-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
                std::to_string(rd()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    fs::path write(const std::string& name, const std::string& content) const {
        const fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << content;
        return p;
    }

    fs::path dir_;
};

glm::vec3 faceNormal(const Mesh& m, std::size_t tri) {
    const glm::vec3 a = m.positions[m.indices[3 * tri]], b = m.positions[m.indices[3 * tri + 1]],
                    c = m.positions[m.indices[3 * tri + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

double signedVolume(const Mesh& m) { // divergence theorem, > 0 for outward faces
    double v = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
        v += glm::dot(glm::dvec3(m.positions[m.indices[t]]),
                      glm::cross(glm::dvec3(m.positions[m.indices[t + 1]]), glm::dvec3(m.positions[m.indices[t + 2]])));
    return v / 6.0;
}

void expectValidMesh(const Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_TRUE(m.uvs.empty() || m.uvs.size() == m.positions.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

void expectVec(const glm::vec3& actual, const glm::vec3& expected, float tol = 1e-5f) {
    EXPECT_LT(glm::length(actual - expected), tol) << "got (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected ("
                                                   << expected.x << ", " << expected.y << ", " << expected.z << ")";
}

// --- binary helpers for glTF buffers ---

struct Bytes {
    std::vector<std::uint8_t> data;
    template <typename T> Bytes& put(T v) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
        data.insert(data.end(), p, p + sizeof(T));
        return *this;
    }
    Bytes& floats(std::initializer_list<float> vs) {
        for (float v : vs) put(v);
        return *this;
    }
    Bytes& pad4(std::uint8_t fill = 0) {
        while (data.size() % 4) data.push_back(fill);
        return *this;
    }
};

std::string base64(const std::vector<std::uint8_t>& in) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const std::uint32_t n = (std::uint32_t(in[i]) << 16) | (i + 1 < in.size() ? std::uint32_t(in[i + 1]) << 8 : 0u) |
                                (i + 2 < in.size() ? std::uint32_t(in[i + 2]) : 0u);
        out += table[(n >> 18) & 63];
        out += table[(n >> 12) & 63];
        out += i + 1 < in.size() ? table[(n >> 6) & 63] : '=';
        out += i + 2 < in.size() ? table[n & 63] : '=';
    }
    return out;
}

std::string dataUri(const std::vector<std::uint8_t>& bytes, const std::string& mime = "application/octet-stream") {
    return "data:" + mime + ";base64," + base64(bytes);
}

/// Minimal PNG encoder (zlib "stored" blocks, filter 0) so that tests can
/// embed images of any bit depth / colour type without an image library.
std::vector<std::uint8_t> png(int width, int height, int bitDepth, int colorType, const std::vector<std::uint8_t>& samplesBigEndian) {
    const auto crc32 = [](const std::uint8_t* p, std::size_t n) {
        std::uint32_t c = 0xFFFFFFFFu;
        for (std::size_t i = 0; i < n; ++i) {
            c ^= p[i];
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
        }
        return c ^ 0xFFFFFFFFu;
    };
    std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    const auto be32 = [](std::vector<std::uint8_t>& v, std::uint32_t x) {
        for (int s = 24; s >= 0; s -= 8) v.push_back(static_cast<std::uint8_t>(x >> s));
    };
    const auto chunk = [&](const char* type, const std::vector<std::uint8_t>& body) {
        be32(out, static_cast<std::uint32_t>(body.size()));
        std::vector<std::uint8_t> typed(type, type + 4);
        typed.insert(typed.end(), body.begin(), body.end());
        out.insert(out.end(), typed.begin(), typed.end());
        be32(out, crc32(typed.data(), typed.size()));
    };
    std::vector<std::uint8_t> ihdr;
    be32(ihdr, static_cast<std::uint32_t>(width));
    be32(ihdr, static_cast<std::uint32_t>(height));
    ihdr.insert(ihdr.end(), {static_cast<std::uint8_t>(bitDepth), static_cast<std::uint8_t>(colorType), 0, 0, 0});
    chunk("IHDR", ihdr);
    const int channels = colorType == 0 ? 1 : colorType == 2 ? 3 : colorType == 4 ? 2 : 4;
    const std::size_t rowBytes = static_cast<std::size_t>(width * channels * bitDepth / 8);
    std::vector<std::uint8_t> raw;
    for (int y = 0; y < height; ++y) {
        raw.push_back(0); // filter: none
        raw.insert(raw.end(), samplesBigEndian.begin() + static_cast<long>(y * rowBytes),
                   samplesBigEndian.begin() + static_cast<long>((y + 1) * rowBytes));
    }
    std::vector<std::uint8_t> z = {0x78, 0x01, 0x01}; // zlib header, final stored block
    const auto len = static_cast<std::uint16_t>(raw.size());
    z.insert(z.end(), {static_cast<std::uint8_t>(len), static_cast<std::uint8_t>(len >> 8), static_cast<std::uint8_t>(~len),
                       static_cast<std::uint8_t>(~len >> 8)});
    z.insert(z.end(), raw.begin(), raw.end());
    std::uint32_t a = 1, b = 0; // adler32
    for (std::uint8_t c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    be32(z, (b << 16) | a);
    chunk("IDAT", z);
    chunk("IEND", {});
    return out;
}

/// A .glb container: 12-byte header, JSON chunk (space padded), BIN chunk (zero padded).
std::string glb(std::string json, std::vector<std::uint8_t> bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin.push_back(0);
    Bytes b;
    b.data = {'g', 'l', 'T', 'F'};
    b.put<std::uint32_t>(2).put<std::uint32_t>(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    b.put<std::uint32_t>(static_cast<std::uint32_t>(json.size())).put<std::uint32_t>(0x4E4F534A);
    b.data.insert(b.data.end(), json.begin(), json.end());
    b.put<std::uint32_t>(static_cast<std::uint32_t>(bin.size())).put<std::uint32_t>(0x004E4942);
    b.data.insert(b.data.end(), bin.begin(), bin.end());
    return std::string(b.data.begin(), b.data.end());
}

/// One triangle (0,0,0) (1,0,0) (0,1,0) with u16 indices: bytes 0..35 positions, 36..41 indices.
Bytes triangleBuffer() {
    Bytes b;
    b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0});
    b.put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(2).pad4();
    return b;
}

/// glTF JSON around `triangleBuffer` with custom nodes/scenes and primitive extras.
std::string triangleGltf(const std::string& bufferUri, const std::string& nodesAndScenes, const std::string& primitiveExtra = "",
                         const std::string& positionAccessorExtra = "") {
    return R"({
  "asset": {"version": "2.0"},
  )" + nodesAndScenes + R"(,
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1)" + primitiveExtra + R"(}]}],
  "buffers": [{"byteLength": 44, "uri": ")" + bufferUri + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3")" + positionAccessorExtra + R"(},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
}

// ---------------------------------------------------------------------------
// OBJ

TEST_F(MeshFileTest, ObjCubeWithQuadsAndNormalsIsDedupedAndClosed) {
    // Unit cube, quads counter-clockwise seen from outside, v//vn corners.
    const fs::path p = write("cube.obj", R"(# a cube
mtllib cube.mtl
o Cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 -1
vn 0 0 1
vn -1 0 0
vn 1 0 0
vn 0 -1 0
vn 0 1 0
usemtl white
s off
f 1//1 4//1 3//1 2//1
f 5//2 6//2 7//2 8//2
f 1//3 5//3 8//3 4//3
f 2//4 3//4 7//4 6//4
f 1//5 2//5 6//5 5//5
f 4//6 8//6 7//6 3//6
l 1 2
)");
    const ImportedModel model = shadowlab::loadMeshFile(p);
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.nodes.size(), 1u);
    EXPECT_EQ(model.nodes[0].parent, -1);
    ASSERT_EQ(model.nodes[0].primitives.size(), 1u);
    EXPECT_EQ(model.nodes[0].primitives[0].mesh, 0);
    EXPECT_EQ(model.nodes[0].primitives[0].material, -1);
    EXPECT_TRUE(model.materials.empty());
    const Mesh& m = model.meshes[0];
    expectValidMesh(m);
    EXPECT_EQ(m.name, "Cube");
    EXPECT_EQ(m.triangleCount(), 12u);
    EXPECT_EQ(m.positions.size(), 24u); // 6 faces x 4 distinct (v, vn) pairs
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_NEAR(signedVolume(m), 1.0, 1e-6);
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) expectVec(m.normals[m.indices[3 * t + k]], faceNormal(m, t));
}

TEST_F(MeshFileTest, ObjDedupsIdenticalCornersOnly) {
    // Two triangles share corners 1/1/1 and 3/3/1; corner 3 is also used with another vt.
    const fs::path p = write("dedup.obj", R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vt 0.5 0.5
vn 0 0 1
f 1/1/1 2/2/1 3/3/1
f 1/1/1 3/3/1 4/4/1
f 1/1/1 3/5/1 4/4/1
)");
    const Mesh m = shadowlab::loadObj(p).meshes.at(0);
    expectValidMesh(m);
    EXPECT_EQ(m.triangleCount(), 3u);
    EXPECT_EQ(m.positions.size(), 5u); // 4 shared corners + (3, 5, 1)
    EXPECT_EQ(m.indices[0], m.indices[3]);
    EXPECT_EQ(m.indices[2], m.indices[4]);
    EXPECT_NE(m.indices[4], m.indices[7]);
}

TEST_F(MeshFileTest, ObjCornerFormsUvFlipAndNormalisedNormals) {
    const fs::path p = write("forms.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0\r\n"
                                          "vt 0.25 0.75\r\nvt 1 0\r\nvt 0 1 0\r\n"
                                          "vn 0 0 2\r\n"
                                          "g grp\r\n"
                                          "f 1/1/1 2/2/1 3/3/1\r\n" // v/vt/vn
                                          "f 2/2 4/1 3/3\r\n");     // v/vt (no vn -> flat)
    const Mesh m = shadowlab::loadMeshFile(p).meshes.at(0);
    expectValidMesh(m);
    EXPECT_EQ(m.name, "grp");
    ASSERT_EQ(m.triangleCount(), 2u);
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    // OBJ's v = 0 is the image bottom; shadowlab uses v = 0 at the top.
    EXPECT_FLOAT_EQ(m.uvs[m.indices[0]].x, 0.25f);
    EXPECT_FLOAT_EQ(m.uvs[m.indices[0]].y, 0.25f);
    EXPECT_FLOAT_EQ(m.uvs[m.indices[1]].y, 1.0f);
    EXPECT_FLOAT_EQ(m.uvs[m.indices[2]].y, 0.0f);
    for (int k = 0; k < 6; ++k) expectVec(m.normals[m.indices[k]], {0, 0, 1}); // vn 0 0 2 normalised; flat face also +Z
    expectVec(m.positions[m.indices[4]], {1, 1, 0});
    EXPECT_FLOAT_EQ(m.uvs[m.indices[4]].y, 0.25f);
}

TEST_F(MeshFileTest, ObjNegativeIndicesAreRelativeToVerticesSoFar) {
    const fs::path p = write("neg.obj", R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
f -4 -3 -2 -1
v 5 0 0
v 6 0 0
v 5 1 0
f -3 -2 -1
f -7/ -1 -6
)");
    const Mesh m = shadowlab::loadObj(p).meshes.at(0);
    expectValidMesh(m);
    ASSERT_EQ(m.triangleCount(), 4u);
    expectVec(m.positions[m.indices[0]], {0, 0, 0});
    expectVec(m.positions[m.indices[4]], {1, 1, 0});
    expectVec(m.positions[m.indices[5]], {0, 1, 0});
    expectVec(m.positions[m.indices[6]], {5, 0, 0});
    expectVec(m.positions[m.indices[8]], {5, 1, 0});
    expectVec(m.positions[m.indices[9]], {0, 0, 0});
    expectVec(m.positions[m.indices[10]], {5, 1, 0});
    expectVec(m.positions[m.indices[11]], {1, 0, 0});
}

TEST_F(MeshFileTest, ObjWithoutNormalsGetsFlatNormalsAndSplitVertices) {
    // Tetrahedron, outward counter-clockwise faces, no vn: shared positions
    // must be split so that each face keeps its own flat normal.
    const fs::path p = write("tetra.obj", R"(v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
f 1 3 2
f 1 2 4
f 1 4 3
f 2 3 4
)");
    const Mesh m = shadowlab::loadObj(p).meshes.at(0);
    expectValidMesh(m);
    EXPECT_EQ(m.name, "tetra"); // no o/g: the file stem
    ASSERT_EQ(m.triangleCount(), 4u);
    EXPECT_EQ(m.positions.size(), 12u);
    EXPECT_NEAR(signedVolume(m), 1.0 / 6.0, 1e-6);
    for (std::size_t t = 0; t < 4; ++t)
        for (int k = 0; k < 3; ++k) expectVec(m.normals[m.indices[3 * t + k]], faceNormal(m, t));
    expectVec(m.normals[m.indices[9]], glm::normalize(glm::vec3(1, 1, 1)));
}

TEST_F(MeshFileTest, ObjPolygonIsFanTriangulated) {
    const fs::path p = write("pentagon.OBJ", R"(v 0 0 0
v 2 0 0
v 3 1 0
v 1 2 0
v -1 1 0
f 1 2 3 4 5
)");
    const Mesh m = shadowlab::loadMeshFile(p).meshes.at(0); // upper-case extension
    expectValidMesh(m);
    ASSERT_EQ(m.triangleCount(), 3u);
    EXPECT_EQ(m.positions.size(), 5u);
    double area = 0.0;
    for (std::size_t t = 0; t < 3; ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]], c = m.positions[m.indices[3 * t + 2]];
        area += 0.5 * glm::cross(b - a, c - a).z;
        EXPECT_EQ(m.indices[3 * t], m.indices[0]); // fan around the first corner
    }
    EXPECT_NEAR(area, 5.0, 1e-6); // shoelace area of the pentagon
}

TEST_F(MeshFileTest, ObjExtraComponentsAndSpacingAreAccepted) {
    const fs::path p = write("extra.obj", "  v 0 0 0 1.0   # w\nv\t+1e0 0 0 0.5 0.5 0.5\nv 0 1 0\nvt 0.5\nf 1/1 2/1 3/1 # tail\n\n");
    const Mesh m = shadowlab::loadObj(p).meshes.at(0);
    expectValidMesh(m);
    EXPECT_EQ(m.triangleCount(), 1u);
    expectVec(m.positions[m.indices[1]], {1, 0, 0});
    EXPECT_FLOAT_EQ(m.uvs[0].x, 0.5f);
    EXPECT_FLOAT_EQ(m.uvs[0].y, 1.0f); // missing v defaults to 0, flipped
}

TEST_F(MeshFileTest, ObjBadNumberNamesFileAndLine) {
    const fs::path p = write("badnum.obj", "v 0 0 0\nv 1 2 abc\n");
    expectError([&] { shadowlab::loadMeshFile(p); }, {"badnum.obj:2:", "bad number 'abc' after 'v'"});
    const fs::path q = write("short.obj", "# header\nv 1 2\n");
    expectError([&] { shadowlab::loadObj(q); }, {"short.obj:2: expected 3 numbers after 'v'"});
    const fs::path r = write("badidx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
    expectError([&] { shadowlab::loadObj(r); }, {"badidx.obj:4:", "bad vertex index 'x'"});
    const fs::path s = write("twocorners.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
    expectError([&] { shadowlab::loadObj(s); }, {"twocorners.obj:3:", "at least 3 vertices"});
}

TEST_F(MeshFileTest, ObjOutOfRangeIndicesAreErrors) {
    const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expectError([&] { shadowlab::loadObj(write("range.obj", verts + "f 1 2 3\nf 1 2 99\n")); },
                {"range.obj:5: vertex index 99 out of range (file has 3 vertices)"});
    expectError([&] { shadowlab::loadObj(write("negrange.obj", verts + "f -1 -2 -4\n")); }, {"negrange.obj:4:", "vertex index -4 out of range"});
    expectError([&] { shadowlab::loadObj(write("zero.obj", verts + "f 0 1 2\n")); }, {"zero.obj:4:", "index 0"});
    expectError([&] { shadowlab::loadObj(write("vt.obj", verts + "vt 0 0\nf 1/1 2/2 3/1\n")); },
                {"vt.obj:5: texture coordinate index 2 out of range (file has 1 texture coordinate)"});
    expectError([&] { shadowlab::loadObj(write("vn.obj", verts + "f 1//1 2//1 3//1\n")); },
                {"vn.obj:4: normal index 1 out of range (file has 0 normals)"});
}

TEST_F(MeshFileTest, ObjNonFiniteNumbersAreErrors) {
    expectError([&] { shadowlab::loadObj(write("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); },
                {"nan.obj:1:", "number 'nan' after 'v' is not finite"});
    expectError([&] { shadowlab::loadObj(write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n")); }, {"inf.obj:3:", "is not finite or past a 32-bit float's range"});
    expectError([&] { shadowlab::loadObj(write("huge.obj", "v 0 0 0\nv 1e999 0 0\n")); }, {"huge.obj:2:", "is not finite or past a 32-bit float's range"});
    expectError([&] { shadowlab::loadObj(write("float-range.obj", "v 1e39 0 0\n")); }, {"float-range.obj:1:", "past a 32-bit float's range (about 3.4e38)"});
    expectError([&] { shadowlab::loadObj(write("vn_nan.obj", "vn 0 NaN 1\n")); }, {"vn_nan.obj:1:", "after 'vn'"});
}

TEST_F(MeshFileTest, ObjWithoutFacesIsAnError) {
    expectError([&] { shadowlab::loadMeshFile(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n")); }, {"points.obj: no triangles"});
    expectError([&] { shadowlab::loadMeshFile(write("empty.obj", "")); }, {"empty.obj: no triangles"});
}

TEST_F(MeshFileTest, GlmarkBunnyLoads) {
    const fs::path bunny = "/usr/share/glmark2/models/bunny.obj";
    if (!fs::exists(bunny)) GTEST_SKIP() << bunny << " not present (install glmark2-data to run this test)";
    const Mesh m = shadowlab::loadMeshFile(bunny).meshes.at(0);
    expectValidMesh(m);
    EXPECT_EQ(m.triangleCount(), 69666u);
}

// ---------------------------------------------------------------------------
// glTF

TEST_F(MeshFileTest, GltfHierarchyTranslationMaterialAndComputedNormals) {
    const std::string nodes = R"("scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "parent", "translation": [1, 2, 3], "children": [1]},
            {"name": "child", "mesh": 0, "translation": [0, 1, 0],
             "rotation": [0, 0.70710678, 0, 0.70710678], "scale": [2, 2, 2]}],
  "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.2, 0.5]}, "alphaMode": "MASK", "alphaCutoff": 0.3}])";
    const fs::path p = write("scene.gltf", triangleGltf(dataUri(triangleBuffer().data), nodes, R"(, "material": 0)"));
    const ImportedModel model = shadowlab::loadMeshFile(p);

    ASSERT_EQ(model.nodes.size(), 2u);
    EXPECT_EQ(model.nodes[0].name, "parent");
    EXPECT_EQ(model.nodes[0].parent, -1);
    expectVec(model.nodes[0].translation, {1, 2, 3});
    EXPECT_TRUE(model.nodes[0].primitives.empty());
    EXPECT_EQ(model.nodes[1].name, "child");
    EXPECT_EQ(model.nodes[1].parent, 0);
    expectVec(model.nodes[1].translation, {0, 1, 0});
    expectVec(model.nodes[1].scale, {2, 2, 2});
    // glTF quaternions are (x, y, z, w): 90 degrees about +Y maps +X to -Z.
    expectVec(model.nodes[1].rotation * glm::vec3(1, 0, 0), {0, 0, -1});
    ASSERT_EQ(model.nodes[1].primitives.size(), 1u);
    EXPECT_EQ(model.nodes[1].primitives[0].mesh, 0);
    EXPECT_EQ(model.nodes[1].primitives[0].material, 0);

    ASSERT_EQ(model.meshes.size(), 1u);
    const Mesh& m = model.meshes[0];
    expectValidMesh(m);
    EXPECT_EQ(m.name, "tri");
    ASSERT_EQ(m.positions.size(), 3u);
    expectVec(m.positions[1], {1, 0, 0});
    expectVec(m.positions[2], {0, 1, 0});
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    for (const glm::vec3& n : m.normals) expectVec(n, {0, 0, 1}); // computed: counter-clockwise in XY faces +Z
    EXPECT_TRUE(m.uvs.empty());

    ASSERT_EQ(model.materials.size(), 1u);
    const shadowlab::Material& mat = model.materials[0];
    EXPECT_EQ(mat.name, "red");
    expectVec(mat.baseColor, {0.8f, 0.1f, 0.2f});
    EXPECT_FLOAT_EQ(mat.alpha, 0.5f);  // the factor's fourth component
    EXPECT_EQ(mat.alphaMode, shadowlab::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(mat.alphaCutoff, 0.3f);
    EXPECT_EQ(mat.baseColorTexture, -1);
    const shadowlab::Material defaults;
    EXPECT_EQ(mat.specular, defaults.specular);
    EXPECT_EQ(mat.shininess, defaults.shininess);
    EXPECT_TRUE(model.textures.empty());
}

// Material values outside glTF's ranges are refused, naming the file and
// the value's path, as the scene JSON refuses them (they were clamped, or
// an unknown alphaMode made the material opaque).
TEST_F(MeshFileTest, GltfMaterialValuesOutOfRangeAreRefused) {
    const struct {
        const char* material;
        const char* expected;
    } cases[] = {
        {R"({"alphaMode": "CUTOUT"})", "materials[0].alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\", got \"CUTOUT\""},
        {R"({"alphaMode": "MASK", "alphaCutoff": 1.5})", "materials[0].alphaCutoff: expected a number in 0..1, got 1.5"},
        {R"({"alphaMode": "MASK", "alphaCutoff": -0.25})", "materials[0].alphaCutoff: expected a number in 0..1, got -0.25"},
        {R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 2.0]}})",
         "materials[0].pbrMetallicRoughness.baseColorFactor[3]: expected a number in 0..1, got 2"},
        {R"({"pbrMetallicRoughness": {"baseColorFactor": [-0.5, 0.5, 0.5, 1.0]}})",
         "materials[0].pbrMetallicRoughness.baseColorFactor[0]: expected a number in 0..1, got -0.5"},
        // Wrong types, which the glTF loader kept its defaults for without a word.
        {R"({"alphaMode": 3})", "materials[0].alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\", got 3"},
        {R"({"alphaMode": "MASK", "alphaCutoff": "half"})", "materials[0].alphaCutoff: expected a number in 0..1, got \"half\""},
        {R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5]}})",
         "materials[0].pbrMetallicRoughness.baseColorFactor: expected 4 numbers, got [0.5,0.5,0.5]"},
        {R"({"pbrMetallicRoughness": {"baseColorFactor": "red"}})", "materials[0].pbrMetallicRoughness.baseColorFactor: expected 4 numbers"},
        {R"({"pbrMetallicRoughness": {"baseColorFactor": [1e300, 0.5, 0.5, 1.0]}})",
         "materials[0].pbrMetallicRoughness.baseColorFactor[0]: expected a number in 0..1, got 1e+300"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.material);
        const std::string nodes = std::string(R"("nodes": [{"mesh": 0}], "materials": [)") + c.material + "]";
        const fs::path p = write("bad-material.gltf", triangleGltf(dataUri(triangleBuffer().data), nodes, R"(, "material": 0)"));
        try {
            shadowlab::loadMeshFile(p);
            ADD_FAILURE() << "accepted";
        } catch (const shadowlab::Error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("bad-material.gltf: "), std::string::npos) << what;
            EXPECT_NE(what.find(c.expected), std::string::npos) << what;
        }
    }
}

// A node's transform of the wrong shape is refused (the loader took it as
// the identity, or as no transform at all).
TEST_F(MeshFileTest, GltfNodeTransformsOfTheWrongShapeAreRefused) {
    const struct {
        const char* node;
        const char* expected;
    } cases[] = {
        {R"({"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,"x"]})", "nodes[0].matrix[15]: expected a number, got \"x\""},
        {R"({"mesh": 0, "matrix": [1,0,0,0]})", "nodes[0].matrix: expected 16 numbers"},
        {R"({"mesh": 0, "translation": [1, 2]})", "nodes[0].translation: expected 3 numbers"},
        {R"({"mesh": 0, "rotation": "none"})", "nodes[0].rotation: expected 4 numbers"},
        {R"({"mesh": 0, "scale": [1, 1, null]})", "nodes[0].scale[2]: expected a number, got null"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.node);
        const std::string nodes = std::string(R"("nodes": [)") + c.node + "]";
        const fs::path p = write("bad-node.gltf", triangleGltf(dataUri(triangleBuffer().data), nodes));
        try {
            shadowlab::loadMeshFile(p);
            ADD_FAILURE() << "accepted";
        } catch (const shadowlab::Error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("bad-node.gltf: "), std::string::npos) << what;
            EXPECT_NE(what.find(c.expected), std::string::npos) << what;
        }
    }
}

TEST_F(MeshFileTest, GltfMatrixNodeIsDecomposedAndNodesWithoutSceneAreRoots) {
    // No "scenes": every node that is nobody's child is a root. Node 1 has a
    // matrix: translation (4,5,6), uniform scale 2 (column-major).
    const std::string nodes = R"("nodes": [{"name": "a", "mesh": 0},
            {"name": "b", "children": [2], "matrix": [2,0,0,0, 0,2,0,0, 0,0,2,0, 4,5,6,1]},
            {"name": "c", "mesh": 0}])";
    const ImportedModel model = shadowlab::loadGltf(write("matrix.gltf", triangleGltf(dataUri(triangleBuffer().data), nodes)));
    ASSERT_EQ(model.nodes.size(), 3u);
    EXPECT_EQ(model.nodes[0].name, "a");
    EXPECT_EQ(model.nodes[1].name, "b");
    EXPECT_EQ(model.nodes[2].name, "c");
    EXPECT_EQ(model.nodes[2].parent, 1);
    expectVec(model.nodes[1].translation, {4, 5, 6});
    expectVec(model.nodes[1].scale, {2, 2, 2});
    expectVec(model.nodes[1].rotation * glm::vec3(1, 2, 3), {1, 2, 3});
    // The same glTF mesh instanced twice is imported once; no material given.
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.nodes[0].primitives.at(0).mesh, 0);
    EXPECT_EQ(model.nodes[2].primitives.at(0).mesh, 0);
    EXPECT_EQ(model.nodes[0].primitives.at(0).material, -1);
}

TEST_F(MeshFileTest, GltfInterleavedStridesIndexTypesModesAndTexture) {
    // View 0: interleaved position+normal (stride 24) of 4 vertices, normals at accessor byteOffset 12.
    // View 1: texcoords. View 2: u8 indices. View 3: u32 indices.
    Bytes b;
    const std::array<glm::vec3, 4> pos = {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(2, 0, -2), glm::vec3(0, 0, -2)};
    for (const glm::vec3& q : pos) b.floats({q.x, q.y, q.z, 0, 3, 0}); // normals (0,3,0): renormalised
    b.floats({0, 1, 1, 1, 1, 0, 0, 0});                                  // 96: texcoords
    b.put<std::uint8_t>(0).put<std::uint8_t>(1).put<std::uint8_t>(2).pad4(); // 128: u8 indices
    b.put<std::uint32_t>(0).put<std::uint32_t>(2).put<std::uint32_t>(3);      // 132: u32 indices
    ASSERT_EQ(b.data.size(), 144u);
    // 2x1 RGB image, 16 bits per channel: converted to 8-bit RGBA.
    const std::vector<std::uint8_t> samples = {0xFF, 0xFF, 0x80, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x12, 0x34, 0xFF, 0x00};
    const std::string imageUri = dataUri(png(2, 1, 16, 2, samples), "image/png");

    const std::string json = R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [1]}, {"nodes": [0]}], "scene": 1,
  "nodes": [{"name": "quad", "mesh": 0}, {"name": "ignored scene"}],
  "meshes": [{"name": "m", "primitives": [
     {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0},
     {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 4, "material": 0, "mode": 4},
     {"attributes": {"POSITION": 0}, "mode": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"name": "img", "uri": ")" + imageUri + R"("}],
  "buffers": [{"byteLength": 144, "uri": ")" + dataUri(b.data) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96, "byteStride": 24},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 128, "byteLength": 3},
                  {"buffer": 0, "byteOffset": 132, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 2, "componentType": 5121, "count": 3, "type": "SCALAR"},
                {"bufferView": 3, "componentType": 5125, "count": 3, "type": "SCALAR"}]
})";
    const ImportedModel model = shadowlab::loadMeshFile(write("quad.gltf", json));
    ASSERT_EQ(model.nodes.size(), 1u); // the default scene (1) holds node 0 only
    EXPECT_EQ(model.nodes[0].name, "quad");
    ASSERT_EQ(model.nodes[0].primitives.size(), 2u); // POINTS primitive skipped
    ASSERT_EQ(model.meshes.size(), 2u);
    for (const auto& prim : model.nodes[0].primitives) {
        const Mesh& m = model.meshes.at(static_cast<std::size_t>(prim.mesh));
        expectValidMesh(m);
        EXPECT_EQ(prim.material, 0);
        ASSERT_EQ(m.positions.size(), 4u);
        ASSERT_EQ(m.uvs.size(), 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            expectVec(m.positions[i], pos[i]);
            expectVec(m.normals[i], {0, 1, 0});
        }
        EXPECT_FLOAT_EQ(m.uvs[2].x, 1.0f);
        EXPECT_FLOAT_EQ(m.uvs[2].y, 0.0f);
    }
    EXPECT_EQ(model.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(model.meshes[1].indices, (std::vector<std::uint32_t>{0, 2, 3}));
    EXPECT_EQ(model.meshes[0].name, "m#0");

    ASSERT_EQ(model.materials.size(), 1u);
    expectVec(model.materials[0].baseColor, {1, 1, 1}); // factor absent: glTF's default (1,1,1,1) multiplies the texture
    ASSERT_EQ(model.materials[0].baseColorTexture, 0);
    ASSERT_EQ(model.textures.size(), 1u);
    const shadowlab::ImageRGBA8& img = model.textures[0];
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 1);
    // 16-bit -> 8-bit is round(v * 255 / 65535) = round(v / 257): 0xFFFF -> 255,
    // 0x8000 -> 128, 0x00FF -> 1 (truncating v >> 8 would give 0),
    // 0x1234 -> 18 and 0xFF00 -> 254 (byte-swapped they would give 52 and 1).
    EXPECT_EQ(img.pixels, (std::vector<std::uint8_t>{255, 128, 0, 255, 1, 18, 254, 255}));
}

TEST_F(MeshFileTest, GltfGreyscaleTextureIsExpandedToRgba) {
    const std::string imageUri = dataUri(png(2, 2, 8, 0, {10, 20, 30, 40}), "image/png");
    const std::string nodes = R"("nodes": [{"mesh": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"uri": ")" + imageUri + R"("}])";
    const ImportedModel model = shadowlab::loadGltf(write("grey.gltf", triangleGltf(dataUri(triangleBuffer().data), nodes, R"(, "material": 0)")));
    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_EQ(model.textures[0].pixels,
              (std::vector<std::uint8_t>{10, 10, 10, 255, 20, 20, 20, 255, 30, 30, 30, 255, 40, 40, 40, 255}));
}

TEST_F(MeshFileTest, GlbBinaryContainerLoads) {
    const std::string json = R"({"asset": {"version": "2.0"},
  "nodes": [{"name": "n", "mesh": 0, "translation": [0, 0, 7]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "buffers": [{"byteLength": 36}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]})";
    Bytes b;
    b.floats({0, 0, 0, 0, 0, 1, 1, 0, 0}); // normal = cross(+Z, +X) = +Y
    const ImportedModel model = shadowlab::loadMeshFile(write("tri.GLB", glb(json, b.data)));
    ASSERT_EQ(model.nodes.size(), 1u);
    expectVec(model.nodes[0].translation, {0, 0, 7});
    ASSERT_EQ(model.meshes.size(), 1u);
    const Mesh& m = model.meshes[0];
    expectValidMesh(m);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2})); // non-indexed
    for (const glm::vec3& n : m.normals) expectVec(n, {0, 1, 0});
}

TEST_F(MeshFileTest, GltfAreaWeightedNormals) {
    // Two triangles meeting at vertex 0: a large one facing +Z (area 2) and a
    // small one facing +X (area 0.5); the shared normal leans 4:1 to +Z.
    Bytes b;
    b.floats({0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 1, 0, -1, 0});
    b.put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(2);
    b.put<std::uint16_t>(0).put<std::uint16_t>(3).put<std::uint16_t>(4);
    const std::string json = R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 72, "uri": ")" + dataUri(b.data) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 60}, {"buffer": 0, "byteOffset": 60, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
    const Mesh m = shadowlab::loadGltf(write("weights.gltf", json)).meshes.at(0);
    expectValidMesh(m);
    expectVec(m.normals[0], glm::normalize(glm::vec3(1, 0, 4)));
    expectVec(m.normals[1], {0, 0, 1});
    expectVec(m.normals[3], {1, 0, 0});
}

TEST_F(MeshFileTest, MissingFileUnknownExtensionAndFakeGlb) {
    expectError([&] { shadowlab::loadMeshFile(dir_ / "nothere.obj"); }, {"nothere.obj: file not found"});
    expectError([&] { shadowlab::loadMeshFile(dir_ / "nothere.gltf"); }, {"nothere.gltf: file not found"});
    expectError([&] { shadowlab::loadMeshFile(dir_ / "nothere.glb"); }, {"nothere.glb: file not found"});
    expectError([&] { shadowlab::loadMeshFile(write("x.stl", "solid x\nendsolid x\n")); },
                {"x.stl: unsupported mesh format (expected .obj, .gltf or .glb)"});
    expectError([&] { shadowlab::loadMeshFile(write("noext", "v 0 0 0\n")); }, {"noext: unsupported mesh format"});
    expectError([&] { shadowlab::loadMeshFile(write("fake.glb", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); },
                {"fake.glb: not a binary glTF file (missing 'glTF' magic)"});
    expectError([&] { shadowlab::loadMeshFile(write("tiny.glb", "gl")); }, {"tiny.glb: not a binary glTF file"});
    expectError([&] { shadowlab::loadMeshFile(write("trunc.glb", "glTF\x02")); }, {"trunc.glb: "});
    expectError([&] { shadowlab::loadMeshFile(dir_); }, {dir_.filename().string(), "unsupported mesh format"});
}

TEST_F(MeshFileTest, MalformedGltfIsOneLineError) {
    expectError([&] { shadowlab::loadMeshFile(write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": [")); },
                {"broken.gltf: "});
    expectError([&] { shadowlab::loadMeshFile(write("noasset.gltf", "{}")); }, {"noasset.gltf: "});
    expectError([&] { shadowlab::loadMeshFile(write("missingbin.gltf", triangleGltf("missing.bin", R"("nodes": [{"mesh": 0}])"))); },
                {"missingbin.gltf: ", "missing.bin"});
    // tinygltf quotes an undecodable data URI in full; the message keeps only its start.
    const std::string longUri = "data:application/octet-stream;base64," + std::string(40000, 'A') + "==";
    const std::string msg = errorOf([&] { shadowlab::loadGltf(write("baduri.gltf", triangleGltf(longUri, R"("nodes": [{"mesh": 0}])"))); });
    EXPECT_NE(msg.find("baduri.gltf: "), std::string::npos) << msg;
    EXPECT_LT(msg.size(), 300u) << msg;
}

// The header a glTF 2.0 loader must check: the version, extensions the file
// requires, the default scene's index; a binary file's version.
TEST_F(MeshFileTest, GltfHeaderErrors) {
    const std::string uri = dataUri(triangleBuffer().data);
    std::string v1 = triangleGltf(uri, R"("nodes": [{"mesh": 0}])");
    v1.replace(v1.find("\"2.0\""), 5, "\"1.0\"");
    expectError([&] { shadowlab::loadMeshFile(write("v1.gltf", v1)); }, {"v1.gltf: asset.version: expected glTF 2.x (\"2.0\"), got \"1.0\""});
    expectError([&] { shadowlab::loadMeshFile(write("draco.gltf", triangleGltf(uri, R"("nodes": [{"mesh": 0}], "extensionsRequired": ["KHR_draco_mesh_compression"])"))); },
                {"draco.gltf: extensionsRequired: \"KHR_draco_mesh_compression\" is not supported"});
    expectError([&] { shadowlab::loadMeshFile(write("scene.gltf", triangleGltf(uri, R"("nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 5)"))); },
                {"scene.gltf: scene: expected an index into scenes (0..0), got 5"});
    expectError([&] { shadowlab::loadMeshFile(write("v3.glb", std::string("glTF\x03\0\0\0\x0c\0\0\0", 12))); }, {"v3.glb: binary glTF version 3 (expected 2)"});
    // A node's camera that does not exist (issue 59: it loaded silently).
    expectError([&] { shadowlab::loadMeshFile(write("camera.gltf", triangleGltf(uri, R"("nodes": [{"mesh": 0}, {"camera": 3}])"))); },
                {"camera.gltf: nodes[1].camera: expected an index into cameras (none), got 3"});
    // A file that uses the header as it should loads.
    EXPECT_NO_THROW(shadowlab::loadMeshFile(write("ok.gltf", triangleGltf(uri, R"("nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0)"))));
}

TEST_F(MeshFileTest, GltfContentErrors) {
    const std::string uri = dataUri(triangleBuffer().data);
    const std::string oneNode = R"("nodes": [{"mesh": 0}])";
    // Quantized/normalized positions are rejected, naming the accessor.
    {
        Bytes b;
        for (int i = 0; i < 9; ++i) b.put<std::uint16_t>(static_cast<std::uint16_t>(i % 2 ? 65535 : 0));
        b.pad4();
        const std::string json = R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "buffers": [{"byteLength": 20, "uri": ")" + dataUri(b.data) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 18}],
  "accessors": [{"bufferView": 0, "componentType": 5123, "normalized": true, "count": 3, "type": "VEC3"}]})";
        expectError([&] { shadowlab::loadGltf(write("quantized.gltf", json)); }, {"quantized.gltf: ", "accessor 0 (POSITION)", "normalized"});
    }
    // Non-finite position.
    {
        Bytes b;
        b.floats({0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0});
        b.put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(2).pad4();
        expectError([&] { shadowlab::loadGltf(write("nanpos.gltf", triangleGltf(dataUri(b.data), oneNode))); },
                    {"nanpos.gltf: ", "accessor 0 (POSITION)", "non-finite"});
    }
    // Index past the vertex count.
    {
        Bytes b;
        b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0});
        b.put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(3).pad4();
        expectError([&] { shadowlab::loadGltf(write("badindex.gltf", triangleGltf(dataUri(b.data), oneNode))); },
                    {"badindex.gltf: ", "index 3 out of range"});
    }
    // Accessor reading past its buffer view.
    expectError([&] { shadowlab::loadGltf(write("overrun.gltf", triangleGltf(uri, oneNode, "", R"(, "byteOffset": 4)"))); },
                {"overrun.gltf: ", "accessor 0", "past the end"});
    // Only a POINTS primitive, or no node referencing the mesh: no triangles.
    expectError([&] { shadowlab::loadGltf(write("points.gltf", triangleGltf(uri, oneNode, R"(, "mode": 0)"))); }, {"points.gltf: no triangles"});
    expectError([&] { shadowlab::loadGltf(write("nonodes.gltf", triangleGltf(uri, R"("nodes": [{"name": "empty"}])"))); },
                {"nonodes.gltf: no triangles"});
    // Node cycles: through a scene, and with no scene (no root at all).
    expectError([&] { shadowlab::loadGltf(write("cycle.gltf", triangleGltf(uri, R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "children": [1]}, {"children": [0]}])"))); },
                {"cycle.gltf: ", "node 0 is referenced more than once"});
    expectError([&] { shadowlab::loadGltf(write("noroot.gltf", triangleGltf(uri, R"("nodes": [{"mesh": 0, "children": [0]}])"))); },
                {"noroot.gltf: ", "no root"});
    expectError([&] { shadowlab::loadGltf(write("badchild.gltf", triangleGltf(uri, R"("nodes": [{"mesh": 0, "children": [5]}])"))); },
                {"badchild.gltf: node index 5 out of range"});
}

} // namespace

TEST_F(MeshFileTest, FilesThatAreNotWhatTheirExtensionSaysAreErrors) {
    const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    expectError([&] { shadowlab::loadMeshFile(write("image.obj", png)); }, {"image.obj", "not a Wavefront OBJ file"});
    expectError([&] { shadowlab::loadMeshFile(write("image.gltf", png)); }, {"image.gltf", "not a glTF JSON file"});
    expectError([&] { shadowlab::loadMeshFile(write("image.glb", png)); }, {"image.glb", "not a binary glTF file"});
    // JSON that is not glTF: tinygltf's complaint, in one printable line.
    try {
        shadowlab::loadMeshFile(write("plain.gltf", "{\"hello\": \"\x01world\"}"));
        FAIL() << "no error";
    } catch (const shadowlab::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("plain.gltf: "), std::string::npos) << m;
        EXPECT_EQ(m.find("[json.exception"), std::string::npos) << m;
        for (char c : m) EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f) << m;
    }
}
