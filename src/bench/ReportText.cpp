// report.html's text (ReportText.h).
#include "bench/ReportText.h"

#include "core/Base64.h"

#include <shadowlab/Error.h>
#include <shadowlab/Image.h>

#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace shadowlab::bench {

namespace fs = std::filesystem;
using nlohmann::json;

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string thumbnailUri(const fs::path& file, int width, bool photo) {
    ImageRGBA8 image;
    try {
        image = readPng(file);
    } catch (const Error& e) {
        throw Error(file.string() + ": cannot read image for the report (" + e.what() + ")");
    }
    // Averaged down by a whole factor, so each thumbnail pixel is a box of the image's.
    const int step = std::max(1, (image.width + width - 1) / std::max(width, 1));
    ImageRGBA8 small;
    small.width = std::max(1, image.width / step);
    small.height = std::max(1, image.height / step);
    small.pixels.assign(static_cast<std::size_t>(small.width) * small.height * 4, 0);
    for (int y = 0; y < small.height; ++y)
        for (int x = 0; x < small.width; ++x)
            for (int c = 0; c < 4; ++c) {
                unsigned sum = 0, n = 0;
                for (int dy = 0; dy < step && y * step + dy < image.height; ++dy)
                    for (int dx = 0; dx < step && x * step + dx < image.width; ++dx, ++n)
                        sum += image.pixels[(static_cast<std::size_t>(y * step + dy) * image.width + (x * step + dx)) * 4 + c];
                small.pixels[(static_cast<std::size_t>(y) * small.width + x) * 4 + c] = static_cast<std::uint8_t>((sum + n / 2) / std::max(n, 1u));
            }
    std::string bytes;
    const auto append = [](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<const char*>(data), size); };
    const bool ok = photo ? stbi_write_jpg_to_func(append, &bytes, small.width, small.height, 4, small.pixels.data(), 85) != 0
                          : stbi_write_png_to_func(append, &bytes, small.width, small.height, 4, small.pixels.data(), small.width * 4) != 0;
    if (!ok) throw Error(file.string() + ": cannot encode its thumbnail for the report");
    return std::string(photo ? "data:image/jpeg;base64," : "data:image/png;base64,") + base64(bytes);
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

std::string percent(double share) { return fixed(100.0 * share, 3); }

std::string settingsText(const json& record) {
    std::string out;
    for (const auto& [key, value] : record["settings"].items()) out += (out.empty() ? "" : ", ") + key + "=" + value.get<std::string>();
    return out.empty() ? "defaults" : out;
}

} // namespace shadowlab::bench
