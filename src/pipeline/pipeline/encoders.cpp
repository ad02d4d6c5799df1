// pipeline/encoders.cpp — see encoders.hpp. Float code, written as the paper's listings are.
#include "pipeline/encoders.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace gsdot3::pipeline {

namespace {
gs::u8 byte(int v) { return gs::u8::from_wrapped(v); }
gs::rgba8 rgba(int r, int g, int b, int a) { return {byte(r), byte(g), byte(b), byte(a)}; }
}  // namespace

int nearest(float x) { return x < 0 ? -nearest(-x) : static_cast<int>(x + 0.5f); }

two_pass_texel pack_two_pass(glm::vec3 n) {
  const float scale = 127.9f;
  int iX = static_cast<int>(n.x * scale);
  int iY = static_cast<int>(n.y * scale);
  iX = (iX < -127) ? -127 : ((iX > 128) ? 128 : iX);
  iY = (iY < -127) ? -127 : ((iY > 128) ? 128 : iY);
  const int iZ = static_cast<int>(std::sqrt(static_cast<float>(128 * 128 - (iX * iX + iY * iY))));
  assert(iX * iX + iY * iY + iZ * iZ <= 128 * 128);
  const int R_pos = std::max(iX, 0), G_pos = std::max(iY, 0), B_pos = std::max(iZ, 0);
  const int R_neg = std::max(-iX, 0), G_neg = std::max(-iY, 0), B_neg = std::max(-iZ, 0);
  const int delta = (R_neg - R_pos) + (G_neg - G_pos) + (B_neg - B_pos);
  int alpha = (3 * 128 + delta + 1) / 3;
  alpha = std::clamp(alpha, 0, 255);
  return {rgba(R_pos, G_pos, B_pos, 0x80), rgba(R_neg, G_neg, B_neg, alpha)};
}

gs::rgba8 pack_tolight(glm::vec3 t, int s) {
  auto c = [&](float v) { return 128 + static_cast<signed char>(static_cast<int>(static_cast<float>(s) * v)); };
  return rgba(c(t.x), c(t.y), c(t.z), 0x80);
}

std::vector<std::uint32_t> sphere_map(int iWidth, int iHeight) {
  std::vector<std::uint32_t> mem(static_cast<std::size_t>(iWidth) * iHeight);
  for (int y = 0; y < iHeight; y++)
    for (int x = 0; x < iWidth; x++) {
      const float s = (x + 0.5f) / static_cast<float>(iWidth);
      const float t = (y + 0.5f) / static_cast<float>(iHeight);
      const float s2 = 2 * s - 1;
      const float t2 = 2 * t - 1;
      const float Lz0 = 1 - (s2 * s2 + t2 * t2) * 2;
      int r = 128, g = 128, b = 128;  // zero vector
      if (Lz0 >= -1) {
        const float m = 2 * std::sqrt(2 * Lz0 + 2);
        float Lx = static_cast<float>((s - 0.5) * m);
        float Ly = static_cast<float>((t - 0.5) * m);
        float Lz = Lz0;
        const float div = std::sqrt(Lx * Lx + Ly * Ly + Lz * Lz);
        Lx /= div;
        Ly /= div;
        Lz /= div;
        r = 128 - nearest(Lx * 127);
        g = 128 - nearest(Ly * 127);
        b = 128 - nearest(Lz * 127);
      }
      mem[static_cast<std::size_t>(y) * iWidth + x] = static_cast<std::uint32_t>((b << 16) | (g << 8) | (r << 0));
    }
  return mem;
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
