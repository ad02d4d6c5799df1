// pipeline/encoders.cpp — see encoders.hpp. Appendix 1 and 2 are src/proofs' transcriptions
// (proofs::paper); the palettes built from them are here.
#include "pipeline/encoders.hpp"

#include "pipeline/spot.hpp"
#include "proofs/paper_code.hpp"

#include <algorithm>
#include <cmath>

namespace gsdot3::pipeline {

namespace {
gs::u8 byte(int v) { return gs::u8::from_wrapped(v); }
gs::rgba8 rgba(int r, int g, int b, int a) { return {byte(r), byte(g), byte(b), byte(a)}; }
}  // namespace

int nearest(float x) { return proofs::paper::nearest(x); }

two_pass_texel pack_two_pass(glm::vec3 n) {
  const proofs::paper::packed_normal p = proofs::paper::pack_normal(n.x, n.y);
  return {rgba(p.R_pos, p.G_pos, p.B_pos, 0x80), rgba(p.R_neg, p.G_neg, p.B_neg, p.alpha)};
}

gs::rgba8 pack_tolight(glm::vec3 t, int s) {
  const auto sf = static_cast<float>(s);
  return rgba(128 + proofs::paper::pack_light_component(sf, t.x), 128 + proofs::paper::pack_light_component(sf, t.y),
              128 + proofs::paper::pack_light_component(sf, t.z), 0x80);
}

std::vector<std::uint32_t> sphere_map(int width, int height) {
  return proofs::paper::generate_sphere_map(width, height);
}

std::vector<std::uint32_t> spot_map() {
  std::vector<std::uint32_t> w(spot_map_size * spot_map_size);
  for (int j = 0; j < spot_map_size; ++j)
    for (int i = 0; i < spot_map_size; ++i) {
      const double s = (i + 0.5) / spot_map_size, t = (j + 0.5) / spot_map_size;
      const auto a = static_cast<std::uint32_t>(std::lround(128.0 * spot_intensity(s, t)));
      w[static_cast<std::size_t>(j * spot_map_size + i)] = a << 24 | 0x808080u;
    }
  return w;
}

st sphere_coordinates(glm::vec3 t) {
  // m = 2·sqrt(2·Tz + 2); at Tz = −1 the map's rim is reached (m → 0): keep m away from zero.
  const float m = std::max(2.0f * std::sqrt(std::max(2.0f * t.z + 2.0f, 0.0f)), 1e-6f);
  return {std::clamp(t.x / m + 0.5f, 0.0f, 1.0f), std::clamp(t.y / m + 0.5f, 0.0f, 1.0f)};
}

gs::clut_buffer reordered_palette(const std::vector<glm::vec3>& normals, int axis) {
  gs::clut_buffer p{};
  p.fill(rgba(128, 128, 128, 128));
  for (std::size_t i = 0; i < normals.size() && i < 256; ++i)
    p[i] = rgba(128, 128, 128, 128 + nearest(normals[i][axis] * 127));
  return p;
}

std::vector<std::uint8_t> component_map(const std::vector<glm::vec3>& normals, int axis) {
  std::vector<std::uint8_t> m(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i)
    m[i] = static_cast<std::uint8_t>(128 + nearest(normals[i][axis] * 127));
  return m;
}

gs::clut_buffer component_ramp_palette() {
  gs::clut_buffer p{};
  for (int i = 0; i < 256; ++i) p[static_cast<std::size_t>(i)] = rgba(128, 128, 128, i);
  return p;
}

gs::clut_buffer signed_side_palette(const std::vector<glm::vec3>& normals, bool negative) {
  gs::clut_buffer p{};
  p.fill(rgba(0, 0, 0, 0x80));
  const float sign = negative ? -1.0f : 1.0f;
  for (std::size_t i = 0; i < normals.size() && i < 256; ++i) {
    const glm::vec3 n = normals[i] * sign;
    p[i] = rgba(nearest(std::max(n.x, 0.0f) * 127), nearest(std::max(n.y, 0.0f) * 127),
                nearest(std::max(n.z, 0.0f) * 127), 0x80);
  }
  return p;
}

gs::clut_buffer two_pass_palette(const std::vector<glm::vec3>& normals, bool negative) {
  gs::clut_buffer p{};
  p.fill(negative ? rgba(0, 0, 0, 128) : rgba(0, 0, 0, 0x80));
  for (std::size_t i = 0; i < normals.size() && i < 256; ++i) {
    const two_pass_texel t = pack_two_pass(normals[i]);
    p[i] = negative ? t.negative : t.positive;
  }
  return p;
}

gs::clut_buffer three_pass_terms_palette(const std::vector<glm::vec3>& normals) {
  gs::clut_buffer p{};
  p.fill(rgba(128, 128, 128, 0x80));  // the zero normal's terms: the fill of the other two palettes
  for (std::size_t i = 0; i < normals.size() && i < 256; ++i) {
    const two_pass_texel t = pack_two_pass(normals[i]);
    auto term = [](gs::u8 pos, gs::u8 neg) { return 128 + neg.value() - pos.value(); };
    p[i] = rgba(term(t.positive.r, t.negative.r), term(t.positive.g, t.negative.g), term(t.positive.b, t.negative.b),
                0x80);
  }
  return p;
}

gs::clut_buffer intensity_palette(double power) {
  gs::clut_buffer p{};
  for (int v = 0; v < 256; ++v) {
    const int d = (v - 128) & 0xFF;  // the dot product this sum stands for, as an unsigned byte
    int level = d < 128 ? d + 1 : 0;
    if (power != 1.0 && level > 0) level = static_cast<int>(std::lround(128.0 * std::pow(level / 128.0, power)));
    p[static_cast<std::size_t>(v)] = rgba(level, level, level, 0x80);
  }
  return p;
}

gs::clut_buffer identity_palette() {
  gs::clut_buffer p{};
  for (int i = 0; i < 256; ++i) p[static_cast<std::size_t>(i)] = rgba(i, i, i, 0x80);
  return p;
}

}  // namespace gsdot3::pipeline
