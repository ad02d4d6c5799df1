// pipeline/normal_map_image.cpp — decoded image → unit normals → GS size → palette.
#include "pipeline/normal_map_image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "pipeline/image_io.hpp"
#include "pipeline/normal_map.hpp"

namespace gsdot3::pipeline {

int texture_side(int side) {
  const int e = static_cast<int>(std::lround(std::log2(std::max(side, 1))));
  return 1 << std::clamp(e, 3, 10);
}

namespace {

// The source texels output texel i of `out` covers along one axis, with their overlap lengths.
struct tap {
  int src;
  double weight;
};
std::vector<std::vector<tap>> box_taps(int in, int out) {
  std::vector<std::vector<tap>> taps(static_cast<std::size_t>(out));
  const double scale = static_cast<double>(in) / out;
  for (int i = 0; i < out; ++i) {
    const double lo = i * scale, hi = (i + 1) * scale;
    for (int s = static_cast<int>(std::floor(lo)); s < std::min(in, static_cast<int>(std::ceil(hi))); ++s) {
      const double w = std::min<double>(hi, s + 1) - std::max<double>(lo, s);
      if (w > 0) taps[static_cast<std::size_t>(i)].push_back({s, w});
    }
  }
  return taps;
}

}  // namespace

std::vector<glm::vec3> resample_normals(const std::vector<glm::vec3>& n, int w, int h, int W, int H) {
  const auto tx = box_taps(w, W), ty = box_taps(h, H);
  std::vector<glm::vec3> out(static_cast<std::size_t>(W) * static_cast<std::size_t>(H));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      glm::dvec3 sum(0.0);
      for (const tap& a : ty[static_cast<std::size_t>(y)])
        for (const tap& b : tx[static_cast<std::size_t>(x)])
          sum +=
              glm::dvec3(
                  n[static_cast<std::size_t>(a.src) * static_cast<std::size_t>(w) + static_cast<std::size_t>(b.src)]) *
              (a.weight * b.weight);
      out[static_cast<std::size_t>(y) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x)] =
          glm::length(sum) > 1e-12 ? glm::vec3(glm::normalize(sum)) : glm::vec3(0, 0, 1);
    }
  return out;
}

loaded_normal_map normal_map_from_image(const image& img, const std::string& name, const normal_map_settings& s) {
  loaded_normal_map r;
  r.source_width = img.width;
  r.source_height = img.height;
  const std::size_t texels = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  bool grey = img.channels == 1;
  if (!grey && s.grey_is_height) {
    grey = true;
    for (std::size_t i = 0; grey && i < texels; ++i)
      grey = img.data[3 * i] == img.data[3 * i + 1] && img.data[3 * i] == img.data[3 * i + 2];
  }
  std::vector<glm::vec3> normals;
  if (grey) {
    if (!s.grey_is_height)
      throw std::runtime_error(
          name + ": the normal map must be 8-bit RGB or RGBA, not grey (a grey image is a height map: --height-map)");
    std::vector<float> height(texels);
    for (std::size_t i = 0; i < texels; ++i) height[i] = img.data[i * static_cast<std::size_t>(img.channels)];
    normals = normals_from_height(height, img.width, img.height, s.height_strength);  // y down the image
    r.from_height = true;
  } else {
    normals.reserve(texels);
    const float y_sign = s.y == normal_map_y::up ? -1.0f : 1.0f;  // into the renderer's v-down frame
    for (std::size_t i = 0; i < texels; ++i) {
      const glm::vec3 n{s.xy_scale * (img.data[3 * i] / 127.5f - 1.0f),
                        s.xy_scale * y_sign * (img.data[3 * i + 1] / 127.5f - 1.0f),
                        img.data[3 * i + 2] / 127.5f - 1.0f};
      normals.push_back(glm::length(n) > 1e-3f ? glm::normalize(n) : glm::vec3(0, 0, 1));
    }
  }
  const int W = s.width > 0 ? s.width : texture_side(img.width), H = s.height > 0 ? s.height : texture_side(img.height);
  r.resampled = W != img.width || H != img.height;
  if (r.resampled) normals = resample_normals(normals, img.width, img.height, W, H);
  r.map = quantise(normals, W, H, 256);
  return r;
}

loaded_normal_map load_normal_map(const std::uint8_t* data, std::size_t size, const std::string& name,
                                  const normal_map_settings& s) {
  std::string format;
  const image img = decode_image(data, size, name, format);
  loaded_normal_map r = normal_map_from_image(img, name, s);
  r.format = format;
  return r;
}

loaded_normal_map load_normal_map(const std::filesystem::path& file, const normal_map_settings& s) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(file, "normal map");
  return load_normal_map(bytes.data(), bytes.size(), file.string(), s);
}

}  // namespace gsdot3::pipeline
