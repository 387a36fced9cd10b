// Shader variants and source assembly, without a GPU.
#include "gl/ShaderSource.h"
#include "render/ShaderVariant.h"
#include "shadow_map_shared.h"
#include "techniques/map/options/Settings.h"

#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace shadowlab;


TEST(ShaderVariant, DistinctVariantsHaveDistinctPrograms) {
    // Two variants get the same program exactly when they differ only in
    // fields that do not apply (light type, screen/output visibility without a light).
    auto canonical = [](ShaderVariant v) {
        if (!v.light) {
            v.lightType = LightType::Directional;
            v.screenVisibility = v.outputVisibility = false;
        }
        return std::make_tuple(v.ambient, v.light, static_cast<int>(v.lightType), v.baseColorTexture, v.writeSurfaces,
                               v.screenVisibility, v.outputVisibility, v.blended, v.alphaTest);
    };
    std::map<std::string, std::set<decltype(canonical(ShaderVariant{}))>> byProgram;
    for (const ShaderVariant& v : ShaderVariant::all()) byProgram[v.program().id()].insert(canonical(v));
    std::set<decltype(canonical(ShaderVariant{}))> distinct;
    for (const ShaderVariant& v : ShaderVariant::all()) distinct.insert(canonical(v));
    EXPECT_EQ(byProgram.size(), distinct.size());
    for (const auto& [id, variants] : byProgram) EXPECT_EQ(variants.size(), 1u) << id;
}

TEST(ShaderVariant, TechniqueFileAndDefinesSplitTheCacheOnlyWithALight) {
    ShaderVariant a, b;
    a.light = b.light = true;
    b.techniqueFile = "shadow_other.glsl";
    EXPECT_NE(a.program().id(), b.program().id());
    b = a;
    b.techniqueDefines = "#define MAP_FILTER 2\n";
    EXPECT_NE(a.program().id(), b.program().id());
    EXPECT_NE(b.preamble().find("#define MAP_FILTER 2\n"), std::string::npos);
    a.light = b.light = false;  // the base pass without a light never reads the technique
    EXPECT_EQ(a.program().id(), b.program().id());
}

TEST(ShaderVariant, PreambleDefinesEverySwitchTheSourcesTest) {
    ShaderVariant v;
    v.light = true;
    v.lightType = LightType::Spot;
    v.baseColorTexture = true;
    const std::string p = v.preamble();
    for (const char* define : {"#define AMBIENT 1\n", "#define LIGHT 1\n", "#define LIGHT_TYPE SL_LIGHT_SPOT\n",
                               "#define HAS_BASE_COLOR_TEXTURE 1\n", "#define WRITE_SURFACES 0\n",
                               "#define SCREEN_VISIBILITY 0\n", "#define OUTPUT_VISIBILITY 0\n",
                               "#define BLENDED 0\n"})
        EXPECT_NE(p.find(define), std::string::npos) << define << " in " << p;
    const gl::ProgramKey key = v.program();
    ASSERT_EQ(key.aliases.size(), 2u);
    EXPECT_EQ(key.aliases[0], (std::pair<std::string, std::string>{"@shadow", "shadow_none.glsl"}));
    EXPECT_EQ(key.aliases[1], (std::pair<std::string, std::string>{"@list_shadow", "shadow_list_none.glsl"}));
}

TEST(ShaderSource, IncludesExpandWithLineDirectivesPerFile) {
    const gl::AssembledSource s =
        gl::assembleShader("lighting.frag", "#define X 1\n", {{"@shadow", "shadow_none.glsl"}, {"@list_shadow", "shadow_atlas_list.glsl"}});
    EXPECT_EQ(s.text.rfind("#version 450 core\n#define X 1\n#define SL_BINDING(unit) layout(binding = unit)\n", 0), 0u);
    // preamble, lighting.frag, shadowlab_shared.h, light_reach.h and the
    // shadowlab_shared.h it includes (its include guard leaves that copy
    // empty), alpha_test.h and its own copy of shadowlab_shared.h, then the
    // "@shadow" slot's file, then the "@list_shadow" slot's (inside #if
    // LIGHT_LIST_SHADOWS): shadow_atlas_list.glsl, its shadow_atlas.glsl,
    // shadow_atlas_shared.h and that one's shadowlab_shared.h.
    ASSERT_EQ(s.files.size(), 12u);
    EXPECT_EQ(s.files[1], "lighting.frag");
    EXPECT_EQ(s.files[2], "shadowlab_shared.h");
    EXPECT_EQ(s.files[3], "light_reach.h");
    EXPECT_EQ(s.files[5], "alpha_test.h");
    EXPECT_EQ(s.files[7], "shadow_none.glsl");
    EXPECT_EQ(s.files[8], "shadow_atlas_list.glsl");
    EXPECT_EQ(s.files[9], "shadow_atlas.glsl");
    EXPECT_EQ(s.files[10], "shadow_atlas_shared.h");
    EXPECT_NE(s.text.find("#line 1 2\n"), std::string::npos);
    EXPECT_EQ(s.text.find("#include \""), std::string::npos);  // quoted includes are all expanded
}

TEST(ShaderSource, MissingFileIsAnError) {
    EXPECT_THROW(gl::assembleShader("nope.frag", ""), Error);
}

TEST(ShaderSource, AnUnfilledSlotIsAnErrorNamingIt) {
    try {
        gl::assembleShader("lighting.frag", "");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("lighting.frag: #include \"@shadow\""), std::string::npos) << e.what();
    }
}

