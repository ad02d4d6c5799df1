// normal_encoding/stereographic.hpp — Method #7: stereographic projection, scale 1.7777 (seed 002,
// same in 2010). enc = n.xy/(n.z + 1)/scale·0.5 + 0.5 (the render target clamps it to [0, 1]);
// dec: nn = (enc.xy·2·scale − scale, 1); g = 2/dot(nn, nn); n = (g·nn.xy, g − 1).
// The pole (0, 0, −1) gives 0/0 = NaN (stored as 0); directions beyond the unit square of the
// scaled projection are clamped, which is where the worst case lives.
#pragma once

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/two_channel.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::stereographic {

inline constexpr double scale = 1.7777;

inline void enc(vec3 n, double& ex, double& ey) noexcept {
  const double px = n.x / (n.z + 1) / scale, py = n.y / (n.z + 1) / scale;
  ex = px * 0.5 + 0.5;
  ey = py * 0.5 + 0.5;
}
inline vec3 dec(double ex, double ey) noexcept {
  const double x = ex * 2 * scale - scale, y = ey * 2 * scale - scale;
  const double g = 2.0 / (x * x + y * y + 1);
  return {g * x, g * y, g - 1};
}

inline code encode(vec3 n, int bits) { return unorm2_encode<enc>(n, bits); }
inline vec3 decode(code q, int bits) { return unorm2_decode<dec>(q, bits); }

}  // namespace gsdot3::normal_encoding::stereographic
