#pragma once
// Images in linear RGB, their conversion to 8-bit sRGB, and the cost heat map's colour scale.
#include "raystep/base/file_write.h"
#include "raystep/base/math.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;  // row-major, top row first
    Image() = default;
    Image(int w, int h)
        : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, Color(0.0)) {}
    Color& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const Color& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Linear [0, 1] -> sRGB-encoded 8-bit value (values outside are clamped).
std::uint8_t linearToSrgb8(double v);

/// 8-bit RGB bytes (sRGB), row-major, for PNG.
std::vector<std::uint8_t> toSrgb8(const Image& image);

/// Heat map of per-pixel cost: `cost` (width*height values) mapped linearly from 0 to its
/// maximum onto a perceptually ordered scale (black-purple-orange-yellow), as RGB bytes.
std::vector<std::uint8_t> heatmapRgb8(const std::vector<std::uint64_t>& cost, int width,
                                      int height);

/// The colour scale itself at s in [0, 1] (exposed for the legend and for tests).
std::array<std::uint8_t, 3> heatmapColor(double s);

/// RGB bytes encoded as a PNG file's bytes. Throws std::runtime_error naming `path` on failure.
std::string encodePng(const std::string& path, const std::vector<std::uint8_t>& rgb, int width,
                      int height);

/// Encodes RGB bytes as PNG and writes the file atomically (a temporary file renamed into place,
/// so a reader never sees half a file). Throws std::runtime_error naming the path on failure.
void writePng(const std::string& path, const std::vector<std::uint8_t>& rgb, int width, int height);

}  // namespace raystep
