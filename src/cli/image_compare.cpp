// cli/image_compare.cpp — the per-pixel comparison of two PNG frames (see image_compare.hpp).
#include "image_compare.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <png.h>

#include "commands.hpp"
#include "pipeline/files.hpp"
#include "pipeline/image_io.hpp"

namespace gsdot3::cli {
namespace {

struct rgba_image {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> px;  // RGBA, rows top first
};

// The header of FILE read (libpng's simplified API), its size checked as the image loaders check it.
png_image begin_read(const std::string& file) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, file.c_str())) throw usage_error(file + ": " + img.message);
  try {
    pipeline::check_image_size(img.width, img.height, file);
  } catch (const std::runtime_error& e) {
    png_image_free(&img);
    throw usage_error(e.what());
  }
  return img;
}

// Any PNG, converted to 8-bit RGBA.
rgba_image read_rgba(const std::string& file) {
  png_image img = begin_read(file);
  img.format = PNG_FORMAT_RGBA;
  rgba_image out;
  out.width = img.width;
  out.height = img.height;
  out.px.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.px.data(), 0, nullptr)) {
    const std::string msg = img.message;
    png_image_free(&img);
    throw usage_error(file + ": " + msg);
  }
  return out;
}

std::string hex_pixel(const std::uint8_t* p) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%02x%02x%02x%02x", p[0], p[1], p[2], p[3]);
  return buf;
}

}  // namespace

void check_png(const std::string& option, const std::string& file) {
  try {
    png_image img = begin_read(file);
    png_image_free(&img);
  } catch (const usage_error& e) { throw usage_error(option + ": " + e.what()); }
}

std::uint64_t compare_pngs(const std::string& file_a, const std::string& file_b, const std::string& heat_file,
                           int first_n, std::ostream& out) {
  if (first_n < 0) throw usage_error("--first: must be >= 0");
  const rgba_image a = read_rgba(file_a), b = read_rgba(file_b);
  if (a.width != b.width || a.height != b.height)
    throw usage_error("sizes differ: " + file_a + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                      ", " + file_b + " is " + std::to_string(b.width) + "x" + std::to_string(b.height));
  const std::uint64_t n = std::uint64_t{a.width} * a.height;
  std::uint64_t differ = 0;
  std::array<std::uint64_t, 4> per_channel{}, max_diff{};
  std::array<std::uint64_t, 8> histogram{};  // max channel |difference| in [1], [2,3], [4,7], … [128,255]
  pipeline::image heat{static_cast<int>(a.width), static_cast<int>(a.height), 3, std::vector<std::uint8_t>(3 * n)};
  std::vector<std::string> first;
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint8_t* pa = &a.px[4 * i];
    const std::uint8_t* pb = &b.px[4 * i];
    int worst = 0;
    for (int c = 0; c < 4; ++c) {
      const int d = std::abs(int{pa[c]} - int{pb[c]});
      if (d != 0) ++per_channel[c];
      max_diff[c] = std::max<std::uint64_t>(max_diff[c], static_cast<std::uint64_t>(d));
      worst = std::max(worst, d);
    }
    // Heat map: equal pixels as A's luma at a quarter, differing ones red from 128 (difference 1) to 255.
    const auto luma = static_cast<std::uint8_t>((54 * pa[0] + 183 * pa[1] + 19 * pa[2]) / 256 / 4);
    std::uint8_t* h = &heat.data[3 * i];
    h[0] = h[1] = h[2] = luma;
    if (worst == 0) continue;
    ++differ;
    int bucket = 0;
    while ((2 << bucket) <= worst) ++bucket;
    ++histogram[static_cast<std::size_t>(bucket)];
    h[0] = static_cast<std::uint8_t>(128 + worst / 2);
    h[1] = h[2] = 0;
    if (first.size() < static_cast<std::size_t>(first_n))
      first.push_back("  (" + std::to_string(i % a.width) + ", " + std::to_string(i / a.width) + "): " + hex_pixel(pa) +
                      " " + hex_pixel(pb));
  }
  out << "size " << a.width << "x" << a.height << "\n"
      << "differing pixels " << differ << " of " << n << "\n"
      << "channels differing R " << per_channel[0] << ", G " << per_channel[1] << ", B " << per_channel[2] << ", A "
      << per_channel[3] << "\n"
      << "max difference R " << max_diff[0] << ", G " << max_diff[1] << ", B " << max_diff[2] << ", A " << max_diff[3]
      << "\n"
      << "largest channel difference: 1: " << histogram[0];
  for (int k = 1; k < 8; ++k)
    out << ", " << (1 << k) << "-" << ((2 << k) - 1) << ": " << histogram[static_cast<std::size_t>(k)];
  out << "\n";
  if (!first.empty()) {
    out << "first differing pixels (x, y): A B as 0xRRGGBBAA\n";
    for (const auto& line : first) out << line << "\n";
  }
  if (!heat_file.empty()) {
    try {
      pipeline::write_png(heat_file, heat);
    } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
    out << "heat map " << heat_file << "\n";
  }
  return differ;
}

}  // namespace gsdot3::cli
