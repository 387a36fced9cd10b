#include <shadowlab/Image.h>

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <png.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <memory>
#include <string>
#include <string_view>
#include <system_error>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

void requireSize(const fs::path& path, int width, int height, std::size_t pixels, std::size_t channels) {
    if (width <= 0 || height <= 0 || pixels != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * channels)
        throw Error(path.string() + ": cannot write an empty or inconsistent image");
}

// An 8-bit PNG of `channels` channels, encoded in memory and written whole.
void writeStbPng(const fs::path& path, int width, int height, int channels, const std::uint8_t* pixels) {
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, width, height, channels, pixels, width * channels))
        throw Error(path.string() + ": cannot write PNG (cannot encode it)");
    writeFileAtomically(path, bytes);
}

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}
void flushNothing(png_structp) {}

} // namespace

void writePng(const fs::path& path, const ImageRGBA8& image) {
    requireSize(path, image.width, image.height, image.pixels.size(), 4);
    writeStbPng(path, image.width, image.height, 4, image.pixels.data());
}

void writePng(const fs::path& path, const ImageGray8& image) {
    requireSize(path, image.width, image.height, image.pixels.size(), 1);
    writeStbPng(path, image.width, image.height, 1, image.pixels.data());
}

void writePng16(const fs::path& path, const ImageGray16& image) {
    requireSize(path, image.width, image.height, image.pixels.size(), 1);
    std::string bytes;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    volatile bool ok = png && info;
    if (ok && setjmp(png_jmpbuf(png)) == 0) {
        png_set_write_fn(png, &bytes, &appendBytes, &flushNothing);
        png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 16,
                     PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        png_set_swap(png); // PNG stores 16-bit samples big-endian
        for (int y = 0; y < image.height; ++y)
            png_write_row(png, reinterpret_cast<png_const_bytep>(&image.pixels[static_cast<std::size_t>(y) * image.width]));
        png_write_end(png, nullptr);
    } else {
        ok = false;
    }
    png_destroy_write_struct(&png, &info);
    if (!ok) throw Error(path.string() + ": cannot write 16-bit PNG (cannot encode it)");
    writeFileAtomically(path, bytes);
}

ImageRGBA8 readPng(const fs::path& path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
    if (!data) throw Error(path.string() + ": cannot read image (" + std::string(stbi_failure_reason()) + ")");
    ImageRGBA8 image{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 4)};
    stbi_image_free(data);
    return image;
}

ImageGray16 readPng16(const fs::path& path) {
    int w = 0, h = 0, channels = 0;
    stbi_us* data = stbi_load_16(path.string().c_str(), &w, &h, &channels, 1);
    if (!data) throw Error(path.string() + ": cannot read 16-bit image (" + std::string(stbi_failure_reason()) + ")");
    ImageGray16 image{w, h, std::vector<std::uint16_t>(data, data + static_cast<std::size_t>(w) * h)};
    stbi_image_free(data);
    return image;
}

} // namespace shadowlab
