// Which clock times passes where (no GPU needed for the choice itself).
#include "gl/PassClock.h"

#include <gtest/gtest.h>

using namespace shadowlab::gl;

TEST(PassClock, SoftwareRasterisersAreTimedWithFinish) {
    EXPECT_EQ(clockFor("llvmpipe (LLVM 15.0.6, 256 bits)"), ClockKind::CpuFinish);
    EXPECT_EQ(clockFor("softpipe"), ClockKind::CpuFinish);
    EXPECT_EQ(clockFor("SWR (LLVM 12, 256 bits)"), ClockKind::CpuFinish);
    EXPECT_EQ(clockFor("NVIDIA GeForce RTX 3080/PCIe/SSE2"), ClockKind::GpuTimestamp);
    EXPECT_EQ(clockFor("AMD Radeon RX 6800 (radeonsi, navi21, LLVM 15.0.6, DRM 3.49, 6.1.0)"), ClockKind::GpuTimestamp);
    EXPECT_STREQ(toString(ClockKind::CpuFinish), "cpu-finish");
    EXPECT_STREQ(toString(ClockKind::GpuTimestamp), "gpu-timestamp");
}

TEST(PassClock, OffRecordsNestedNamesWithoutAContext) {
    // ClockKind::Off makes no GL call, so it runs without a context.
    PassClock clock(ClockKind::Off);
    clock.begin("shadow[2]");
    clock.begin("blur");
    clock.end();
    clock.end();
    clock.begin("base");
    clock.end();
    const auto r = clock.results();
    ASSERT_EQ(r.size(), 3u);
    EXPECT_EQ(r[0].first, "shadow[2]");
    EXPECT_EQ(r[1].first, "shadow[2].blur");
    EXPECT_EQ(r[2].first, "base");
    for (const auto& [name, ms] : r) EXPECT_EQ(ms, 0.0) << name;
}
