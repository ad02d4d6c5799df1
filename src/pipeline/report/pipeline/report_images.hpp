// pipeline/report_images.hpp — the report's pictures: frames as PNG-ready images, the float dot
// products as the byte a DPB would hold, the signed-error heat map with its legend, the 2×2 montage.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pipeline/files.hpp"

namespace gsdot3::pipeline::report_images {

// A frame's 32-bit words (A8B8G8R8, R low) as an RGB image.
image rgb_image(int w, int h, const std::vector<std::uint32_t>& words);
// One byte per pixel as a grey image.
image grey_image(int w, int h, const std::vector<std::uint8_t>& bytes);

// Float dot products (the reference's, a scheme's) as the byte a DPB would hold: nearest(dot) + 128,
// clamped to 0..255.
std::vector<std::uint8_t> reference_bytes(const std::vector<float>& ref);

// Heat-map colour of a signed error: white at 0, red for positive, blue for negative, saturated at ±limit.
std::array<std::uint8_t, 3> heat(double e, double limit);

constexpr double heat_limit = 8.0;  // 1/128 units at full saturation
constexpr int legend_rows = 20;

// The error map of one light, plus a legend strip under it: −limit .. +limit left to right, with a
// dark tick at every whole unit and a long one at 0.
// `value(i)` is the method's dot product at pixel i, in 1/128 units.
template <class Value>
image error_map(int w, int h, Value&& value, const std::vector<float>& ref) {
  image img{
      w, h + legend_rows, 3,
      std::vector<std::uint8_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h + legend_rows) * 3, 0x30)};
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (std::isnan(ref[i])) continue;
    const auto c = heat(value(i) - ref[i], heat_limit);
    for (int k = 0; k < 3; ++k) img.data[3 * i + static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k)];
  }
  for (int y = h + 4; y < h + legend_rows; ++y)
    for (int x = 0; x < w; ++x) {
      const double e = (2.0 * x / (w - 1) - 1.0) * heat_limit;
      auto c = heat(e, heat_limit);
      const double unit = std::fabs(e - std::round(e)) * (w - 1) / (2.0 * heat_limit);
      const bool tick = unit < 0.5 && (y < h + 10 || std::lround(e) == 0);
      if (tick) c = {0, 0, 0};
      const std::size_t at =
          (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3;
      for (int k = 0; k < 3; ++k) img.data[at + static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k)];
    }
  return img;
}

// Four frames of equal size in a 2×2 grid: a b / c d (figure 7).
image montage(const image& a, const image& b, const image& c, const image& d);

}  // namespace gsdot3::pipeline::report_images
