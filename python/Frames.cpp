// The Python module's frames (Module.h): the frame, a light's visibility
// as its technique computes it, and the techniques' debug images.
#include "Module.h"

#include <cstring>

namespace shadowlab::python {

// The frame as the CLI writes it: RGBA bytes, top row first.
py::array_t<std::uint8_t> render(const PyScene& s, int width, int height, double time) {
    ImageRGBA8 image;
    drawn(s, width, height, time, [&](Renderer& renderer, const Scene& at) {
        renderer.render(at, frameOptions(width, height, time));
        image = renderer.readColor();
    });
    return rgba(std::move(image));
}

namespace {

// A frame's visibility for one light (per channel) and its debug images.
struct Frame {
    std::vector<glm::vec3> visibility;
    std::vector<DebugImage> images;
};

Frame frameOf(const PyScene& s, int width, int height, double time, int light, bool images) {
    if (light >= 0 && static_cast<std::size_t>(light) >= s.scene->lights.size())
        throw InputFailure("light " + std::to_string(light) + ": the scene has " + std::to_string(s.scene->lights.size()) + " light(s)");
    Frame f;
    drawn(s, width, height, time, [&](Renderer& renderer, const Scene& at) {
        renderer.render(at, frameOptions(width, height, time));
        if (light >= 0) f.visibility = renderer.readVisibilityRgb(at, static_cast<std::size_t>(light));
        if (images) f.images = renderer.debugImages(at);
    });
    return f;
}

} // namespace

// Light `light`'s visibility as its technique computes it in the frame
// (1 lit, 0 shadowed, 0 on the background), HxW float32, or HxWx3 with
// `coloured` (transmittance through translucent casters).
py::array_t<float> visibility(const PyScene& s, int light, int width, int height, bool coloured, double time) {
    if (light < 0) throw InputFailure("light " + std::to_string(light) + ": expected an index from 0");
    const Frame f = frameOf(s, width, height, time, light, false);
    if (coloured) {
        py::array_t<float> out({height, width, 3});
        std::memcpy(out.mutable_data(), f.visibility.data(), f.visibility.size() * sizeof(glm::vec3));
        return out;
    }
    py::array_t<float> out({height, width});
    float* d = out.mutable_data();
    for (std::size_t i = 0; i < f.visibility.size(); ++i) d[i] = (f.visibility[i].r + f.visibility[i].g + f.visibility[i].b) / 3.0f;
    return out;
}

// The techniques' debug images as {name: HxWx4 uint8}.
py::dict debugImages(const PyScene& s, int width, int height, double time) {
    const Frame f = frameOf(s, width, height, time, -1, true);
    py::dict out;
    for (const DebugImage& d : f.images) out[py::str(d.name)] = rgba(d.image);
    return out;
}

} // namespace shadowlab::python
