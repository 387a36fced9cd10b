// Shader programs on the headless context: every variant compiles; a
// compile error names the file, the line and its text.
#include "GLTestContext.h"

#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "render/ShaderVariant.h"

#include <shadowlab/Error.h>

#include <algorithm>

using namespace shadowlab;
using shadowlab::test::GLTest;

class ProgramGLTest : public GLTest {};

TEST_F(ProgramGLTest, EveryVariantCompilesAndLinks) {
    int built = 0;
    for (ShaderPass pass : {ShaderPass::Base, ShaderPass::Light, ShaderPass::Resolve})
        for (LightType light : {LightType::Directional, LightType::Spot, LightType::Point})
            for (bool texture : {false, true}) {
                const ShaderVariant v{pass, light, ShadowTechnique::None, texture};
                SCOPED_TRACE(v.preamble());
                gl::Program program(v.stages(), v.preamble());
                EXPECT_NE(program.id(), 0u);
                ++built;
            }
    EXPECT_EQ(built, 18);
}

TEST_F(ProgramGLTest, CompileErrorNamesFileLineAndText) {
    // A technique number no module defines stops lighting.frag at its #error.
    try {
        gl::Program program({{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}},
                            "#define HAS_BASE_COLOR_TEXTURE 0\n#define LIGHT_TYPE SL_LIGHT_POINT\n#define SHADOW_TECHNIQUE 99\n");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        const auto source = gl::embeddedShader("lighting.frag");
        ASSERT_TRUE(source);
        // The line number of the #error directive in the embedded file.
        const auto at = source->find("#error unknown SHADOW_TECHNIQUE");
        ASSERT_NE(at, std::string_view::npos);
        const long line = 1 + std::count(source->begin(), source->begin() + static_cast<long>(at), '\n');
        EXPECT_NE(m.find("lighting.frag:" + std::to_string(line) + ": "), std::string::npos) << m;
        EXPECT_NE(m.find("| #error unknown SHADOW_TECHNIQUE"), std::string::npos) << m;  // the line's text
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    test::glContext().resetDebugErrors();  // the failed compile is expected to be reported
}
