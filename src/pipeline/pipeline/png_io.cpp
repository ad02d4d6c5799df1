// pipeline/png_io.cpp — libpng reading of normal maps and writing of report images.
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <png.h>

#include "pipeline/files.hpp"
#include "pipeline/normal_map.hpp"

namespace gsdot3::pipeline {

namespace {

struct file_closer {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using file_ptr = std::unique_ptr<std::FILE, file_closer>;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error(file.string() + ": " + what);
}

bool power_of_two_texture(png_uint_32 v) { return v >= 8 && v <= 1024 && (v & (v - 1)) == 0; }

void on_png_error(png_structp png, png_const_charp) { longjmp(png_jmpbuf(png), 1); }
void on_png_warning(png_structp, png_const_charp) {}

}  // namespace

namespace {

// An 8-bit PNG with power-of-two sides (a GS texture), as grey (1 channel) or RGB (3 channels, alpha
// stripped); `what` names it in messages.
image read_texture_png(const std::filesystem::path& file, const std::string& what, bool grey) {
  file_ptr f(std::fopen(file.c_str(), "rb"));
  if (!f) fail(file, "cannot open the " + what);
  png_byte sig[8];
  if (std::fread(sig, 1, 8, f.get()) != 8 || png_sig_cmp(sig, 0, 8) != 0) fail(file, "not a PNG file");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, on_png_error, on_png_warning);
  png_infop info = png_create_info_struct(png);
  // Everything longjmp may skip over is constructed before setjmp, so its destructor still runs.
  image img;
  std::vector<png_byte> row;
  volatile png_uint_32 w = 0, h = 0;
  volatile int problem = 0;  // 1: size, 2: format
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    fail(file, "malformed PNG data");
  }
  png_init_io(png, f.get());
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  w = png_get_image_width(png, info);
  h = png_get_image_height(png, info);
  const int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
  const bool rgb = type == PNG_COLOR_TYPE_RGB || type == PNG_COLOR_TYPE_RGB_ALPHA;
  const bool gray = type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA;
  if (!power_of_two_texture(w) || !power_of_two_texture(h)) {
    problem = 1;
  } else if (depth != 8 || !(rgb || (grey && gray))) {
    problem = 2;
  } else {
    if (type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    png_read_update_info(png, info);
    img = {static_cast<int>(w), static_cast<int>(h), rgb ? 3 : 1, {}};
    row.resize(png_get_rowbytes(png, info));
    img.data.reserve(static_cast<std::size_t>(w) * h * static_cast<std::size_t>(img.channels));
    for (png_uint_32 y = 0; y < h; ++y) {
      png_read_row(png, row.data(), nullptr);
      img.data.insert(img.data.end(), row.begin(), row.begin() + static_cast<std::ptrdiff_t>(w * static_cast<png_uint_32>(img.channels)));
    }
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (problem == 1)
    fail(file, what + " is " + std::to_string(static_cast<png_uint_32>(w)) + "x" + std::to_string(static_cast<png_uint_32>(h)) +
                   "; width and height must be powers of two from 8 to 1024");
  if (problem == 2)
    fail(file, "the " + what + " must be 8-bit " + (grey ? "grey or RGB" : "RGB or RGBA") + " (bit depth " +
                   std::to_string(depth) + ", colour type " + std::to_string(type) + ")");
  return img;
}

}  // namespace

normal_map load_normal_map_png(const std::filesystem::path& file) {
  const image img = read_texture_png(file, "normal map", false);
  std::vector<glm::vec3> normals;
  normals.reserve(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
  for (std::size_t i = 0; i < img.data.size(); i += 3) {
    const glm::vec3 n{img.data[i] / 127.5f - 1.0f, img.data[i + 1] / 127.5f - 1.0f, img.data[i + 2] / 127.5f - 1.0f};
    normals.push_back(glm::length(n) > 1e-3f ? glm::normalize(n) : glm::vec3(0, 0, 1));
  }
  return quantise(normals, img.width, img.height, 256);
}

normal_map load_height_map_png(const std::filesystem::path& file, float strength) {
  const image img = read_texture_png(file, "height map", true);
  std::vector<float> h;
  h.reserve(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
  for (std::size_t i = 0; i < img.data.size(); i += static_cast<std::size_t>(img.channels)) h.push_back(img.data[i]);
  return quantise(normals_from_height(h, img.width, img.height, strength), img.width, img.height, 256);
}

void write_png(const std::filesystem::path& file, const image& img) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    file_ptr f(std::fopen(tmp.c_str(), "wb"));
    if (!f) fail(tmp, "cannot write");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_png_error, on_png_warning);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
      png_destroy_write_struct(&png, &info);
      f.reset();
      std::filesystem::remove(tmp);
      fail(file, "PNG encoding failed");
    }
    png_init_io(png, f.get());
    png_set_IHDR(png, info, static_cast<png_uint_32>(img.width), static_cast<png_uint_32>(img.height), 8,
                 img.channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    const std::size_t stride = static_cast<std::size_t>(img.width) * img.channels;
    for (int y = 0; y < img.height; ++y)
      png_write_row(png, img.data.data() + stride * static_cast<std::size_t>(y));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fflush(f.get()) != 0) fail(tmp, "write failed");
  }
  std::filesystem::rename(tmp, file);
}

image read_texture_image_png(const std::filesystem::path& file, bool grey) {
  return read_texture_png(file, grey ? "height map" : "normal map", grey);
}

}  // namespace gsdot3::pipeline
