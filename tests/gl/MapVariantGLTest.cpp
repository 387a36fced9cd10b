// Every shader variant of technique "map" that one option changed from the
// defaults reaches, compiled, linked and drawn (llvmpipe compiles a program
// at its first draw, so a link alone proves little), under a sun, a spot
// and a point light, over a scene with an alpha-tested and a translucent
// caster (their passes have variants of their own), and the debug views
// of each (texel density, cascade colours). A variant that fails to
// compile or draw fails the test with the option and value named; the test
// prints how many distinct light-pass and shadow-pass programs it drew.
#include "GLTestContext.h"

#include "gl/PassClock.h"
#include "techniques/map/Variants.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/Arrays.h"

#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::GLTest;

namespace {

const char* kLights[] = {
    R"({"type": "directional", "direction": [0.3, -1, 0.2], "size": 1.0)",
    R"({"type": "spot", "position": [2, 4, 2], "direction": [-0.5, -1, -0.5], "outerCone": 40, "size": 0.2)",
    R"({"type": "point", "position": [0, 2.5, 0], "size": 0.2)",
};

Scene variantScene(const char* light, const std::vector<std::string>& overrides) {
    return parseScene(std::string(R"({
      "camera": {"position": [0, 5, 7], "target": [0, 0.5, 0], "fovY": 50},
      "materials": {"cutout": {"baseColor": [0.8, 0.8, 0.8], "alpha": 0.3, "alphaMode": "mask", "alphaCutoff": 0.5},
                    "glass": {"baseColor": [1, 0.2, 0.2], "alpha": 0.5, "alphaMode": "blend"}},
      "lights": [)") + light + R"(, "shadow": {"technique": "map", "map": {"size": 256}}}],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [10, 10]}},
        {"name": "box", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [-1, 0.5, 0]},
        {"name": "cutout", "shape": {"type": "box", "size": [0.8, 0.8, 0.1]}, "translation": [1, 1, 0], "material": "cutout"},
        {"name": "glass", "shape": {"type": "box", "size": [0.8, 0.8, 0.1]}, "translation": [0, 1.2, 1], "material": "glass"}
      ]
    })",
                      "variants", ".", overrides);
}

// The values one option takes, one at a time: every choice, both booleans,
// an integer's every value over a range of at most 16 (a kernel's side,
// the cascades: loop bounds compiled in) or else its ends, a number's ends
// (numbers are uniforms, drawn at both ends all the same). A map's size
// stops at 1024: larger maps change no variant, only memory.
std::vector<std::string> valuesOf(const OptionField& f) {
    auto number = [](double v) {
        const double r = std::round(v);
        return std::abs(v - r) < 1e-9 ? std::to_string(static_cast<long long>(r)) : std::to_string(v);
    };
    switch (f.kind) {
    case OptionKind::Choice: return f.choices;
    case OptionKind::Boolean: return {"true", "false"};
    case OptionKind::Integer: {
        const double top = f.key == "size" ? 1024.0 : f.maximum;
        if (top - f.minimum > 16.0) return {number(f.minimum), number(top)};
        std::vector<std::string> all;
        for (double v = f.minimum; v <= top; v += 1.0) all.push_back(number(v));
        return all;
    }
    case OptionKind::Number: return {number(f.minimum), number(f.maximum)};
    case OptionKind::Text: return {};  // cascadeSplits: distances, uniforms (CascadeTest checks them)
    }
    return {};
}

}  // namespace

class MapVariantGLTest : public GLTest {};

TEST_F(MapVariantGLTest, EveryVariantOneOptionFromTheDefaultsCompilesAndDraws) {
    Renderer renderer(test::glContext());
    const bool software = gl::isSoftwareRasterizer(test::glContext().info().renderer);
    std::set<std::string> lightPasses, shadowPasses;
    int drawn = 0, refused = 0;
    for (const char* light : kLights) {
        for (const OptionField& field : mapOptionTable().fields) {
            for (const std::string& value : valuesOf(field)) {
                const std::string set = "lights[0].shadow.map." + field.key + "=" + value;
                Scene scene;
                try {
                    scene = variantScene(light, {set});
                } catch (const Error&) {
                    ++refused;  // a combination the technique refuses (dither4 on a cube, ...): MapGLTest checks the messages
                    continue;
                }
                SCOPED_TRACE(std::string(light) + " with " + set);
                try {
                    renderer.upload(scene);
                    renderer.render(scene, RenderOptions{64, 48});
                    // The debug views' programs too (texel density, cascade colours).
                    EXPECT_FALSE(renderer.debugImages(scene).empty());
                } catch (const Error& e) {
                    ADD_FAILURE() << e.what();
                    continue;
                }
                ++drawn;
                const Light& l = scene.lights[0];
                const MapOptions& o = l.shadow.get<MapOptions>();  // as resolved when the scene was read
                lightPasses.insert(map::LightPassVariant::of(o, l, software, false).defines());
                if (map::isCube(o, l))
                    shadowPasses.insert(map::CubePassVariant{o.format, o.cubePasses == MapCubePasses::One, o.faceCulling}.defines());
                else {
                    const map::ArrayKey key = map::ArrayKey::of(o, false);
                    const bool moments = key.representation != MapRepresentation::Depth;
                    shadowPasses.insert(map::DepthPassVariant{moments ? MapFormat::Depth32F : key.format}.defines());
                    if (moments)  // the moments made from that depth, across (and down when blurred)
                        shadowPasses.insert(map::BlurVariant{true, o.blur, l.type == LightType::Spot, key.representation, key.momentFormat}.defines());
                }
                // The frame has the scene in it, not only the clear colour: the
                // ground alone fills over half of the 3,072 pixels; 500 leaves
                // room for any variant's shadows without passing a blank frame.
                const ImageRGBA8 image = renderer.readColor();
                std::size_t differ = 0;
                for (std::size_t p = 4; p < image.pixels.size(); p += 4) differ += image.pixels[p] != image.pixels[0];
                EXPECT_GT(differ, 500u);
            }
        }
    }
    std::printf("map variants: %d frames drawn (%d combinations refused), %zu light-pass and %zu shadow-pass programs\n", drawn, refused,
                lightPasses.size(), shadowPasses.size());
    // Every choice of filter, format and representation is a program of its
    // own somewhere: at least as many light-pass programs as their values.
    EXPECT_GE(lightPasses.size(), static_cast<std::size_t>(7 + 5 + 5));
}
