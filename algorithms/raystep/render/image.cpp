#include "raystep/render/image.h"

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace raystep {

std::uint8_t linearToSrgb8(double v) {
    if (!(v > 0.0)) return 0;  // also maps NaN to black
    if (v >= 1.0) return 255;
    const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

std::vector<std::uint8_t> toSrgb8(const Image& image) {
    std::vector<std::uint8_t> out(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        out[3 * i + 0] = linearToSrgb8(image.pixels[i].r);
        out[3 * i + 1] = linearToSrgb8(image.pixels[i].g);
        out[3 * i + 2] = linearToSrgb8(image.pixels[i].b);
    }
    return out;
}

std::array<std::uint8_t, 3> heatmapColor(double s) {
    // Control points of a black-body-like scale (dark = cheap, bright = expensive).
    static constexpr double kStops[5][3] = {
        {0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
    s = std::clamp(std::isnan(s) ? 0.0 : s, 0.0, 1.0);
    const double f = s * 4.0;
    const int i = std::min(3, static_cast<int>(f));
    const double w = f - i;
    std::array<std::uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] =
            static_cast<std::uint8_t>(std::lround(kStops[i][k] * (1 - w) + kStops[i + 1][k] * w));
    return c;
}

std::vector<std::uint8_t> heatmapRgb8(const std::vector<std::uint64_t>& cost, int width,
                                      int height) {
    std::uint64_t maxCost = 0;
    for (auto c : cost) maxCost = std::max(maxCost, c);
    std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * height * 3);
    for (std::size_t i = 0; i < out.size() / 3; ++i) {
        const double s =
            maxCost ? static_cast<double>(cost[i]) / static_cast<double>(maxCost) : 0.0;
        const auto c = heatmapColor(s);
        std::memcpy(&out[3 * i], c.data(), 3);
    }
    return out;
}

std::string encodePng(const std::string& path, const std::vector<std::uint8_t>& rgb, int width,
                      int height) {
    std::string png;
    const auto append = [](void* ctx, void* data, int size) {
        static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size);
    };
    if (!stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3))
        throw std::runtime_error(path + ": PNG encoding failed");
    return png;
}

void writePng(const std::string& path, const std::vector<std::uint8_t>& rgb, int width,
              int height) {
    writeFileAtomic(path, encodePng(path, rgb, width, height));
}

}  // namespace raystep
