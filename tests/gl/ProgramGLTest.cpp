// Shader programs on the headless context: every variant compiles; a
// compile error names the file, the line and its text.
#include "GLTestContext.h"

#include "gl/Debug.h"

#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "render/ShaderVariant.h"

#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <algorithm>
#include <set>

using namespace shadowlab;
using shadowlab::test::GLTest;

class ProgramGLTest : public GLTest {};

TEST_F(ProgramGLTest, EveryVariantCompilesAndLinks) {
    std::set<std::string> built;
    for (const ShaderVariant& v : ShaderVariant::all()) {
        const gl::ProgramKey key = v.program();
        if (!built.insert(key.id()).second) continue;
        SCOPED_TRACE(key.preamble);
        gl::Program program(key);
        EXPECT_NE(program.id(), 0u);
    }
    // Without a light: ambient x texture x surfaces = 8 programs (light type
    // and the visibility modes do not apply); with one: the same 8 x 3 light
    // types x 4 combinations of the two visibility switches = 96; each
    // opaque, alpha-tested (alphaMode mask) or blended.
    EXPECT_EQ(built.size(), 3u * (8u + 96u));
}

TEST_F(ProgramGLTest, TheContextCacheCompilesEachProgramOnce) {
    gl::ProgramCache& cache = *test::glContext().impl().programs;
    ShaderVariant v;
    v.light = true;
    v.lightType = LightType::Spot;
    v.techniqueDefines = "#define CACHE_TEST_UNIQUE 1\n";  // a program no other test asks for
    const std::size_t before = cache.compiles();
    const gl::Program& first = cache.get(v.program());
    const gl::Program& second = cache.get(v.program());
    EXPECT_EQ(&first, &second);
    EXPECT_EQ(cache.compiles(), before + 1);
}

TEST_F(ProgramGLTest, ASecondRendererOnTheContextCompilesNothing) {
    // bench makes a Renderer per combination: the programs outlive it.
    const Scene scene = defaultScene();
    gl::ProgramCache& cache = *test::glContext().impl().programs;
    {
        Renderer first(test::glContext());
        first.upload(scene);
        first.render(scene, {64, 36});
    }
    const std::size_t compiled = cache.compiles();
    Renderer second(test::glContext());
    second.upload(scene);
    second.render(scene, {64, 36});
    EXPECT_EQ(cache.compiles(), compiled);
}

TEST_F(ProgramGLTest, CompileErrorNamesFileLineAndText) {
    // A preprocessor error: Mesa attributes those to the right source string
    // (its semantic errors all come back as string 0).
    const std::string text = "void main() {}\n#error broken on purpose\n";
    try {
        gl::Program program({{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "broken.frag", text}}, "#define X 1\n");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("broken.frag:2: "), std::string::npos) << m;
        EXPECT_NE(m.find("| #error broken on purpose"), std::string::npos) << m;  // the line's text
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    test::glContext().resetDebugErrors();  // the failed compile is expected to be reported
}
