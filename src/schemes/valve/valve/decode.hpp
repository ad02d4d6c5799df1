// valve/decode.hpp — what the pixel shader makes of an 8-bit texel: the RNM normal N = 2·T − 1
// (seed eq. (2), Listing 1's first line), the SSBump weights (the texel itself, Listing 2), and the
// tangent-space normal rebuilt from SSBump weights "when needed" with the basis directions.
#pragma once

#include <cmath>
#include <cstdint>

#include "valve/basis.hpp"
#include "valve/shader_float.hpp"

namespace gsdot3::valve {

struct texel {
  std::uint8_t r = 0, g = 0, b = 0;
  friend constexpr bool operator==(const texel&, const texel&) = default;
  // The 2^24 RGB8 texels by index 0xRRGGBB.
  static constexpr texel at(std::uint32_t rgb) noexcept {
    return {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8), static_cast<std::uint8_t>(rgb)};
  }
  constexpr std::uint32_t index() const noexcept { return (std::uint32_t{r} << 16) | (std::uint32_t{g} << 8) | b; }
};

// UNORM8 → shader float: c / 255 (Direct3D 9 texture fetch), rounded to the shader's format.
constexpr double unorm8(const shader_arith& a, std::uint8_t c) noexcept { return a.r(c / 255.0); }

// Eq. (2): N = 2·T − 1 in the shader's arithmetic (2·t is exact; one rounding for the − 1).
constexpr vec3<double> rnm_normal(const shader_arith& a, const texel& t) noexcept {
  auto n = [&](std::uint8_t c) { return a.sub(a.mul(2.0, unorm8(a, c)), 1.0); };
  return {n(t.r), n(t.g), n(t.b)};
}

// The normal a texel encodes, exactly: (2c − 255)/255 per channel (never zero: 2c − 255 is odd).
constexpr vec3<double> encoded_normal(const texel& t) noexcept {
  auto n = [](std::uint8_t c) { return (2.0 * c - 255.0) / 255.0; };
  return {n(t.r), n(t.g), n(t.b)};
}

inline vec3<double> normalised(const vec3<double>& v) noexcept {
  const double len = std::sqrt(dot(v, v));
  return {v.x / len, v.y / len, v.z / len};
}

// Listing 2: the SSBump texel is D itself.
constexpr vec3<double> ssbump_weights(const shader_arith& a, const texel& t) noexcept {
  return {unorm8(a, t.r), unorm8(a, t.g), unorm8(a, t.b)};
}

// The seed's reconstruction "use our original basis directions B to reconstruct a suitable
// tangent-space normal", read as normalize(Σ D_i·B_i) (exact arithmetic).
inline vec3<double> reconstruct_normal(const vec3<double>& D, const basis3& B = exact_basis) noexcept {
  const vec3<double> s{D.x * B[0].x + D.y * B[1].x + D.z * B[2].x, D.x * B[0].y + D.y * B[1].y + D.z * B[2].y,
                       D.x * B[0].z + D.y * B[1].z + D.z * B[2].z};
  return normalised(s);
}

// The inverse of D_i = (N·B_i)² where every N·B_i ≥ 0: normalize(Σ √D_i·B_i) (orthonormal B).
inline vec3<double> reconstruct_normal_sqrt(const vec3<double>& D, const basis3& B = exact_basis) noexcept {
  return reconstruct_normal({std::sqrt(D.x), std::sqrt(D.y), std::sqrt(D.z)}, B);
}

}  // namespace gsdot3::valve
