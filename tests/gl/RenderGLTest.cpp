// Rendering on the headless context, checked by measured properties:
// colours Blinn-Phong predicts, where objects land in the image, and that
// every bundled scene renders without a GL error.
#include "GLTestContext.h"

#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <unistd.h>

using namespace shadowlab;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// A large grey plane seen straight from above; the centre pixel looks at the
// origin with V = +Y. Specular off unless the test turns it on.
Scene planeFromAbove(const std::string& lightJson, const std::string& material = R"({"baseColor":[0.5,0.4,0.3],"specular":[0,0,0]})") {
    return parseScene(R"({
      "camera": {"position": [0, 5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fovY": 40},
      "ambient": [0.1, 0.1, 0.1],
      "materials": {"m": )" + material + R"(},
      "lights": [)" + lightJson + R"(],
      "nodes": [{"shape": {"type": "plane", "size": [100, 100]}, "material": "m"}]
    })", "test", ".");
}

glm::vec3 pixel(const ImageRGBA8& image, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
    return {image.pixels[i] / 255.0f, image.pixels[i + 1] / 255.0f, image.pixels[i + 2] / 255.0f};
}

ImageRGBA8 renderImage(const Scene& scene, int w, int h) {
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {w, h});
    return renderer.readColor();
}

// Output is 8-bit sRGB: rounding alone is 0.5/255; the RGBA16F accumulation
// adds < 2^-11 relative error, well below one more step. So 1/255.
constexpr float kColorTolerance = 1.0f / 255.0f;

} // namespace

class RenderGLTest : public GLTest {};

TEST_F(RenderGLTest, LitPlaneHasTheBlinnPhongDiffuseColour) {
    // Light travels along (0.6, -0.8, 0): N.L = 0.8 on the +Y plane.
    const Scene scene = planeFromAbove(R"({"type": "directional", "direction": [0.6, -0.8, 0], "color": [1, 0.5, 0.25], "intensity": 1})");
    const ImageRGBA8 image = renderImage(scene, 64, 64);
    const glm::vec3 base(0.5f, 0.4f, 0.3f), lightColor(1.0f, 0.5f, 0.25f);
    for (int c = 0; c < 3; ++c) {
        const double linear = 0.1 * base[c] + 0.8 * base[c] * lightColor[c];  // ambient + diffuse N.L
        EXPECT_NEAR(pixel(image, 32, 32)[c], srgbEncode(linear), kColorTolerance) << "channel " << c;
    }
}

TEST_F(RenderGLTest, SpecularFollowsTheHalfVector) {
    // Centre pixel: V = +Y, L = (-0.6, 0.8, 0); H = normalize(L + V).
    const Scene scene = planeFromAbove(R"({"type": "directional", "direction": [0.6, -0.8, 0]})",
                                       R"({"baseColor":[0.2,0.2,0.2],"specular":[0.5,0.5,0.5],"shininess":8})");
    // The centre of a 64x64 image is between pixels 31 and 32; sample pixel
    // 32's centre, whose view ray is slightly off +Y, so compute V for it.
    const ImageRGBA8 image = renderImage(scene, 64, 64);
    const double tanHalf = std::tan(glm::radians(20.0));
    const double ndcX = (32.5 / 64.0) * 2.0 - 1.0, ndcY = -((32.5 / 64.0) * 2.0 - 1.0);
    const glm::dvec3 p(ndcX * tanHalf * 5.0, 0.0, -ndcY * tanHalf * 5.0);  // up = -Z
    const glm::dvec3 V = glm::normalize(glm::dvec3(0, 5, 0) - p), L(-0.6, 0.8, 0.0);
    const double NdotH = glm::normalize(L + V).y;
    const double linear = 0.1 * 0.2 + 0.8 * 0.2 + 0.5 * std::pow(NdotH, 8.0);
    EXPECT_NEAR(pixel(image, 32, 32).g, srgbEncode(linear), kColorTolerance);
}

