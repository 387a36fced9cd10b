#pragma once
/// @file Image.h
/// Images in memory and PNG files. Writes go to a temporary file in the
/// same directory that is renamed into place, so a failure never leaves a
/// partial image behind.
#include <shadowlab/Export.h>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace shadowlab {

/// 8-bit RGBA image in memory, rows top to bottom.
struct ImageRGBA8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; ///< width*height*4 bytes
};

/// 16-bit single-channel image, rows top to bottom.
struct ImageGray16 {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> pixels; ///< width*height values
};

/// 8-bit single-channel image, rows top to bottom.
struct ImageGray8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; ///< width*height values
};

/// Writes 8-bit RGBA PNG. Throws shadowlab::Error naming the path on failure.
SHADOWLAB_API void writePng(const std::filesystem::path& path, const ImageRGBA8& image);
/// Writes 8-bit greyscale PNG. Throws shadowlab::Error naming the path on failure.
SHADOWLAB_API void writePng(const std::filesystem::path& path, const ImageGray8& image);
/// Writes 16-bit greyscale PNG (libpng). Throws shadowlab::Error naming the path.
SHADOWLAB_API void writePng16(const std::filesystem::path& path, const ImageGray16& image);
/// Reads any PNG as 8-bit RGBA. Throws shadowlab::Error naming the path.
SHADOWLAB_API ImageRGBA8 readPng(const std::filesystem::path& path);
/// Reads a 16-bit greyscale PNG written by writePng16.
SHADOWLAB_API ImageGray16 readPng16(const std::filesystem::path& path);

} // namespace shadowlab
