// normal_encoding/cryengine3.hpp — Method #5: CryEngine 3 (seed 002, 2009, after Mittring 2009,
// with the seed's negated z for Unity's view space).
// enc = normalize(n.xy)·sqrt(−n.z·0.5 + 0.5); enc = enc·0.5 + 0.5.
// dec (the first listing): fenc = enc·2 − 1; n.z = −(dot(fenc, fenc)·2 − 1); n.xy = normalize(fenc)·sqrt(1 − n.z²).
// normalize(0) is NaN (HLSL: 0·rsqrt(0)), so BOTH poles (0, 0, ±1) encode to NaN, which the render
// target stores as 0 (quantise.hpp) — code (0, 0), which decodes to NaN (n.z = −3).
#pragma once

#include <cmath>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/two_channel.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::cryengine3 {

inline void enc(vec3 n, double& ex, double& ey) noexcept {
  const double inv = 1.0 / std::sqrt(n.x * n.x + n.y * n.y), s = std::sqrt(-n.z * 0.5 + 0.5);
  ex = (n.x * inv) * s * 0.5 + 0.5;
  ey = (n.y * inv) * s * 0.5 + 0.5;
}
inline vec3 dec(double ex, double ey) noexcept {
  const double fx = ex * 2 - 1, fy = ey * 2 - 1;
  const double z = -((fx * fx + fy * fy) * 2 - 1);
  const double inv = 1.0 / std::sqrt(fx * fx + fy * fy), r = std::sqrt(1 - z * z);
  return {fx * inv * r, fy * inv * r, z};
}

inline code encode(vec3 n, int bits) { return unorm2_encode<enc>(n, bits); }
inline vec3 decode(code q, int bits) { return unorm2_decode<dec>(q, bits); }

}  // namespace gsdot3::normal_encoding::cryengine3
