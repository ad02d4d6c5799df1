// pipeline/stb_decode.cpp — the one translation unit that compiles stb_image (libstb-dev, a
// single-header library: STB_IMAGE_IMPLEMENTATION goes in exactly one .cpp). Only its TGA and BMP
// decoders are compiled (JPEG: jpeg_decode.cpp; BMP: `gsdot3 probe decode` screenshots);
// <stb/stb_image.h> is found in /usr/include, a system directory, so its own warnings do not trip -Werror.
#include <stdexcept>

#include "pipeline/image_io.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#define STBI_MAX_DIMENSIONS gsdot3::pipeline::max_image_side
#include <stb/stb_image.h>

namespace gsdot3::pipeline {

namespace {

// stb_image fills the texels of a cut RLE stream with zeros (and stops silently at an overrun), so
// a run-length-encoded TGA (image types 9, 10, 11) has its packet stream checked first: the packets
// must cover exactly width × height pixels within the file. Layout (Truevision TGA 2.0 spec): an
// 18-byte header (ID length at 0, colour-map type at 1, image type at 2, colour-map length at 5-6 and
// entry bits at 7, width at 12-13, height at 14-15, pixel bits at 16, little-endian), the ID, the
// colour map, then packets: a byte h, and 1 + (h & 0x7f) pixels, given once if h & 0x80 (a run)
// or one by one (raw).
void check_tga_rle(const std::uint8_t* d, std::size_t size, const std::string& name) {
  if (size < 18 || (d[2] != 9 && d[2] != 10 && d[2] != 11)) return;  // not RLE: stb checks the rest
  auto u16 = [&](std::size_t at) { return static_cast<std::size_t>(d[at]) | static_cast<std::size_t>(d[at + 1]) << 8; };
  const std::size_t map_bytes = d[1] != 0 ? u16(5) * ((static_cast<std::size_t>(d[7]) + 7) / 8) : 0;
  const std::size_t pixel_bytes = (static_cast<std::size_t>(d[16]) + 7) / 8;
  const std::size_t total = u16(12) * u16(14);
  std::size_t at = 18 + d[0] + map_bytes, done = 0;
  while (done < total) {
    if (at >= size)
      throw std::runtime_error(name + ": the TGA's RLE stream ends after " + std::to_string(done) + " of " +
                               std::to_string(total) + " pixels");
    const std::size_t n = 1 + (d[at] & 0x7fu);
    const std::size_t bytes = (d[at] & 0x80u) != 0 ? pixel_bytes : n * pixel_bytes;
    if (done + n > total)
      throw std::runtime_error(name + ": a TGA RLE packet at byte " + std::to_string(at) + " runs past the image's " +
                               std::to_string(total) + " pixels");
    if (at + 1 + bytes > size)
      throw std::runtime_error(name + ": the TGA's RLE stream ends inside the packet at byte " + std::to_string(at));
    at += 1 + bytes;
    done += n;
  }
}

}  // namespace

namespace {

// Decodes through stb_image once the caller has checked the format: grey (+alpha) stays grey, RGB(A)
// becomes RGB (rgb_only: always RGB).
image stb_load(const std::uint8_t* data, std::size_t size, const std::string& name, const char* formats, bool rgb_only,
               void (*check)(const std::uint8_t*, std::size_t, const std::string&)) {
  if (size > 0x7fffffffu) throw std::runtime_error(name + ": the image file is too large");
  const int len = static_cast<int>(size);
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(data, len, &w, &h, &n))
    throw std::runtime_error(name + ": not a " + formats + " image (" + stbi_failure_reason() + ")");
  check_image_size(w, h, name);
  if (check != nullptr) check(data, size, name);
  const int channels = n <= 2 && !rgb_only ? 1 : 3;
  stbi_uc* px = stbi_load_from_memory(data, len, &w, &h, &n, channels);
  if (px == nullptr)
    throw std::runtime_error(name + ": malformed image data (" + std::string(stbi_failure_reason()) + ")");
  image img{w, h, channels,
            std::vector<std::uint8_t>(px, px + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                                                   static_cast<std::size_t>(channels))};
  stbi_image_free(px);
  return img;
}

// stb_image reads an uncompressed BMP cut short as if its missing rows were black, so the pixel data's
// length is checked against the header first (BITMAPFILEHEADER bfOffBits at byte 10; BITMAPINFOHEADER
// width 18, height 22, bit count 28, compression 30; rows padded to 4 bytes).
void check_bmp_length(const std::uint8_t* d, std::size_t size, const std::string& name) {
  if (size < 34) throw std::runtime_error(name + ": the BMP header is cut short");
  auto u32 = [&](std::size_t at) {
    return std::uint32_t{d[at]} | std::uint32_t{d[at + 1]} << 8 | std::uint32_t{d[at + 2]} << 16 |
           std::uint32_t{d[at + 3]} << 24;
  };
  const std::uint32_t compression = u32(30);
  if (compression != 0 && compression != 3) return;  // BI_RGB, BI_BITFIELDS; stb refuses RLE itself
  const long long width = static_cast<std::int32_t>(u32(18)), height = static_cast<std::int32_t>(u32(22));
  const long long bits = d[28] | d[29] << 8;
  const long long need = u32(10) + (height < 0 ? -height : height) * ((width * bits + 31) / 32 * 4);
  if (static_cast<long long>(size) < need)
    throw std::runtime_error(name + ": the BMP's pixel data ends at byte " + std::to_string(size) +
                             ", its header needs " + std::to_string(need));
}

}  // namespace

image decode_tga(const std::uint8_t* data, std::size_t size, const std::string& name) {
  return stb_load(data, size, name, "PNG, JPEG or TGA", false, check_tga_rle);
}

image decode_bmp(const std::uint8_t* data, std::size_t size, const std::string& name) {
  if (size < 2 || data[0] != 'B' || data[1] != 'M') throw std::runtime_error(name + ": not a BMP file");
  return stb_load(data, size, name, "BMP", true, check_bmp_length);
}

}  // namespace gsdot3::pipeline
