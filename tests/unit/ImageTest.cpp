// PNG writing: round trips, and no partial file on failure.
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {
fs::path tempFile(const std::string& name) {
    return fs::temp_directory_path() / ("shadowlab-imagetest-" + std::to_string(::getpid()) + "-" + name);
}
} // namespace

TEST(Image, Rgba8RoundTrip) {
    ImageRGBA8 image{3, 2, {}};
    for (int i = 0; i < 24; ++i) image.pixels.push_back(static_cast<std::uint8_t>(i * 10));
    const fs::path path = tempFile("rgba.png");
    writePng(path, image);
    const ImageRGBA8 back = readPng(path);
    fs::remove(path);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.pixels, image.pixels);
}

TEST(Image, Gray16RoundTripKeepsAllSixteenBits) {
    ImageGray16 image{4, 2, {0, 1, 255, 256, 4095, 32768, 65534, 65535}};
    const fs::path path = tempFile("gray16.png");
    writePng16(path, image);
    const ImageGray16 back = readPng16(path);
    fs::remove(path);
    EXPECT_EQ(back.width, 4);
    EXPECT_EQ(back.pixels, image.pixels);
}

TEST(Image, MissingDirectoryFailsWithoutWritingAnything) {
    const fs::path path = fs::temp_directory_path() / "shadowlab-no-such-dir" / "out.png";
    try {
        writePng(path, ImageRGBA8{1, 1, {1, 2, 3, 4}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path));
}

TEST(Image, InconsistentImageIsRefused) {
    const fs::path path = tempFile("bad.png");
    EXPECT_THROW(writePng(path, ImageRGBA8{2, 2, {1, 2, 3}}), Error);
    EXPECT_FALSE(fs::exists(path));
}
