// The memory guards: the device memory a driver reports (read through the
// two extensions that report it, fed here by a fake driver, since llvmpipe
// has neither), and GL_OUT_OF_MEMORY turned into one clear error wherever it
// comes (provoked for real: a 4 TiB buffer no machine gives).
#include "GLTestContext.h"

#include "gl/Debug.h"
#include "gl/Object.h"

#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <epoxy/gl.h>

#include <set>
#include <string>

using namespace shadowlab;
using shadowlab::test::GLTest;
using shadowlab::test::glContext;

namespace {

// A driver with the named extensions, answering every query with `kib`.
struct FakeDriver {
    std::set<std::string> extensions;
    int kib = 0;
    std::set<unsigned> asked;
    gl::DeviceMemory query() {
        return gl::queryDeviceMemory([this](const char* name) { return extensions.count(name) > 0; },
                                     [this](unsigned pname, int* values) {
                                         asked.insert(pname);
                                         values[0] = kib;
                                     });
    }
};

// Asks GL for a buffer far beyond any memory: GL_OUT_OF_MEMORY.
void exhaustMemory() {
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferData(buffer, GLsizeiptr(1) << 42, nullptr, GL_STATIC_DRAW);
    glDeleteBuffers(1, &buffer);
}

} // namespace

TEST(DeviceMemory, ReadFromNvxGpuMemoryInfoInKibibytes) {
    FakeDriver nvx{{"GL_NVX_gpu_memory_info"}, 2 * 1024 * 1024, {}};
    const gl::DeviceMemory m = nvx.query();
    EXPECT_EQ(m.bytes, 2LL << 30);
    EXPECT_EQ(m.source, "GL_NVX_gpu_memory_info");
    EXPECT_EQ(nvx.asked, std::set<unsigned>{0x9049u});  // current available video memory, not the total
}

TEST(DeviceMemory, ReadFromAtiMeminfoWhenThereIsNoNvx) {
    FakeDriver ati{{"GL_ATI_meminfo"}, 512 * 1024, {}};
    const gl::DeviceMemory m = ati.query();
    EXPECT_EQ(m.bytes, 512LL << 20);
    EXPECT_EQ(m.source, "GL_ATI_meminfo");
    EXPECT_EQ(ati.asked, std::set<unsigned>{0x87FCu});  // GL_TEXTURE_FREE_MEMORY_ATI
}

TEST(DeviceMemory, UnknownWithoutEitherExtensionOrWithNoAnswer) {
    FakeDriver none{{}, 1024, {}};
    EXPECT_EQ(none.query().bytes, 0);
    EXPECT_TRUE(none.asked.empty());
    FakeDriver silent{{"GL_NVX_gpu_memory_info"}, 0, {}};
    EXPECT_EQ(silent.query().bytes, 0);
    EXPECT_EQ(silent.query().source, "");
}

TEST_F(GLTest, OutOfMemoryIsOneErrorNamingWhereItCame) {
    exhaustMemory();
    try {
        gl::throwIfOutOfMemory("while testing");
        ADD_FAILURE() << "no error thrown";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "the GPU ran out of memory while testing (GL_OUT_OF_MEMORY): lower --width/--height or lights[i].shadow.map.size");
    }
    EXPECT_NO_THROW(gl::throwIfOutOfMemory("again"));  // the flag was cleared
    glContext().resetDebugErrors();  // the debug output saw the provoked error too
}

TEST_F(GLTest, AFrameAfterOutOfMemoryFailsInsteadOfDrawingGarbage) {
    const Scene scene = defaultScene({});
    Renderer renderer(glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = 32;
    options.height = 32;
    EXPECT_NO_THROW(renderer.render(scene, options));
    exhaustMemory();
    try {
        renderer.render(scene, options);
        ADD_FAILURE() << "no error thrown";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ran out of memory while drawing the frame (GL_OUT_OF_MEMORY)"), std::string::npos) << e.what();
    }
    glContext().resetDebugErrors();
}

// A framebuffer left incomplete because its attachment got no memory says
// so in one line (the error thrown), and the debug output prints nothing of
// it: no "GL error: GL_OUT_OF_MEMORY" or "FBO incomplete" lines before it.
TEST_F(GLTest, AnIncompleteFramebufferAfterOutOfMemoryIsOneLine) {
    gl::Framebuffer fbo;  // no attachment: incomplete
    testing::internal::CaptureStderr();
    exhaustMemory();
    std::string message;
    try {
        gl::checkFramebuffer(fbo, "test framebuffer");
    } catch (const Error& e) {
        message = e.what();
    }
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_EQ(message, "the GPU ran out of memory making the test framebuffer (GL_OUT_OF_MEMORY): lower --width/--height or "
                       "lights[i].shadow.map.size");
    EXPECT_EQ(printed, "");
    EXPECT_EQ(glContext().debugErrorCount(), 1u);  // still counted for the run's final check
    glContext().resetDebugErrors();
}
