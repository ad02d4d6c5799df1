// pipeline/image_io.hpp — decoding user images from memory: PNG through libpng, JPEG through
// libjpeg-turbo, TGA through stb_image (Debian's libstb-dev). Every failure throws std::runtime_error "NAME: why" (one
// line); images larger than max_image_side on a side or max_image_pixels in all are refused from
// their header, before any pixel is decoded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/files.hpp"

namespace gsdot3::pipeline {

inline constexpr int max_image_side = 16384;
inline constexpr long long max_image_pixels = 1LL << 24;  // 4096², 64 MiB as RGBA

// Throws "NAME: the image is WxH; ..." unless both sides are 1..max_image_side and the area is at
// most max_image_pixels.
void check_image_size(long long width, long long height, const std::string& name);

// The whole file; `what` names it in the message ("cannot open the normal map").
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file, const std::string& what);

// 8-bit grey (1 channel) or RGB (3 channels): palettes expanded, 16-bit reduced to 8, alpha dropped.
// `format` receives "PNG", "JPEG" or "TGA".
image decode_image(const std::uint8_t* data, std::size_t size, const std::string& name, std::string& format);
image decode_png(const std::uint8_t* data, std::size_t size, const std::string& name);
image decode_jpeg(const std::uint8_t* data, std::size_t size, const std::string& name);
image decode_tga(const std::uint8_t* data, std::size_t size, const std::string& name);
// A BMP through stb_image, always as RGB (3 channels).
image decode_bmp(const std::uint8_t* data, std::size_t size, const std::string& name);

// Any PNG as RGBA8 for the image tools (gsdot3 ssbump: the height from alpha, as Source's tools
// read it): the same reader as decode_png (palettes expanded, 16-bit reduced to 8, the same size
// limits), grey expanded to RGB, alpha 255 where the file has none.
struct rgba_image {
  int width = 0, height = 0;
  bool has_alpha = false;          // the file had an alpha channel (or a tRNS chunk)
  bool grey = false;               // the file was grey (R = G = B)
  std::vector<std::uint8_t> rgba;  // width·height·4, rows top first
};
rgba_image decode_png_rgba(const std::uint8_t* data, std::size_t size, const std::string& name);
rgba_image read_png_rgba(const std::filesystem::path& file);  // the file's bytes through decode_png_rgba

}  // namespace gsdot3::pipeline
