// normal_encoding/quantise.hpp — how a render target stores a value, and the bit counts allowed.
//
// unorm (the seed's 8-bit RGBA render target, and 10/12/16-bit ones): NaN -> 0, clamp to [0, 1],
// q = floor(v·(2^b − 1) + 0.5), i.e. round to nearest with halves up. D3D10+ prescribes NaN -> 0 and
// round-to-nearest for float -> UNORM (D3D11 functional spec §3.2.3.6; the tie rule is ours: confidence
// medium — ties have measure zero on the sphere, so no supremum depends on it).
// snorm (as mesh compressors store octahedral codes, meshoptimizer `meshopt_quantizeSnorm`): clamp to
// [−1, 1], q = round half away from zero of v·(2^(b−1) − 1); decode max(q / (2^(b−1) − 1), −1).
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace gsdot3::normal_encoding {

// The supported bits per channel: 4 to 16 (render targets have 8, 10 and 16; the small counts let
// the tests check the rounding-cell argument against brute force). Otherwise std::invalid_argument.
inline constexpr int min_bits = 4, max_bits = 16;
inline void check_bits(int bits) {
  if (bits < min_bits || bits > max_bits)
    throw std::invalid_argument("normal_encoding: bits per channel must be 4 to 16, not " + std::to_string(bits));
}

constexpr std::uint32_t unorm_max(int bits) noexcept { return (std::uint32_t{1} << bits) - 1; }
constexpr std::int32_t snorm_max(int bits) noexcept { return (std::int32_t{1} << (bits - 1)) - 1; }

inline std::uint32_t unorm_encode(double v, int bits) noexcept {
  if (std::isnan(v)) return 0;
  const double c = v < 0 ? 0 : v > 1 ? 1 : v;
  return static_cast<std::uint32_t>(std::floor(c * unorm_max(bits) + 0.5));
}
inline double unorm_decode(std::uint32_t q, int bits) noexcept { return q / static_cast<double>(unorm_max(bits)); }

inline std::int32_t snorm_encode(double v, int bits) noexcept {
  if (std::isnan(v)) return 0;
  const double c = v < -1 ? -1 : v > 1 ? 1 : v;
  return static_cast<std::int32_t>(std::round(c * snorm_max(bits)));  // std::round: halves away from zero
}
inline double snorm_decode(std::int32_t q, int bits) noexcept {
  const double v = q / static_cast<double>(snorm_max(bits));
  return v < -1 ? -1 : v;
}

// A stored code: up to three channels (for snorm the channel holds q + 2^(b−1)).
struct code {
  std::uint32_t c[3] = {0, 0, 0};
  friend bool operator==(const code&, const code&) = default;
};

}  // namespace gsdot3::normal_encoding
