// Shader variants and source assembly, without a GPU.
#include "gl/ShaderSource.h"
#include "render/ShaderVariant.h"

#include <shadowlab/Error.h>

#include <gtest/gtest.h>

#include <set>

using namespace shadowlab;

TEST(ShaderVariant, DistinctVariantsHaveDistinctKeys) {
    std::set<std::uint32_t> keys;
    int count = 0;
    for (ShaderPass pass : {ShaderPass::Base, ShaderPass::Light})
        for (LightType light : {LightType::Directional, LightType::Spot, LightType::Point})
            for (bool texture : {false, true}) {
                if (pass == ShaderPass::Base && light != LightType::Directional) continue;  // light ignored in Base
                keys.insert(ShaderVariant{pass, light, ShadowTechnique::None, texture}.key());
                ++count;
            }
    keys.insert(ShaderVariant{ShaderPass::Resolve}.key());
    EXPECT_EQ(keys.size(), static_cast<std::size_t>(count + 1));
}

TEST(ShaderVariant, FieldsThatDoNotApplyDoNotSplitTheCache) {
    EXPECT_EQ((ShaderVariant{ShaderPass::Base, LightType::Directional}.key()),
              (ShaderVariant{ShaderPass::Base, LightType::Point}.key()));
    EXPECT_EQ((ShaderVariant{ShaderPass::Resolve, LightType::Spot, ShadowTechnique::None, true}.key()),
              (ShaderVariant{ShaderPass::Resolve}.key()));
}

TEST(ShaderVariant, PreambleDefinesEverySwitchTheSourcesTest) {
    const std::string p = ShaderVariant{ShaderPass::Light, LightType::Spot, ShadowTechnique::None, true}.preamble();
    EXPECT_NE(p.find("#define LIGHT_TYPE SL_LIGHT_SPOT\n"), std::string::npos) << p;
    EXPECT_NE(p.find("#define SHADOW_TECHNIQUE SL_SHADOW_NONE\n"), std::string::npos) << p;
    EXPECT_NE(p.find("#define HAS_BASE_COLOR_TEXTURE 1\n"), std::string::npos) << p;
}

TEST(ShaderSource, IncludesExpandWithLineDirectivesPerFile) {
    const gl::AssembledSource s = gl::assembleShader("lighting.frag", "#define X 1\n");
    EXPECT_EQ(s.text.rfind("#version 450 core\n#define X 1\n", 0), 0u);
    // preamble, lighting.frag, shadowlab_shared.h, light_reach.h and the
    // shadowlab_shared.h it includes (its include guard leaves that copy empty).
    ASSERT_EQ(s.files.size(), 5u);
    EXPECT_EQ(s.files[1], "lighting.frag");
    EXPECT_EQ(s.files[2], "shadowlab_shared.h");
    EXPECT_EQ(s.files[3], "light_reach.h");
    EXPECT_NE(s.text.find("#line 1 2\n"), std::string::npos);
    EXPECT_EQ(s.text.find("#include \""), std::string::npos);  // quoted includes are all expanded
}

TEST(ShaderSource, MissingFileIsAnError) {
    EXPECT_THROW(gl::assembleShader("nope.frag", ""), Error);
}

TEST(ShaderSource, CompileLogNamesFileLineAndText) {
    const gl::AssembledSource s = gl::assembleShader("resolve.frag", "");
    // Mesa's form "<source>:<line>(<column>): error: ..."; line 1 of resolve.frag.
    const auto embedded = gl::embeddedShader("resolve.frag");
    ASSERT_TRUE(embedded);
    const std::string firstLine(embedded->substr(0, embedded->find('\n')));
    const std::string log = gl::describeShaderLog("1:1(3): error: something is wrong\n", s);
    EXPECT_EQ(log, "resolve.frag:1: error: something is wrong | " + firstLine);
    // NVIDIA's form "<source>(<line>) : error ...".
    EXPECT_EQ(gl::describeShaderLog("0(2) : error C0000: bad", s).rfind("<variant preamble>:2: error C0000: bad", 0), 0u);
}
