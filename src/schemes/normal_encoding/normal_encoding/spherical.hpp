// normal_encoding/spherical.hpp — Method #3: spherical coordinates (seed 002, same in 2010).
// enc = (float2(atan2(n.y, n.x)/kPI, n.z) + 1)·0.5, kPI = 3.1415926536;
// dec: ang = enc·2 − 1; (s, c) = sincos(ang.x·kPI); n = (c·sqrt(1 − ang.y²), s·sqrt(1 − ang.y²), ang.y).
// z is stored linearly (not as an angle). atan2(0, 0) = 0 (C; the poles' azimuth is immaterial).
#pragma once

#include <cmath>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/two_channel.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::spherical {

inline constexpr double kPI = 3.1415926536;  // the seed's constant, as written

inline void enc(vec3 n, double& ex, double& ey) noexcept {
  ex = (std::atan2(n.y, n.x) / kPI + 1) * 0.5;
  ey = (n.z + 1) * 0.5;
}
inline vec3 dec(double ex, double ey) noexcept {
  const double ax = ex * 2 - 1, ay = ey * 2 - 1;
  const double s = std::sin(ax * kPI), c = std::cos(ax * kPI), r = std::sqrt(1 - ay * ay);
  return {c * r, s * r, ay};
}

inline code encode(vec3 n, int bits) { return unorm2_encode<enc>(n, bits); }
inline vec3 decode(code q, int bits) { return unorm2_decode<dec>(q, bits); }

}  // namespace gsdot3::normal_encoding::spherical