TEST_F(RenderGLTest, PointLightDirectlyAboveGivesFullDiffuse) {
    const Scene scene = planeFromAbove(R"({"type": "point", "position": [0, 3, 0]})");
    const ImageRGBA8 image = renderImage(scene, 65, 65);  // odd: pixel 32 is exactly the centre
    EXPECT_NEAR(pixel(image, 32, 32).r, srgbEncode(0.1 * 0.5 + 1.0 * 0.5), kColorTolerance);
}

TEST_F(RenderGLTest, OutsideASpotConeOnlyAmbientRemains) {
    // Spot straight down from 3 m, 10 degree cone: radius ~0.53 m on the plane.
    const Scene scene = planeFromAbove(R"({"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "innerCone": 5, "outerCone": 10})");
    const ImageRGBA8 image = renderImage(scene, 65, 65);
    EXPECT_NEAR(pixel(image, 32, 32).r, srgbEncode(0.1 * 0.5 + 0.5), kColorTolerance);  // inside: full light
    EXPECT_NEAR(pixel(image, 2, 2).r, srgbEncode(0.1 * 0.5), kColorTolerance);          // far outside: ambient
}

TEST_F(RenderGLTest, LightsAddUp) {
    const Scene one = planeFromAbove(R"({"type": "directional", "direction": [0, -1, 0], "intensity": 0.3})");
    const Scene two = planeFromAbove(R"({"type": "directional", "direction": [0, -1, 0], "intensity": 0.3},
                                        {"type": "directional", "direction": [0, -1, 0], "intensity": 0.3})");
    EXPECT_NEAR(pixel(renderImage(one, 33, 33), 16, 16).r, srgbEncode(0.05 + 0.15), kColorTolerance);
    EXPECT_NEAR(pixel(renderImage(two, 33, 33), 16, 16).r, srgbEncode(0.05 + 0.30), kColorTolerance);
}

TEST_F(RenderGLTest, ObjectOnTheCameraLeftAppearsOnTheImageLeft) {
    const Scene scene = parseScene(R"({
      "camera": {"position": [0, 0, 10], "target": [0, 0, 0]},
      "background": [0, 0, 0],
      "lights": [{"type": "directional", "direction": [0, 0, -1]}],
      "nodes": [{"shape": {"type": "sphere", "radius": 1}, "translation": [-3, 1.5, 0]}]
    })", "test", ".");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {160, 120, TimingClock::Off, true});
    const SurfaceBuffer surfaces = renderer.readSurfaces();
    double sumX = 0, sumY = 0, count = 0;
    for (int y = 0; y < surfaces.height; ++y)
        for (int x = 0; x < surfaces.width; ++x)
            if (surfaces.position[static_cast<std::size_t>(y) * surfaces.width + x].w > 0.5f) {
                sumX += x;
                sumY += y;
                ++count;
            }
    ASSERT_GT(count, 100);
    // Projected centre: x = -3 / (10 tan 22.5deg * 4/3) of the half width -> ~0.45 of the way left.
    const double expectedX = 80.0 * (1.0 - 3.0 / (10.0 * std::tan(glm::radians(22.5)) * 160.0 / 120.0));
    const double expectedY = 60.0 * (1.0 - 1.5 / (10.0 * std::tan(glm::radians(22.5))));  // rows go top to bottom
    // 2 pixels: perspective shifts a sphere's silhouette centroid slightly off its centre's projection.
    EXPECT_NEAR(sumX / count, expectedX, 2.0);
    EXPECT_NEAR(sumY / count, expectedY, 2.0);
    // The same pixels are not background in the colour image.
    const ImageRGBA8 color = renderer.readColor();
    EXPECT_GT(pixel(color, static_cast<int>(expectedX), static_cast<int>(expectedY)).r, 0.2f);
}

TEST_F(RenderGLTest, SurfaceBufferHoldsWorldPositionAndNormal) {
    const Scene scene = planeFromAbove(R"({"type": "directional", "direction": [0, -1, 0]})");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {65, 65, TimingClock::Off, true});
    const SurfaceBuffer s = renderer.readSurfaces();
    const glm::vec4 p = s.position[32 * 65 + 32], n = s.normal[32 * 65 + 32];
    EXPECT_NEAR(glm::length(glm::vec3(p)), 0.0f, 1e-4f);  // the centre pixel sees the origin
    EXPECT_FLOAT_EQ(p.w, 1.0f);
    EXPECT_NEAR(n.y, 1.0f, 1e-3f);                          // half-float normal
    EXPECT_FLOAT_EQ(n.w, 1.0f);                             // receives shadows
}

