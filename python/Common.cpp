// The Python module's shared parts (Module.h): the context, errors named
// as Python names things, images as arrays.
#include "Module.h"

#include <cctype>
#include <cstring>
#include <string_view>

namespace shadowlab::python {

namespace {

struct Gl {
    std::mutex lock;
    std::optional<Context> context;
};
Gl& gl() {
    static Gl g;
    return g;
}

} // namespace

std::mutex& glLock() { return gl().lock; }

Context& contextLocked() {
    Gl& g = gl();
    if (!g.context) {
        try {
            g.context.emplace(Context::createHeadless());
        } catch (const Error& e) {
            throw std::runtime_error(e.what());
        }
    }
    g.context->makeCurrent();
    return *g.context;
}

Released::~Released() {
    if (gl().context) gl().context->releaseCurrent();
}

namespace {

// Every `FLAG KEY=` in `message` as `NAME[KEY]=`.
std::string keyed(std::string message, const std::string& flag, const std::string& name) {
    for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at)) {
        const std::size_t key = at + flag.size(), eq = message.find('=', key);
        if (eq == std::string::npos) break;
        const std::string replacement = name + "[" + message.substr(key, eq - key) + "]";
        message.replace(at, eq - at, replacement);
        at += replacement.size();
    }
    return message;
}

} // namespace

std::string pythonNames(std::string message) {
    message = keyed(keyed(std::move(message), "--set ", "overrides"), "--vary ", "vary");
    // `overrides[K]=V: ...` said first: the key alone, as load_scene names it.
    if (message.rfind("overrides[", 0) == 0) {
        const std::size_t close = message.find("]=");
        const std::size_t colon = close == std::string::npos ? close : message.find(": ", close);
        if (colon != std::string::npos) message = message.substr(0, close + 1) + message.substr(colon);
    }
    // bench's flags as the keyword arguments.
    static const std::pair<std::string_view, std::string_view> flags[] = {
        {"--frames", "frames"}, {"--warmup", "warmup"},        {"--time", "time"},    {"--fps", "fps"},
        {"--flips", "flips"},   {"--samples", "soft_samples"}, {"--width", "width"}, {"--height", "height"}};
    for (const auto& [flag, name] : flags)
        for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at + name.size())) {
            const std::size_t end = at + flag.size();
            if (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-')) {
                at = end - name.size();  // a longer flag (--frames-x): not this one
                continue;
            }
            message.replace(at, flag.size(), name);
        }
    return message;
}

void raiseInput(const Error& e) { throw py::value_error(pythonNames(e.what())); }

py::array_t<std::uint8_t> rgba(const ImageRGBA8& image) {
    py::array_t<std::uint8_t> out({image.height, image.width, 4});
    std::memcpy(out.mutable_data(), image.pixels.data(), image.pixels.size());
    return out;
}

py::array_t<float> unit(const ImageGray16& image) {
    py::array_t<float> out({image.height, image.width});
    float* d = out.mutable_data();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) d[i] = static_cast<float>(image.pixels[i]) / 65535.0f;
    return out;
}

py::array_t<bool> mask(const ImageGray8& image) {
    py::array_t<bool> out({image.height, image.width});
    bool* d = out.mutable_data();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) d[i] = image.pixels[i] != 0;
    return out;
}

RenderOptions frameOptions(int width, int height, double time) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.timeSeconds = time;
    return options;
}

} // namespace shadowlab::python
