// pipeline/png_io.cpp — height-map PNGs (decoded by image_io.cpp) and libpng writing of report images.
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <png.h>

#include "pipeline/files.hpp"
#include "pipeline/image_io.hpp"
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

void on_png_error(png_structp png, png_const_charp) { longjmp(png_jmpbuf(png), 1); }
void on_png_warning(png_structp, png_const_charp) {}

}  // namespace

normal_map load_height_map_png(const std::filesystem::path& file, float strength) {
  const image img = read_texture_image_png(file, true);
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
    for (int y = 0; y < img.height; ++y) png_write_row(png, img.data.data() + stride * static_cast<std::size_t>(y));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fflush(f.get()) != 0) fail(tmp, "write failed");
  }
  std::filesystem::rename(tmp, file);
}

image read_texture_image_png(const std::filesystem::path& file, bool grey) {
  const std::string what = grey ? "height map" : "normal map";
  const std::vector<std::uint8_t> bytes = read_file_bytes(file, what);
  const image img = decode_png(bytes.data(), bytes.size(), file.string());
  auto power_of_two = [](int v) { return v >= 8 && v <= 1024 && (v & (v - 1)) == 0; };
  if (!power_of_two(img.width) || !power_of_two(img.height))
    fail(file, what + " is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                   "; width and height must be powers of two from 8 to 1024");
  if (!grey && img.channels != 3) fail(file, "the normal map must be an RGB image, not grey");
  if (grey && img.channels != 1) fail(file, "the height map must be a grey image, not colour");
  return img;
}

}  // namespace gsdot3::pipeline