TEST_F(RenderGLTest, SizeBeyondTheGpuLimitIsAnError) {
    const Scene scene = planeFromAbove(R"({"type": "directional", "direction": [0, -1, 0]})");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    const int tooBig = test::glContext().info().maxTextureSize + 1;
    EXPECT_THROW(renderer.render(scene, {tooBig, 4}), Error);
    EXPECT_THROW(renderer.render(scene, {0, 4}), Error);
}

TEST_F(RenderGLTest, TimingsNameEveryPassOfTheFrame) {
    // Two lights with "none": the first is shaded inside the base pass, the
    // second gets a pass of its own.
    Scene scene = defaultScene({"lights[0].shadow.technique=none"});
    scene.lights.push_back(scene.lights[0]);
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = 128;
    options.height = 72;
    options.clock = TimingClock::CpuFinish;
    const FrameStats stats = renderer.render(scene, options);
    EXPECT_EQ(stats.clock, "cpu-finish");
    EXPECT_EQ(stats.baseLight, 0);
    std::vector<std::string> names;
    double sum = 0.0;
    for (const PassTiming& p : stats.passes) {
        names.push_back(p.name);
        EXPECT_GE(p.ms, 0.0) << p.name;
        sum += p.ms;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"base", "light[1]"}));
    // The passes are inside the frame: their sum cannot exceed its wall time.
    EXPECT_LE(sum, stats.cpuMs);
    options.clock = TimingClock::Off;
    const FrameStats off = renderer.render(scene, options);
    EXPECT_EQ(off.clock, "off");
    for (const PassTiming& p : off.passes) EXPECT_EQ(p.ms, 0.0) << p.name;
}

TEST_F(RenderGLTest, EveryBundledSceneRendersWithoutGlError) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const Scene scene = loadSceneFile(entry.path());
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 160;
        options.height = 90;
        options.surfaces = true;
        renderer.render(scene, options);
        EXPECT_EQ(test::glContext().debugErrorCount(), 0u) << test::glContext().lastDebugError();
        // Something was drawn: geometry covers part of the image and it is not one flat colour.
        const SurfaceBuffer s = renderer.readSurfaces();
        std::size_t covered = 0;
        for (const glm::vec4& p : s.position) covered += p.w > 0.5f;
        EXPECT_GT(covered, s.position.size() / 10);
        // Its lights light it: with every light off, at least 10% of the
        // covered pixels get darker (each scene's lights face most of its surfaces).
        const ImageRGBA8 lit = renderer.readColor();
        Scene dark = scene;
        for (Light& light : dark.lights) light.intensity = 0.0f;
        renderer.render(dark, {160, 90});
        const ImageRGBA8 unlit = renderer.readColor();
        std::size_t brighter = 0;
        for (std::size_t i = 0; i < lit.pixels.size(); i += 4) brighter += lit.pixels[i] + lit.pixels[i + 1] + lit.pixels[i + 2] > unlit.pixels[i] + unlit.pixels[i + 1] + unlit.pixels[i + 2];
        EXPECT_GT(brighter, covered / 10);
        ++count;
    }
    EXPECT_GE(count, 8);
}

TEST_F(RenderGLTest, TextureWiderThanTheGpuLimitIsAnError) {
    const int tooWide = test::glContext().info().maxTextureSize + 1;
    const fs::path png = fs::temp_directory_path() / ("shadowlab-wide-" + std::to_string(::getpid()) + ".png");
    writePng(png, ImageRGBA8{tooWide, 1, std::vector<std::uint8_t>(static_cast<std::size_t>(tooWide) * 4, 255)});
    const Scene scene = parseScene(R"({"materials": {"m": {"baseColorTexture": ")" + png.filename().string() + R"("}},
                                       "nodes": [{"shape": {"type": "box"}, "material": "m"}]})", "test", png.parent_path());
    fs::remove(png);
    Renderer renderer(test::glContext());
    try {
        renderer.upload(scene);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("texture 0 (" + std::to_string(tooWide) + "x1)"), std::string::npos) << e.what();
        // The message names where the texture came from: file and JSON path.
        EXPECT_EQ(std::string(e.what()).rfind("test: materials.m.baseColorTexture (", 0), 0u) << e.what();
    }
}

