// normal_encoding/xy.hpp — Method #1: store X&Y, reconstruct Z (seed 002; Killzone 2).
// enc = n.xy·0.5 + 0.5; dec: n.xy = enc·2 − 1, n.z = sqrt(1 − dot(n.xy, n.xy)) — z >= 0 always, and
// NaN where dot(n.xy, n.xy) > 1 (HLSL sqrt of a negative), e.g. for the code of (1, 0, 0).
// Also Method #2 (X&Y&sign of Z): the seed leaves it "TODO!"; we store the sign as one extra bit
// (channel 2: 1 iff n.z < 0) and negate the reconstructed z.
#pragma once

#include <cmath>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::xy {

inline vec3 dec(double ex, double ey) noexcept {
  const double x = ex * 2 - 1, y = ey * 2 - 1;
  return {x, y, std::sqrt(1 - (x * x + y * y))};
}

inline code encode(vec3 n, int bits) {
  check_bits(bits);
  return {{unorm_encode(n.x * 0.5 + 0.5, bits), unorm_encode(n.y * 0.5 + 0.5, bits), 0}};
}
inline vec3 decode(code q, int bits) {
  check_bits(bits);
  return dec(unorm_decode(q.c[0], bits), unorm_decode(q.c[1], bits));
}

// Method #2.
inline code encode_signed(vec3 n, int bits) {
  code q = encode(n, bits);
  q.c[2] = n.z < 0 ? 1 : 0;
  return q;
}
inline vec3 decode_signed(code q, int bits) {
  vec3 n = decode(q, bits);
  if (q.c[2] != 0) n.z = -n.z;
  return n;
}

}  // namespace gsdot3::normal_encoding::xy
