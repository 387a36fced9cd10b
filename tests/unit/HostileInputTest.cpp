// Hostile input (issue 12): each reproducer in fuzz/corpus/ gives a one-line
// error naming the file and the JSON path or line, or is accepted within a
// stated limit; nothing crashes, reads out of bounds or recurses per level.
// The inputs are the fuzz seeds, fed the way the fuzz targets feed them.
#include <shadowlab/Text.h>
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/Image.h>
#include <shadowlab/SceneFile.h>

#include "ErrorText.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

const fs::path kCorpus = fs::path(SHADOWLAB_SOURCE_DIR) / "fuzz" / "corpus";

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A scene seed: JSON, then NUL-separated --set overrides (as in FuzzScene.cpp).
Scene loadSceneSeed(const std::string& name) {
    const std::string input = readFile(kCorpus / "scene" / name);
    const std::size_t nul = input.find('\0');
    std::vector<std::string> overrides;
    for (std::size_t at = nul; at != std::string::npos;) {
        const std::size_t next = input.find('\0', at + 1);
        overrides.push_back(input.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
        at = next;
    }
    return parseScene(input.substr(0, nul), name, kCorpus / "files", overrides);
}

bool hasControlCharacter(const std::string& s) {
    for (unsigned char c : s)
        if (c < 0x20 || c == 0x7f) return true;
    return false;
}

struct Case {
    const char* dir;      // corpus directory: scene, obj, gltf or glb
    const char* file;
    const char* expected; // the message contains this
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.dir << "/" << c.file; }

class HostileInputErrors : public ::testing::TestWithParam<Case> {};

TEST_P(HostileInputErrors, OneNamedLine) {
    const Case& c = GetParam();
    const std::string dir = c.dir;
    const std::string message = errorOf([&] {
        if (dir == "scene") loadSceneSeed(c.file);
        else loadMeshFile(kCorpus / dir / c.file);
    });
    EXPECT_NE(message.find(c.expected), std::string::npos) << "message: " << message << "\nexpected: " << c.expected;
    EXPECT_FALSE(hasControlCharacter(message)) << "raw control character in: " << message;
    EXPECT_EQ(text::invalidUtf8At(message), std::string::npos) << "invalid UTF-8 in: " << message;
    if (dir != "scene") {
        EXPECT_EQ(message.rfind((kCorpus / dir / c.file).string() + ":", 0), 0u) << "does not name the file: " << message;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, HostileInputErrors,
    ::testing::Values(
        // glTF: offsets near 2^64 and huge counts are caught without wrapping.
        Case{"gltf", "repro-accessor-offset-wraps.gltf", "accessor 0 (POSITION): byteOffset 18446744073709551604 and count 3 read past the end of bufferView 0 (36 bytes)"},
        Case{"glb", "repro-accessor-offset-wraps.glb", "accessor 0 (POSITION): byteOffset 18446744073709551604 and count 3 read past the end"},
        Case{"gltf", "repro-accessor-count-huge.gltf", "accessor 0 (POSITION): count 1537228672809129301 exceeds the limit of 16777216 elements"},
        Case{"gltf", "repro-view-offset-wraps.gltf", "bufferView"},
        Case{"gltf", "repro-node-cycle.gltf", "node 0 is referenced more than once (a cycle: it is its own ancestor)"},
        Case{"gltf", "repro-node-two-parents.gltf", "node 2 has two parents (nodes 0 and 1)"},
        Case{"gltf", "repro-translation-1e300.gltf", "node 0: transform values must be finite numbers of magnitude <= 3e38"},
        Case{"gltf", "repro-scale-overflows-composed.gltf", "node 1: transform is not finite after composing its parents'"},
        Case{"gltf", "repro-json-nested-10000.gltf", "JSON nested deeper than 200 levels"},
        // Found by fuzzing: a buffer URI that resolves to a directory.
        Case{"gltf", "repro-buffer-uri-directory.gltf", "is not a regular file"},
        Case{"gltf", "repro-buffer-uri-percent.gltf", "is not a regular file"},
        Case{"glb", "repro-json-nested-10000.glb", "JSON nested deeper than 200 levels"},
        // Found by fuzzing: tinygltf throwing from inside its loader.
        Case{"glb", "repro-buffer-length-0-with-bin.glb", "not a valid glTF file (the glTF loader failed: "},
        // OBJ: control bytes in a quoted word are escaped.
        Case{"obj", "repro-control-bytes.obj", ":3: bad number '1\\v\\f\\r' after 'v'"},
        Case{"obj", "repro-bad-number-cr.obj", ":2: bad number '1\\r5' after 'v'"},
        // Scene files and --set.
        Case{"scene", "repro-children-nested-10000.json", "repro-children-nested-10000.json: JSON nested deeper than 200 levels"},
        Case{"scene", "repro-set-index-past-2^64.json", "--set lights[99999999999999999999].intensity=1: bad JSON path 'lights[99999999999999999999].intensity': index 99999999999999999999 is too large"},
        Case{"scene", "repro-newline-in-key.json", "repro-newline-in-key.json: na\\nme: unknown key"},
        Case{"scene", "repro-newline-in-mesh-path.json", "nodes[0].mesh: "},
        Case{"scene", "repro-newline-in-set-value.json", "--set lights[0].intensity=1\\n2: lights[0].intensity: expected a number, got a string"},
        Case{"scene", "repro-invalid-utf8-in-set.json", "name: invalid UTF-8 in the string 'a\\xffb'"},
        Case{"scene", "repro-segments-2^64-1.json", "nodes[0].shape.majorSegments: expected an integer in 3..1024, got 18446744073709551615"},
        Case{"scene", "repro-camera-3e38.json", "camera: camera position and target are too far apart"},
        Case{"scene", "repro-lights-300.json", "repro-lights-300.json: lights: expected at most 256 lights, got 300"},
        Case{"scene", "repro-texture-is-directory.json", "materials.m.baseColorTexture: texture "},
        Case{"scene", "repro-translation-overflows-composed.json", "nodes[0].children[0]: world transform is not finite"}),
    [](const ::testing::TestParamInfo<Case>& p) {
        std::string name = std::string(p.param.dir) + "_" + p.param.file;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

TEST(HostileInput, MeshPathWithNewlineIsEscaped) {
    const std::string message = errorOf([] { loadSceneSeed("repro-newline-in-mesh-path.json"); });
    EXPECT_NE(message.find("a\\nb.obj: file not found"), std::string::npos) << message;
}

TEST(HostileInput, TextureDirectoryIsNotReportedAsMissing) {
    const std::string message = errorOf([] { loadSceneSeed("repro-texture-is-directory.json"); });
    EXPECT_NE(message.find("is not a regular file"), std::string::npos) << message;
    EXPECT_EQ(message.find("not found"), std::string::npos) << message;
}

TEST(HostileInput, HugeDirectionIsNormalisedNotZeroed) {
    const Scene scene = loadSceneSeed("repro-direction-1e30.json");
    ASSERT_EQ(scene.lights.size(), 1u);
    const float third = 1.0f / std::sqrt(3.0f);
    EXPECT_NEAR(scene.lights[0].direction.x, third, 1e-6f);
    EXPECT_NEAR(scene.lights[0].direction.y, third, 1e-6f);
    EXPECT_NEAR(scene.lights[0].direction.z, third, 1e-6f);
}

TEST(HostileInput, NodeChain20000DeepLoadsWithoutRecursion) {
    const ImportedModel model = loadMeshFile(kCorpus / "gltf" / "repro-node-chain-20000.gltf");
    ASSERT_EQ(model.nodes.size(), 20000u);
    for (std::size_t i = 1; i < model.nodes.size(); ++i) ASSERT_EQ(model.nodes[i].parent, static_cast<int>(i) - 1);
    const Scene scene = loadSceneSeed("repro-gltf-chain-20000.json");
    EXPECT_EQ(scene.drawItems().size(), 1u);
    EXPECT_EQ(loadMeshFile(kCorpus / "glb" / "repro-node-chain-20000.glb").nodes.size(), 20000u);
}

TEST(HostileInput, HierarchyAtTheDepthLimitParses) {
    // 99 levels of children: 1 + 2 * 99 = 199 JSON levels, under the limit of 200.
    std::string text = R"({"nodes":)";
    for (int i = 0; i < 99; ++i) text += R"([{"children":)";
    text += "[]";
    for (int i = 0; i < 99; ++i) text += "}]";
    text += "}";
    EXPECT_EQ(parseScene(text, "deep.json", ".").nodes.size(), 99u);
}

TEST(HostileInput, SetValueNestedPastTheLimitIsAnError) {
    const std::string value = std::string(300, '[') + std::string(300, ']');
    const std::string message = errorOf([&] { parseScene("{}", "scene.json", ".", {"name=" + value}); });
    EXPECT_NE(message.find("value nested deeper than 200 levels"), std::string::npos) << message;
}

TEST(HostileInput, TextureSourcesNameFileAndJsonPath) {
    const Scene scene = loadSceneSeed("meshes-and-texture.json");
    ASSERT_EQ(scene.textures.size(), scene.textureSources.size());
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_NE(scene.textureSources[0].find("meshes-and-texture.json: materials.t.baseColorTexture"), std::string::npos) << scene.textureSources[0];
}

TEST(HostileInput, WritePngOntoADirectoryNamesTheRealError) {
    const fs::path dir = fs::temp_directory_path() / ("shadowlab-hostile-dir-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".png");
    fs::create_directories(dir);
    const std::string message = errorOf([&] { writePng(dir, ImageRGBA8{1, 1, {0, 0, 0, 255}}); });
    fs::remove_all(dir);
    EXPECT_NE(message.find(": cannot write ("), std::string::npos) << message;
    EXPECT_EQ(message.find("Success"), std::string::npos) << message;
}

// A write that fails part way (a full disk; here the file-size limit, which
// fails the same calls) throws naming the file and the reason, and leaves
// neither the file nor a temporary. SIGXFSZ is ignored as the tool does.
TEST(HostileInput, AWriteThatFailsPartWayLeavesNothing) {
    const fs::path dir = fs::temp_directory_path() / ("shadowlab-hostile-full-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::create_directories(dir);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit previous{};
    getrlimit(RLIMIT_FSIZE, &previous);
    rlimit limited = previous;
    limited.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &limited);
    const std::string message = errorOf([&] { writeFileAtomically(dir / "big.json", std::string(100000, 'x')); });
    setrlimit(RLIMIT_FSIZE, &previous);
    std::signal(SIGXFSZ, previousHandler);
    EXPECT_NE(message.find("big.json: cannot write (File too large)"), std::string::npos) << message;
    EXPECT_TRUE(fs::is_empty(dir)) << "a temporary or a truncated file is left";
    fs::remove_all(dir);
}

// Numbers in messages read back as the value given: no 300 digits for
// 1e300, no "1" for 1.0000001, a float's shortest text for a float.
TEST(Text, NumbersInMessagesAreShortAndExact) {
    EXPECT_EQ(text::numberText(1e300), "1e+300");
    EXPECT_EQ(text::numberText(1.0000001), "1.0000001");
    EXPECT_EQ(text::numberText(static_cast<double>(0.3f)), "0.3");
    EXPECT_EQ(text::numberText(16385.0), "16385");
    EXPECT_EQ(text::numberText(-2.5), "-2.5");
}

// A value a 32-bit float cannot hold is quoted as written, not as the 0 it became.
TEST(HostileInput, AnUnderflowingSizeIsQuotedAsWritten) {
    const std::string message = errorOf(
        [&] { parseScene(R"({"nodes": [{"shape": {"type": "sphere", "radius": 1e-50}}]})", "scene.json", ".", {}); });
    EXPECT_NE(message.find("nodes[0].shape.radius: expected a number > 0, got 1e-50 (0 as a 32-bit float)"), std::string::npos) << message;
}

TEST(Text, EscapesControlCharactersAndInvalidUtf8Once) {
    EXPECT_EQ(text::escapeControl("a\nb\rc\td\x01\x7f"), "a\\nb\\rc\\td\\x01\\x7f");
    EXPECT_EQ(text::escapeControl("caf\xc3\xa9 \\n"), "caf\xc3\xa9 \\n"); // valid UTF-8 and backslashes stay
    EXPECT_EQ(text::escapeControl("\xff\xc3"), "\\xff\\xc3");
    EXPECT_EQ(text::escapeControl(text::escapeControl("x\ny")), "x\\ny");
}

TEST(Text, FindsInvalidUtf8) {
    EXPECT_EQ(text::invalidUtf8At("plain"), std::string::npos);
    EXPECT_EQ(text::invalidUtf8At("\xe2\x82\xac"), std::string::npos); // euro sign
    EXPECT_EQ(text::invalidUtf8At("ab\xc0\xaf"), 2u);                  // overlong '/'
    EXPECT_EQ(text::invalidUtf8At("\xed\xa0\x80"), 0u);                // surrogate
    EXPECT_EQ(text::invalidUtf8At("\xf4\x90\x80\x80"), 0u);            // past U+10FFFF
    EXPECT_EQ(text::invalidUtf8At("x\xe2\x82"), 1u);                   // truncated
}

TEST(Text, JsonDepthIgnoresBracketsInStrings) {
    EXPECT_EQ(text::jsonDepth(R"({"a": [1, {"b": "[[[\"{{"}]})"), 3u);
    EXPECT_EQ(text::jsonDepth("[]"), 1u);
    EXPECT_EQ(text::jsonDepth("1"), 0u);
    EXPECT_EQ(text::jsonDepth(std::string(100000, '[')), text::kMaxJsonDepth + 1); // stops at the limit
}

} // namespace

// A message quoting a huge value is cut in the middle: at most about
// `limit` bytes, its start and its end (the reason) kept, never inside a
// UTF-8 character. Short ones are unchanged.
TEST(HostileInput, LongMessagesAreCutInTheMiddle) {
    EXPECT_EQ(shadowlab::text::clipMiddle("short"), "short");
    const std::string value(110000, 'x');
    const std::string cut = shadowlab::text::clipMiddle("--set a=" + value + ": a: expected a number, got a string");
    EXPECT_LT(cut.size(), 700u);
    EXPECT_EQ(cut.rfind("--set a=xxx", 0), 0u);
    EXPECT_NE(cut.find(" bytes cut) ..."), std::string::npos);
    EXPECT_EQ(cut.substr(cut.size() - 36), ": a: expected a number, got a string");
    std::string accents;
    for (int i = 0; i < 1000; ++i) accents += "\xc3\xa9";  // é, two bytes each
    EXPECT_EQ(shadowlab::text::invalidUtf8At(shadowlab::text::clipMiddle(accents, 101)), std::string::npos);
}
