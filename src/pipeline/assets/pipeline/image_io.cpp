// pipeline/image_io.cpp — image files to 8-bit pixels: format by signature, PNG by libpng from
// memory, as grey/RGB or as RGBA (JPEG: jpeg_decode.cpp, TGA: stb_decode.cpp).
#include "pipeline/image_io.hpp"

#include <algorithm>
#include <csetjmp>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <utility>

#include <png.h>

namespace gsdot3::pipeline {

void check_image_size(long long width, long long height, const std::string& name) {
  if (width < 1 || height < 1 || width > max_image_side || height > max_image_side || width * height > max_image_pixels)
    throw std::runtime_error(name + ": the image is " + std::to_string(width) + "x" + std::to_string(height) +
                             "; at most " + std::to_string(max_image_side) + " on a side and " +
                             std::to_string(max_image_pixels) + " pixels are read");
}

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || !std::filesystem::is_regular_file(file, ec))
    throw std::runtime_error(file.string() + ": cannot open the " + what);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

namespace {

struct reader {
  const std::uint8_t* data;
  std::size_t size, at = 0;
};

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* r = static_cast<reader*>(png_get_io_ptr(png));
  if (n > r->size - r->at) png_error(png, "truncated");
  std::memcpy(out, r->data + r->at, n);
  r->at += n;
}

void on_error(png_structp png, png_const_charp) { longjmp(png_jmpbuf(png), 1); }
void on_warning(png_structp, png_const_charp) {}

// The one libpng reader: palettes and tRNS expanded, grey below 8 bits to 8, 16-bit reduced to 8,
// then either alpha dropped (grey or RGB) or everything as RGBA (grey to RGB, opaque alpha added).
struct png_pixels {
  image img;
  bool has_alpha = false, grey = false;  // of the file: an alpha channel or a tRNS chunk; no colour
};

png_pixels read_png(const std::uint8_t* data, std::size_t size, const std::string& name, bool rgba) {
  if (size < 8 || png_sig_cmp(data, 0, 8) != 0) throw std::runtime_error(name + ": not a PNG file");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  png_infop info = png_create_info_struct(png);
  // Everything longjmp may skip over is constructed before setjmp, so its destructor still runs.
  reader src{data, size};
  png_pixels out;
  std::vector<png_bytep> rows;
  volatile png_uint_32 w = 0, h = 0;
  volatile bool too_large = false;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(name + ": malformed PNG data");
  }
  png_set_user_limits(png, 0x7fffffff, 0x7fffffff);  // the size is checked below, with a clear message
  png_set_read_fn(png, &src, read_bytes);
  png_read_info(png, info);
  w = png_get_image_width(png, info);
  h = png_get_image_height(png, info);
  const int type = png_get_color_type(png, info);
  out.has_alpha = (type & PNG_COLOR_MASK_ALPHA) != 0 || png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  out.grey = (type & PNG_COLOR_MASK_COLOR) == 0;
  too_large = w > static_cast<png_uint_32>(max_image_side) || h > static_cast<png_uint_32>(max_image_side) ||
              static_cast<long long>(w) * h > max_image_pixels;
  if (!too_large) {
    png_set_expand(png);  // palette to RGB, grey below 8 bits to 8, tRNS to alpha
    png_set_strip_16(png);
    if (rgba) {
      png_set_gray_to_rgb(png);
      png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);  // only where there is no alpha
    } else {
      png_set_strip_alpha(png);
    }
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const int channels = rgba ? 4 : (type & PNG_COLOR_MASK_COLOR) ? 3 : 1;
    out.img = {static_cast<int>(w), static_cast<int>(h), channels,
               std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * static_cast<std::size_t>(channels))};
    if (png_get_rowbytes(png, info) != static_cast<std::size_t>(w) * static_cast<std::size_t>(channels))
      png_error(png, "layout");
    for (png_uint_32 y = 0; y < h; ++y)
      rows.push_back(out.img.data.data() + static_cast<std::size_t>(y) * w * static_cast<std::size_t>(channels));
    png_read_image(png, rows.data());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (too_large) check_image_size(static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), name);
  return out;
}

}  // namespace

image decode_png(const std::uint8_t* data, std::size_t size, const std::string& name) {
  return read_png(data, size, name, false).img;
}

rgba_image decode_png_rgba(const std::uint8_t* data, std::size_t size, const std::string& name) {
  png_pixels p = read_png(data, size, name, true);
  return {p.img.width, p.img.height, p.has_alpha, p.grey, std::move(p.img.data)};
}

rgba_image read_png_rgba(const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(file, "image");
  return decode_png_rgba(bytes.data(), bytes.size(), file.string());
}

image decode_image(const std::uint8_t* data, std::size_t size, const std::string& name, std::string& format) {
  static constexpr std::uint8_t png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size >= 8 && std::equal(png_signature, png_signature + 8, data)) {
    format = "PNG";
    return decode_png(data, size, name);
  }
  if (size >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF) {
    format = "JPEG";
    return decode_jpeg(data, size, name);
  }
  format = "TGA";  // TGA has no signature: the last format tried
  return decode_tga(data, size, name);
}

}  // namespace gsdot3::pipeline