TEST(ShaderSource, InlineTextIsAssembledAndQuotedInMessages) {
    const gl::AssembledSource s = gl::assembleShader("test.frag", "", {}, "void main() {}\nbroken line\n");
    EXPECT_NE(s.text.find("broken line"), std::string::npos);
    EXPECT_EQ(gl::describeShaderLog("1:2(1): error: syntax", s), "test.frag:2: error: syntax | broken line");
}

TEST(ShaderSource, CompileLogNamesFileLineAndText) {
    const gl::AssembledSource s = gl::assembleShader("fullscreen.vert", "");
    // Mesa's form "<source>:<line>(<column>): error: ..."; line 1 of fullscreen.vert.
    const auto embedded = gl::embeddedShader("fullscreen.vert");
    ASSERT_TRUE(embedded);
    const std::string firstLine(embedded->substr(0, embedded->find('\n')));
    const std::string log = gl::describeShaderLog("1:1(3): error: something is wrong\n", s);
    EXPECT_EQ(log, "fullscreen.vert:1: error: something is wrong | " + firstLine);
    // NVIDIA's form "<source>(<line>) : error ...".
    EXPECT_EQ(gl::describeShaderLog("0(2) : error C0000: bad", s).rfind("<variant preamble>:2: error C0000: bad", 0), 0u);
}

// The filters' early out (MapOptions::earlyOut): the rounds of four taps
// after the first (an odd grid's centre) are exactly the rest of the
// kernel, so a pixel whose corners disagree takes every tap once; filters
// and maps without an early-out path, or with it off, take none.
TEST(MapEarlyOut, RoundsTakeEveryTapOfTheKernelOnce) {
    using shadowlab::MapFilter;
    shadowlab::MapOptions o;
    o.filter = MapFilter::Grid;
    for (int n = 3; n <= 8; ++n) {
        o.kernel = n;
        EXPECT_EQ(4 * shadowlab::map::kernelRounds(o, false) + n % 2, n * n) << "kernel " << n;
        EXPECT_EQ(shadowlab::map::kernelRounds(o, true), 0) << "a cube's 3-D grid has no early out";
        EXPECT_TRUE(shadowlab::map::earlyOut(o, false, true)) << "nearest taps on a software rasteriser";
    }
    o.kernel = 2;  // four corners and nothing between them
    EXPECT_EQ(shadowlab::map::kernelRounds(o, false), 0);
    o.kernel = 3;
    o.gridTaps = shadowlab::MapGridTaps::Bilinear;  // pairs of taps per fetch: every tap
    EXPECT_FALSE(shadowlab::map::earlyOut(o, false, true));
    o.filter = MapFilter::Pcf20;
    EXPECT_EQ(4 * shadowlab::map::kernelRounds(o, true), 20);
    EXPECT_TRUE(shadowlab::map::earlyOut(o, true, false));
    o.earlyOut = false;
    EXPECT_EQ(shadowlab::map::kernelRounds(o, true), 0);
    EXPECT_FALSE(shadowlab::map::earlyOut(o, true, false));
    o.earlyOut = true;
    for (MapFilter f : {MapFilter::None, MapFilter::Hardware, MapFilter::Dither4, MapFilter::Poisson, MapFilter::Pcss, MapFilter::Box}) {
        o.filter = f;
        EXPECT_EQ(shadowlab::map::kernelRounds(o, false), 0);
        EXPECT_EQ(shadowlab::map::kernelRounds(o, true), 0);
    }
}

// pcss's umbra early out: vogelHullInradius(n) is the distance from the
// centre to the nearest edge of the convex hull of the disk's n taps,
// checked without building a hull: for a point inside a convex hull that
// distance is the least, over all directions, of how far the taps reach
// along the direction (its support function), here over 7200 directions
// half a tenth of a degree apart. A sampled direction misses the nearest
// edge's normal by at most 4.4e-4 radians, which adds at most that times
// the edge's length (under 1.2 in the unit disk): the sampled least is at
// or above the true distance and at most 5.3e-4 above it.
TEST(MapEarlyOut, TheBlockerHullsInradiusIsTheTapsLeastReach) {
    const double golden = SL_MAP_GOLDEN_ANGLE, pi = 3.14159265358979;
    for (int n : {4, 5, 8, 16, 32, 64}) {
        SCOPED_TRACE("taps " + std::to_string(n));
        std::vector<std::pair<double, double>> taps;
        for (int k = 0; k < n; ++k) {
            const double r = std::sqrt((k + 0.5) / n), a = k * golden;
            taps.emplace_back(r * std::cos(a), r * std::sin(a));
        }
        double least = 1e9;
        for (int d = 0; d < 7200; ++d) {
            const double ux = std::cos(d * pi / 3600.0), uy = std::sin(d * pi / 3600.0);
            double reach = -1e9;
            for (const auto& [tx, ty] : taps) reach = std::max(reach, tx * ux + ty * uy);
            least = std::min(least, reach);
        }
        ASSERT_GT(least, 0.0) << "the centre is inside the taps' hull";
        const double inradius = shadowlab::map::vogelHullInradius(n);
        EXPECT_LE(inradius, least + 1e-6);
        EXPECT_GE(inradius, least - 5.3e-4);
        if (n >= 8) {
            EXPECT_GT(least, 0.5) << "8 taps and more leave most of the disk inside their hull";
        }
    }
    shadowlab::MapOptions o;
    o.filter = shadowlab::MapFilter::Pcss;
    EXPECT_TRUE(shadowlab::map::earlyOut(o, false, true));
    EXPECT_TRUE(shadowlab::map::earlyOut(o, true, false));
    o.earlyOut = false;
    EXPECT_FALSE(shadowlab::map::earlyOut(o, false, true));
}
