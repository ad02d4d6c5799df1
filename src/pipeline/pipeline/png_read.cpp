// pipeline/png_read.cpp — libpng's simplified reading API (png_image), 8-bit only.
#include "pipeline/png_read.hpp"

#include <stdexcept>
#include <string>

#include <png.h>

namespace gsdot3::pipeline {

rgba_image read_png_rgba(const std::filesystem::path& file) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  auto fail = [&](const std::string& what) {
    png_image_free(&img);
    throw std::runtime_error(file.string() + ": " + what);
  };
  if (!std::filesystem::is_regular_file(file)) fail("cannot open the image");
  if (!png_image_begin_read_from_file(&img, file.c_str())) fail(std::string("not a readable PNG (") + img.message + ")");
  if (img.format & PNG_FORMAT_FLAG_LINEAR) fail("16-bit PNGs are not supported; save it with 8 bits per channel");
  if (img.width == 0 || img.height == 0 || img.width > 16384 || img.height > 16384)
    fail("image is " + std::to_string(img.width) + "x" + std::to_string(img.height) + "; sides must be 1..16384");
  rgba_image out;
  out.width = static_cast<int>(img.width);
  out.height = static_cast<int>(img.height);
  out.has_alpha = (img.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  out.grey = (img.format & PNG_FORMAT_FLAG_COLOR) == 0;
  img.format = PNG_FORMAT_RGBA;
  out.rgba.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.rgba.data(), 0, nullptr)) fail(std::string("malformed PNG data (") + img.message + ")");
  png_image_free(&img);
  return out;
}

}  // namespace gsdot3::pipeline
