#pragma once
// Image tests save what they saw when they fail: the actual image, the
// expected one and a difference image, under
// ${CMAKE_BINARY_DIR}/test-artifacts/<suite>.<test>/, and print the path.
#include <shadowlab/Image.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>

namespace shadowlab::test {

/// 8-bit RGBA copy of a greyscale image (0..65535 -> 0..255).
inline ImageRGBA8 toRgba(const ImageGray16& image) {
    ImageRGBA8 out{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size() * 4, 255)};
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        std::fill_n(&out.pixels[i * 4], 3, static_cast<std::uint8_t>(image.pixels[i] >> 8));
    return out;
}

/// 8-bit RGBA copy of a 0/1 (or 0/255) mask: white where set.
inline ImageRGBA8 maskToRgba(int width, int height, const std::vector<std::uint8_t>& mask) {
    ImageRGBA8 out{width, height, std::vector<std::uint8_t>(mask.size() * 4, 255)};
    for (std::size_t i = 0; i < mask.size(); ++i) std::fill_n(&out.pixels[i * 4], 3, mask[i] ? 255 : 0);
    return out;
}

/// Where two images of one size differ: red where any channel differs, the
/// actual image dimmed to a third elsewhere.
inline ImageRGBA8 diffImage(const ImageRGBA8& actual, const ImageRGBA8& expected) {
    ImageRGBA8 out{actual.width, actual.height, std::vector<std::uint8_t>(actual.pixels.size(), 255)};
    for (std::size_t i = 0; i + 3 < actual.pixels.size(); i += 4) {
        const bool same = i + 3 < expected.pixels.size() && std::equal(&actual.pixels[i], &actual.pixels[i] + 3, &expected.pixels[i]);
        for (int c = 0; c < 3; ++c)
            out.pixels[i + c] = same ? static_cast<std::uint8_t>(actual.pixels[i + c] / 3) : (c == 0 ? 255 : 0);
    }
    return out;
}

/// If the running test has failed, writes `<name>-actual.png`,
/// `<name>-expected.png` and `<name>-diff.png` into its artifact directory
/// and prints where. Call after the image's assertions.
inline void saveImagesIfFailed(const std::string& name, const ImageRGBA8& actual, const ImageRGBA8& expected) {
    if (!::testing::Test::HasFailure()) return;
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_ARTIFACT_DIR) /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    writePng(dir / (name + "-actual.png"), actual);
    writePng(dir / (name + "-expected.png"), expected);
    writePng(dir / (name + "-diff.png"), diffImage(actual, expected));
    std::cout << "[ artifacts ] " << (dir / name).string() << "-{actual,expected,diff}.png\n";
}

} // namespace shadowlab::test