TEST_F(RenderGLTest, ASpotProjectsItsImageTheRightWayUp) {
    // A slide in four blocks: top-left red, top-right green, bottom-left
    // blue, bottom-right white, projected straight down. A vertical spot's camera
    // has +X as up, so the slide's top lands towards +X and its right
    // towards +Z (cross(-Y, +X)). The camera above has -Z up: world +X is
    // image right, +Z image down.
    const fs::path png = fs::temp_directory_path() / ("shadowlab-slide-" + std::to_string(::getpid()) + ".png");
    // 16x16 texels in four solid 8x8 blocks, so linear filtering blends
    // colours only along the block borders.
    ImageRGBA8 slide{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 255)};
    const std::uint8_t colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            std::copy_n(colours[(y / 8) * 2 + x / 8], 3, &slide.pixels[(static_cast<std::size_t>(y) * 16 + x) * 4]);
    writePng(png, slide);
    const Scene local = parseScene(R"({
      "camera": {"position": [0, 5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fovY": 40},
      "ambient": [0, 0, 0],
      "materials": {"m": {"baseColor": [1, 1, 1], "specular": [0, 0, 0]}},
      "lights": [{"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "innerCone": 30, "outerCone": 31,
                  "projector": ")" + png.filename().string() + R"("}],
      "nodes": [{"shape": {"type": "plane", "size": [100, 100]}, "material": "m"}]
    })", "slide", png.parent_path());
    fs::remove(png);
    const ImageRGBA8 image = renderImage(local, 128, 128);
    // Mean image position of the pixels each colour dominates.
    struct Acc { double x = 0, y = 0, n = 0; } red, green, blue, white;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            const glm::vec3 c = pixel(image, x, y);
            Acc* a = c.r > 0.5f && c.g > 0.5f && c.b > 0.5f ? &white
                     : c.r > 0.5f && c.g < 0.2f ? &red : c.g > 0.5f && c.r < 0.2f ? &green : c.b > 0.5f && c.r < 0.2f ? &blue : nullptr;
            if (!a) continue;
            a->x += x;
            a->y += y;
            a->n += 1;
        }
    for (Acc* a : {&red, &green, &blue, &white}) {
        ASSERT_GT(a->n, 200) << "every quadrant of the slide is on the floor";
        a->x /= a->n;
        a->y /= a->n;
    }
    // Top of the slide (red, green) towards +X: image right.
    EXPECT_GT(red.x, blue.x + 10);
    EXPECT_GT(green.x, white.x + 10);
    // Right of the slide (green, white) towards +Z: image down.
    EXPECT_GT(green.y, red.y + 10);
    EXPECT_GT(white.y, blue.y + 10);
}

// The viewer reads a scene again on every change (Renderer::upload, then
// render): a hundred reloads must not leave GL objects behind. Counted by
// the library's handles (liveGlObjects); a map, a cube and volumes all run.
TEST_F(RenderGLTest, AHundredReloadsLeaveNoGlObjectsBehind) {
    const Scene scene = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "room-point.json",
                                      {"lights[0].shadow.technique=map", "lights[0].shadow.map.size=256"});
    const Scene sun = defaultScene({"lights[0].shadow.technique=volume"});
    Renderer renderer(test::glContext());
    RenderOptions options;
    options.width = 160;
    options.height = 90;
    long afterFirst = 0;
    for (int i = 0; i < 100; ++i) {
        const Scene& s = i % 2 ? sun : scene;
        renderer.upload(s);
        renderer.render(s, options);
        if (i == 1) afterFirst = liveGlObjects();
    }
    EXPECT_GT(afterFirst, 10);
    EXPECT_EQ(liveGlObjects(), afterFirst);
}
