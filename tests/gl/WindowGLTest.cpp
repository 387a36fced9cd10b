// The GLFW window context (for the viewer) runs the same renderer as the
// headless one. Run under a display; CI uses xvfb-run (tests/CMakeLists.txt).
#include <shadowlab/Context.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <gtest/gtest.h>

using namespace shadowlab;

TEST(WindowGLTest, WindowContextRendersTheDefaultSceneLikeHeadless) {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "needs a display (run through xvfb-run)";
    const Scene scene = defaultScene();
    ImageRGBA8 windowed;
    {
        Context context = Context::createWindow(160, 90, "shadowlab test");
        ASSERT_NE(context.window(), nullptr);
        EXPECT_EQ(context.info().platform, "glfw");
        Renderer renderer(context);
        renderer.upload(scene);
        renderer.render(scene, {160, 90});
        windowed = renderer.readColor();
        EXPECT_EQ(context.debugErrorCount(), 0u) << context.lastDebugError();
    }
    Context headless = Context::createHeadless();
    EXPECT_EQ(headless.window(), nullptr);
    Renderer renderer(headless);
    renderer.upload(scene);
    renderer.render(scene, {160, 90});
    const ImageRGBA8 offscreen = renderer.readColor();
    // Same driver, same shaders: the images agree to within one 8-bit step
    // per channel (a different GL implementation behind GLX could round differently).
    ASSERT_EQ(windowed.pixels.size(), offscreen.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < offscreen.pixels.size(); ++i)
        differing += std::abs(int(windowed.pixels[i]) - int(offscreen.pixels[i])) > 1;
    EXPECT_EQ(differing, 0u);
}
