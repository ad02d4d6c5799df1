// powervr/encode.cpp — the offset-colour encoders (see encode.hpp).
#include "powervr/encode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gsdot3::schemes::powervr {

namespace {
constexpr double two_pi = 2.0 * std::numbers::pi;
double wrap(double q) noexcept { return q < 0.0 ? q + two_pi : q >= two_pi ? q - two_pi : q; }
std::uint8_t byte_nearest(double v) noexcept { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }
}  // namespace

polar_light seed_printed(const glm::dvec3& P, double S_l) noexcept {
  return {S_l, std::asin(std::clamp(P.z, -1.0, 1.0)), wrap(std::atan(P.y / P.x))};
}

polar_light seed_atan2(const glm::dvec3& P, double S_l) noexcept {
  return {S_l, std::asin(std::clamp(P.z, -1.0, 1.0)), wrap(std::atan2(P.y, P.x))};
}

offset_colour offset_nearest(const polar_light& l, azimuth_scale a) noexcept {
  const int steps = azimuth_steps(a);
  const long q = std::lround(l.Q * steps / two_pi) % steps;
  return {byte_nearest(255.0 * (1.0 - l.S_l)), byte_nearest(255.0 * l.S_l * std::sin(l.T)),
          byte_nearest(255.0 * l.S_l * std::cos(l.T)), static_cast<std::uint8_t>(q)};
}

offset_colour pvr_pack_bump(float h, float t, float q) noexcept {
  constexpr float f_pi = 3.1415926f;  // KallistiOS' F_PI
  const auto hp = static_cast<std::uint8_t>(h * 255.0f);
  return {static_cast<std::uint8_t>(~hp), static_cast<std::uint8_t>(static_cast<float>(hp) * std::sin(t)),
          static_cast<std::uint8_t>(static_cast<float>(hp) * std::cos(t)),
          static_cast<std::uint8_t>((q / (2 * f_pi)) * 255.0f)};
}

skk fxyz_light_dir_to_skk(float x, float y, float z) noexcept {
  // Octant index: bit 0 = |z| > |x|, bit 1 = sign of x, bit 2 = sign of z (signbit, so −0 counts).
  constexpr std::array<float, 8> octants{0.0f, 64.0f, 128.0f, -64.0f, 256.0f, -192.0f, -128.0f, 192.0f};
  float lo = 0.0f, hi = 1.0f;
  int octant = 0;
  if (std::fabs(x) < 0x1p-95f && std::fabs(z) < 0x1p-95f) {
    // The SDK's EPSILON test (exponent field below 0x20, i.e. |x|, |z| < 2^−95): any azimuth will do.
  } else if (std::fabs(x) >= std::fabs(z)) {
    lo = z, hi = x;
  } else {
    lo = x, hi = z, octant = 1;
  }
  if (std::signbit(y)) y = 0.00001f;
  const float xz2 = x * x + z * z, xyz2 = xz2 + y * y;
  float s = std::fabs(lo / hi);
  s = static_cast<float>((-11.562812f * s + 43.562812f) * s);
  octant |= (std::signbit(x) ? 2 : 0) | (std::signbit(z) ? 4 : 0);
  s = std::fabs(s - octants[static_cast<std::size_t>(octant)]);
  const float sinT = y / std::sqrt(xyz2), cosT = std::sqrt(xz2) / std::sqrt(xyz2);
  auto to_byte = [](float v) {  // nearest (ties to even, as the FPU's default mode); 256 → 255
    const float r = std::nearbyint(v);
    return static_cast<std::uint8_t>(r >= 256.0f ? 255.0f : r);
  };
  return {to_byte(s), to_byte(sinT * 256.0f), to_byte(cosT * 256.0f)};
}

}  // namespace gsdot3::schemes::powervr
