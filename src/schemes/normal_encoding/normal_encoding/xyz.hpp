// normal_encoding/xyz.hpp — Baseline: store X&Y&Z (seed 002, 2009; unchanged in 2010).
// enc = n.xyz·0.5 + 0.5; dec = enc·2 − 1 (not renormalised, as in the 2010 listing).
#pragma once

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::xyz {

inline vec3 enc(vec3 n) noexcept { return {n.x * 0.5 + 0.5, n.y * 0.5 + 0.5, n.z * 0.5 + 0.5}; }
inline vec3 dec(vec3 e) noexcept { return {e.x * 2 - 1, e.y * 2 - 1, e.z * 2 - 1}; }

inline code encode(vec3 n, int bits) {
  check_bits(bits);
  const vec3 e = enc(n);
  return {{unorm_encode(e.x, bits), unorm_encode(e.y, bits), unorm_encode(e.z, bits)}};
}
inline vec3 decode(code q, int bits) {
  check_bits(bits);
  return dec({unorm_decode(q.c[0], bits), unorm_decode(q.c[1], bits), unorm_decode(q.c[2], bits)});
}

}  // namespace gsdot3::normal_encoding::xyz
