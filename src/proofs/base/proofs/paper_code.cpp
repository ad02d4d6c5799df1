#include "proofs/paper_code.hpp"

#include <cmath>

namespace gsdot3::proofs::paper {

int nearest(const float x) noexcept {
  if (x < 0)
    return -nearest(-x);
  else
    return (int)(x + 0.5f);
}

sphere_texel sphere_map_texel(int x, int y, int iWidth, int iHeight) noexcept {
  // reversed GS remapping (section 3.4.8)
  const float s = (x + 0.5f) / ((float)iWidth);
  const float t = (y + 0.5f) / ((float)iHeight);
  const float s2 = 2 * s - 1;
  const float t2 = 2 * t - 1;

  float Lz = 1 - (s2 * s2 + t2 * t2) * 2;

  sphere_texel out;  // zero vector: r = g = b = 128
  if (Lz >= -1) {
    const float m = 2 * std::sqrt(2 * Lz + 2);  // float sqrt

    float Lx = (s - 0.5) * m;  // 0.5 is a double: formed in double, rounded to float
    float Ly = (t - 0.5) * m;

    // normalize for accuracy
    const float div = std::sqrt(Lx * Lx + Ly * Ly + Lz * Lz);
    Lx /= div;
    Ly /= div;
    Lz /= div;

    // must remember to subtract the vector from 128
    out.r = 128 - nearest(Lx * 127);
    out.g = 128 - nearest(Ly * 127);
    out.b = 128 - nearest(Lz * 127);
    out.inside = true;
    out.lx = Lx;
    out.ly = Ly;
    out.lz = Lz;
  }
  return out;
}

std::vector<std::uint32_t> generate_sphere_map(int width, int height) {
  std::vector<std::uint32_t> mem(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; y++)
    for (int x = 0; x < width; x++) {
      const auto t = sphere_map_texel(x, y, width, height);
      mem[static_cast<std::size_t>(y * width + x)] = static_cast<std::uint32_t>((t.b << 16) | (t.g << 8) | (t.r << 0));
    }
  return mem;
}

namespace {
constexpr int Max(int a, int b) { return a > b ? a : b; }
}  // namespace

packed_normal pack_normal_from(int iX, int iY) noexcept {
  packed_normal p;
  // clamp to [-127; 128]
  iX = (iX < (-127)) ? (-127) : ((iX > 128) ? 128 : iX);
  iY = (iY < (-127)) ? (-127) : ((iY > 128) ? 128 : iY);

  // Choose iZ so length(N) <= 128
  int iZ = (int)std::sqrt(static_cast<double>(128 * 128 - (iX * iX + iY * iY)));
  p.assert_le = (iX * iX + iY * iY + iZ * iZ) <= 128 * 128;
  p.assert_gt = (iX * iX + iY * iY + (iZ + 1) * (iZ + 1)) > 128 * 128;

  // positive side
  p.R_pos = Max(iX, 0);
  p.G_pos = Max(iY, 0);
  p.B_pos = Max(iZ, 0);
  // negative side
  p.R_neg = Max(-iX, 0);
  p.G_neg = Max(-iY, 0);
  p.B_neg = Max(-iZ, 0);  // B_neg should always be zero
  p.delta = (p.R_neg - p.R_pos) + (p.G_neg - p.G_pos) + (p.B_neg - p.B_pos);
  int alpha = (3 * 128 + p.delta + 1) / 3;
  p.alpha_unclamped = alpha;
  alpha = (alpha < 0) ? 0 : ((iX > 255) ? 255 : alpha);  // sic: iX, not alpha
  p.alpha = alpha;
  p.iX = iX;
  p.iY = iY;
  p.iZ = iZ;
  return p;
}

packed_normal pack_normal(float nx, float ny) noexcept {
  const float scale = 127.9f;
  // scale to range
  int iX = (int)(nx * scale);
  int iY = (int)(ny * scale);
  return pack_normal_from(iX, iY);
}

int pack_light_component(float s, float t) noexcept { return static_cast<signed char>(static_cast<int>(s * t)); }

}  // namespace gsdot3::proofs::paper
