#pragma once
// One headless context for the whole test binary; each test fails if the
// driver reported a GL error (KHR_debug) while it ran.
#include <shadowlab/Context.h>

#include <gtest/gtest.h>

#include <memory>

namespace shadowlab::test {

inline Context& glContext() {
    static Context context = Context::createHeadless();
    return context;
}

class GLTest : public ::testing::Test {
protected:
    void SetUp() override {
        glContext().makeCurrent();
        glContext().resetDebugErrors();
    }
    void TearDown() override {
        EXPECT_EQ(glContext().debugErrorCount(), 0u) << "GL error: " << glContext().lastDebugError();
    }
};

} // namespace shadowlab::test
