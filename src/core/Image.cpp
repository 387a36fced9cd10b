#include <shadowlab/Image.h>

#include <shadowlab/Error.h>

#include <png.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <cstdio>
#include <memory>
#include <system_error>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

fs::path temporaryBeside(const fs::path& path) {
    fs::path tmp = path;
    tmp += ".partial";
    return tmp;
}

void commit(const fs::path& tmp, const fs::path& path) {
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored; // removing the temporary must not overwrite the rename's error
        fs::remove(tmp, ignored);
        throw Error(path.string() + ": cannot write (" + ec.message() + ")");
    }
}

void requireDirectory(const fs::path& path) {
    const fs::path dir = path.parent_path();
    std::error_code ec;
    if (!dir.empty() && !fs::is_directory(dir, ec))
        throw Error(path.string() + ": cannot write (directory " + dir.string() + (ec ? ": " + ec.message() : " does not exist") + ")");
}

} // namespace

void writePng(const fs::path& path, const ImageRGBA8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw Error(path.string() + ": cannot write an empty or inconsistent image");
    requireDirectory(path);
    const fs::path tmp = temporaryBeside(path);
    if (!stbi_write_png(tmp.string().c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4)) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw Error(path.string() + ": cannot write PNG");
    }
    commit(tmp, path);
}

void writePng(const fs::path& path, const ImageGray8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error(path.string() + ": cannot write an empty or inconsistent image");
    requireDirectory(path);
    const fs::path tmp = temporaryBeside(path);
    if (!stbi_write_png(tmp.string().c_str(), image.width, image.height, 1, image.pixels.data(), image.width)) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw Error(path.string() + ": cannot write PNG");
    }
    commit(tmp, path);
}

void writePng16(const fs::path& path, const ImageGray16& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error(path.string() + ": cannot write an empty or inconsistent image");
    requireDirectory(path);
    const fs::path tmp = temporaryBeside(path);
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(tmp.string().c_str(), "wb"), &std::fclose);
    if (!file) throw Error(path.string() + ": cannot open for writing");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    volatile bool ok = png && info;
    if (ok && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, file.get());
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
    file.reset();
    if (!ok) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw Error(path.string() + ": cannot write 16-bit PNG");
    }
    commit(tmp, path);
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
