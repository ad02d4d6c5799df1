// pipeline/png_read.hpp — any 8-bit PNG (grey, grey+alpha, RGB, RGBA, palette; any size) as RGBA8,
// for the image tools (gsdot3 ssbump). 16-bit PNGs are refused rather than converted. Failures throw
// std::runtime_error with a one-line message naming the file. (A TGA/JPEG reader would return the
// same struct; Source's own tools read TGA.)
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace gsdot3::pipeline {

struct rgba_image {
  int width = 0, height = 0;
  bool has_alpha = false;  // the file had an alpha channel (or a tRNS chunk)
  bool grey = false;       // the file was grey (R = G = B)
  std::vector<std::uint8_t> rgba;  // width·height·4, rows top first
};
rgba_image read_png_rgba(const std::filesystem::path& file);

}  // namespace gsdot3::pipeline
