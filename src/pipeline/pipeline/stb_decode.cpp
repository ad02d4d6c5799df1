// pipeline/stb_decode.cpp — the one translation unit that compiles stb_image (libstb-dev, a
// single-header library: STB_IMAGE_IMPLEMENTATION goes in exactly one .cpp). Only its TGA decoder
// is compiled (JPEG: jpeg_decode.cpp); <stb/stb_image.h> is found in /usr/include, a system
// directory, so its own warnings do not trip -Werror.
#include <stdexcept>

#include "pipeline/image_io.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_TGA
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#define STBI_MAX_DIMENSIONS gsdot3::pipeline::max_image_side
#include <stb/stb_image.h>

namespace gsdot3::pipeline {

image decode_tga(const std::uint8_t* data, std::size_t size, const std::string& name) {
  if (size > 0x7fffffffu) throw std::runtime_error(name + ": the image file is too large");
  const int len = static_cast<int>(size);
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(data, len, &w, &h, &n))
    throw std::runtime_error(name + ": not a PNG, JPEG or TGA image (" + stbi_failure_reason() + ")");
  check_image_size(w, h, name);
  const int channels = n <= 2 ? 1 : 3;  // grey (+alpha) stays grey, RGB(A) becomes RGB
  stbi_uc* px = stbi_load_from_memory(data, len, &w, &h, &n, channels);
  if (px == nullptr) throw std::runtime_error(name + ": malformed image data (" + std::string(stbi_failure_reason()) + ")");
  image img{w, h, channels, std::vector<std::uint8_t>(px, px + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(channels))};
  stbi_image_free(px);
  return img;
}

}  // namespace gsdot3::pipeline
