#include <shadowlab/ImageTexture.h>

#include "gl/Object.h"

#include <shadowlab/Error.h>

#include <string>

namespace shadowlab {

struct ImageTexture::Impl {
    gl::Texture texture{GL_TEXTURE_2D};
};

ImageTexture::ImageTexture() noexcept = default;

ImageTexture::ImageTexture(const ImageRGBA8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
        throw Error("ImageTexture: image of " + std::to_string(image.width) + "x" + std::to_string(image.height) + " with " +
                    std::to_string(image.pixels.size()) + " bytes (expected width, height > 0 and width*height*4 bytes)");
    impl_ = std::make_unique<Impl>();
    const GLuint id = impl_->texture.id();
    glTextureStorage2D(id, 1, GL_RGBA8, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(id, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4); // GL's default, as the renderer expects
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
}

ImageTexture::~ImageTexture() = default;
ImageTexture::ImageTexture(ImageTexture&&) noexcept = default;
ImageTexture& ImageTexture::operator=(ImageTexture&&) noexcept = default;

unsigned ImageTexture::id() const noexcept { return impl_ ? impl_->texture.id() : 0; }

} // namespace shadowlab
