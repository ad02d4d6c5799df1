// normal_encoding/spheremap.hpp — Method #4 sphere map (seed 002, 2009), Method #6 Lambert azimuthal
// equal-area (2009), and the 2010 revision's single #4 (= Lambert, input normalised first).
//
// #4 (2009) enc: f = n.z·2 + 1; g = dot(n, n); p = sqrt(g + f); enc = n.xy/p·0.5 + 0.5.
//    dec (the first listing): tmp = enc − enc²; f = tmp.x + tmp.y; m = sqrt(4f − 1);
//    n.xy = (enc·4 − 2)·m; n.z = 8f − 3. (The seed's "optimized" listing is the same algebra.)
// #6 (2009) enc: f = sqrt(8·n.z + 8); enc = n.xy/f + 0.5.
//    dec: fenc = enc·4 − 2; f = dot(fenc, fenc); g = sqrt(1 − f/4); n.xy = fenc·g; n.z = 1 − f/2.
// For unit n both encoders are a = n.xy/sqrt(8(1 + n.z)), enc = a + 0.5, and both decoders are
// n = (4a·sqrt(1 − 4|a|²), 1 − 8|a|²): the same mapping (claim normal-encoding.equivalence).
// (0, 0, −1) gives 0/0 = NaN in both encoders; codes with |a| > 1/2 decode to NaN (sqrt < 0).
#pragma once

#include <cmath>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/two_channel.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::spheremap {

inline void enc(vec3 n, double& ex, double& ey) noexcept {
  const double f = n.z * 2 + 1, g = dot(n, n), p = std::sqrt(g + f);
  ex = n.x / p * 0.5 + 0.5;
  ey = n.y / p * 0.5 + 0.5;
}
inline vec3 dec(double ex, double ey) noexcept {
  const double tx = -ex * ex + ex, ty = -ey * ey + ey, f = tx + ty, m = std::sqrt(4 * f - 1);
  return {(ex * 4 - 2) * m, (ey * 4 - 2) * m, 8 * f - 3};
}

inline code encode(vec3 n, int bits) { return unorm2_encode<enc>(n, bits); }
inline vec3 decode(code q, int bits) { return unorm2_decode<dec>(q, bits); }

}  // namespace gsdot3::normal_encoding::spheremap

namespace gsdot3::normal_encoding::lambert {

inline void enc(vec3 n, double& ex, double& ey) noexcept {
  const double f = std::sqrt(8 * n.z + 8);
  ex = n.x / f + 0.5;
  ey = n.y / f + 0.5;
}
inline vec3 dec(double ex, double ey) noexcept {
  const double fx = ex * 4 - 2, fy = ey * 4 - 2, f = fx * fx + fy * fy, g = std::sqrt(1 - f / 4);
  return {fx * g, fy * g, 1 - f / 2};
}

inline code encode(vec3 n, int bits) { return unorm2_encode<enc>(n, bits); }
inline vec3 decode(code q, int bits) { return unorm2_decode<dec>(q, bits); }

}  // namespace gsdot3::normal_encoding::lambert
