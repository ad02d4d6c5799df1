// pipeline/report_images.cpp — the report's pictures (see report_images.hpp).
#include "pipeline/report_images.hpp"

#include <algorithm>

namespace gsdot3::pipeline::report_images {

image rgb_image(int w, int h, const std::vector<std::uint32_t>& words) {
  image img{w, h, 3, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3)};
  for (std::size_t i = 0; i < words.size(); ++i)
    for (int c = 0; c < 3; ++c)
      img.data[3 * i + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(words[i] >> (8 * c));
  return img;
}

image grey_image(int w, int h, const std::vector<std::uint8_t>& bytes) { return {w, h, 1, bytes}; }

std::vector<std::uint8_t> reference_bytes(const std::vector<float>& ref) {
  std::vector<std::uint8_t> b(ref.size(), 128);
  for (std::size_t i = 0; i < ref.size(); ++i)
    if (!std::isnan(ref[i])) b[i] = static_cast<std::uint8_t>(std::clamp(std::lround(ref[i]) + 128, 0L, 255L));
  return b;
}

std::array<std::uint8_t, 3> heat(double e, double limit) {
  const double t = std::clamp(std::fabs(e) / limit, 0.0, 1.0);
  const auto fade = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - t)));
  return e >= 0 ? std::array<std::uint8_t, 3>{255, fade, fade} : std::array<std::uint8_t, 3>{fade, fade, 255};
}

image montage(const image& a, const image& b, const image& c, const image& d) {
  const int w = a.width, h = a.height;
  image m{2 * w, 2 * h, 3, std::vector<std::uint8_t>(static_cast<std::size_t>(4 * w * h) * 3)};
  const image* parts[4] = {&a, &b, &c, &d};
  for (int p = 0; p < 4; ++p)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int k = 0; k < 3; ++k)
          m.data[(static_cast<std::size_t>((p / 2) * h + y) * static_cast<std::size_t>(2 * w) +
                  static_cast<std::size_t>((p % 2) * w + x)) *
                     3 +
                 static_cast<std::size_t>(k)] =
              parts[p]
                  ->data[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3 +
                         static_cast<std::size_t>(k)];
  return m;
}

}  // namespace gsdot3::pipeline::report_images
