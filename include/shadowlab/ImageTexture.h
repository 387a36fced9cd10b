#pragma once
/// @file ImageTexture.h
/// An image uploaded to an OpenGL texture, for an application that draws it
/// itself: the viewer shows debug images and error images in ImGui panels
/// with it (`ImGui::Image(id)`).
#include <shadowlab/Export.h>
#include <shadowlab/Image.h>

#include <memory>

namespace shadowlab {

/// A GL_TEXTURE_2D holding an ImageRGBA8 (GL_RGBA8, one level, linear
/// minification), made in the context current when it is constructed, which
/// must still be current when it is destroyed. Row 0 of the image is texture
/// row 0, so a UI that puts texture coordinate (0, 0) at its top-left corner
/// (ImGui does) shows the image upright. Move-only; an empty texture has id 0.
class SHADOWLAB_API ImageTexture {
public:
    ImageTexture() noexcept;
    /// Uploads `image` (width and height > 0, pixels width*height*4 bytes;
    /// throws Error otherwise).
    explicit ImageTexture(const ImageRGBA8& image);
    ~ImageTexture();
    ImageTexture(ImageTexture&&) noexcept;
    ImageTexture& operator=(ImageTexture&&) noexcept;

    /// The GL texture name, 0 when empty.
    unsigned id() const noexcept;
    explicit operator bool() const noexcept { return id() != 0; }

private:
    struct SHADOWLAB_HIDDEN Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace shadowlab
