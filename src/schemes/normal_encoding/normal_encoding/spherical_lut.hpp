// normal_encoding/spherical_lut.hpp — Method #3a: spherical coordinates with two 256×256 look-up
// textures (seed 002, 2009 only; 8 bits only: the LUTs are 8-bit textures).
//
// As the seed builds them (UnityScript), point-sampled, clamped:
//   _Atan2Lookup (Alpha8) texel (x, y): xval = x/256·2 − 1, yval = y/256·2 − 1,
//     a = (atan2(yval, xval) + π)/(2π) + 0.5/255;
//   _SinCosLookup (ARGB32) texel (x, y): angY = y/256·2 − 1, scphi = sqrt(1 − angY²), ang = (x/256·2 − 1)·π,
//     rgb = (cos(ang)·scphi, sin(ang)·scphi, angY)·0.5 + 0.5 + 0.5/255.
// A texel byte is trunc(255·clamp01(value)): the seed's "+0.5/255" is its changelog's "round values in
// texture LUT" (2009-08-05), which only rounds if the conversion truncates (confidence: medium — the
// Unity 2.x conversion is not public). Encode: in01 = n·0.5 + 0.5; enc.x = _Atan2Lookup(in01.xy) (a byte,
// stored exactly), enc.y = in01.z (render target). Decode: n = _SinCosLookup(enc)·2 − 1.
// Point sampling at coordinate u picks texel min(floor(u·256), 255); for u = k/255 that is texel k.
#pragma once

#include <array>
#include <cstdint>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::spherical_lut {

inline constexpr int size = 256;

struct tables {
  std::array<std::uint8_t, size * size> atan2_lookup;           // [y·256 + x]
  std::array<std::array<std::uint8_t, 3>, size * size> sincos;  // [y·256 + x] = r, g, b
};
// Built once (spherical_lut.cpp).
const tables& lut();

constexpr int texel_of(double u) noexcept {  // point sampling, clamp addressing
  const double t = u * size;
  return t < 0 ? 0 : t >= size ? size - 1 : static_cast<int>(t);
}

// The code's (texel x, texel y) of the atan2 LUT that n samples (used by the rounding-cell analysis).
inline code encode(vec3 n, int bits) {
  check_bits(bits);
  if (bits != 8)
    throw std::invalid_argument("normal_encoding: #3a spherical-lut exists only at 8 bits (its LUTs are 8-bit)");
  const int tx = texel_of(n.x * 0.5 + 0.5), ty = texel_of(n.y * 0.5 + 0.5);
  return {{lut().atan2_lookup[static_cast<std::size_t>(ty * size + tx)], unorm_encode(n.z * 0.5 + 0.5, 8), 0}};
}
inline vec3 decode(code q, int bits) {
  check_bits(bits);
  if (bits != 8)
    throw std::invalid_argument("normal_encoding: #3a spherical-lut exists only at 8 bits (its LUTs are 8-bit)");
  const auto& t = lut().sincos[static_cast<std::size_t>(texel_of(q.c[1] / 255.0) * size + texel_of(q.c[0] / 255.0))];
  return {t[0] / 255.0 * 2 - 1, t[1] / 255.0 * 2 - 1, t[2] / 255.0 * 2 - 1};
}

}  // namespace gsdot3::normal_encoding::spherical_lut
