// powervr/evaluate.hpp — the bump unit: intensity = K1 + K2·sin S + K3·cos S·cos(R − Q), clamped to
// 0..1 (seed 004; the same formula in flycast's PixelPipelineShader). The hardware's internal
// precision is not public (confidence: none), so it is a named option and every figure says which:
//   float32  flycast's float emulation, operation by operation in float (PI = 3.1415926f as its
//            shader defines it), the result rounded to the 8-bit output (round to nearest);
//   fixedB   B = 8, 10, 12: sin S, cos S and cos(R − Q) from tables of round(2^B·f) (round half away
//            from zero); cos S·cos(R − Q) rounded back to B bits (+2^(B−1), floor shift); the sum
//            K1·2^B + K2·sin + K3·cos·cos rounded to the output byte the same way, then clamped.
//            The azimuth difference indexes its table modulo the convention's steps (255 or 256),
//            which is exact: cos is 2π-periodic.
#pragma once

#include <array>
#include <cstdint>

#include "powervr/texel.hpp"

namespace gsdot3::schemes::powervr {

enum class precision { float32, fixed8, fixed10, fixed12 };
inline constexpr std::array<precision, 4> all_precisions{precision::float32, precision::fixed8, precision::fixed10,
                                                         precision::fixed12};
const char* name(precision p) noexcept;
constexpr int table_bits(precision p) noexcept {
  return p == precision::fixed8 ? 8 : p == precision::fixed10 ? 10 : p == precision::fixed12 ? 12 : 0;
}

// The exact real value 255·(K1 + K2 sin S + K3 cos S cos(R − Q))/255, unclamped, in output units
// (1/255 of full intensity), in double.
double intensity_exact(bump_texel t, offset_colour k, azimuth_scale a) noexcept;

// flycast's float value of the clamped intensity (0..1) before the 8-bit output.
float intensity_flycast(bump_texel t, offset_colour k, azimuth_scale a) noexcept;
// The same for an offset colour given as x/255 floats (k1..k3 in 0..1, q = Q/255): what flycast's
// shader sees when it interpolates the per-vertex offset colour across a Gouraud-shaded polygon.
float intensity_flycast(bump_texel t, float k1, float k2, float k3, float q, azimuth_scale a) noexcept;

// The 8-bit output of the bump unit under a precision option (0..255).
std::uint8_t intensity(bump_texel t, offset_colour k, azimuth_scale a, precision p) noexcept;

// The tables of one fixed-point option (exposed for the sweeps, which index them directly).
struct fixed_tables {
  int bits = 8;
  std::array<std::int32_t, 256> sin_s{}, cos_s{};  // round(2^B·sin/cos(S·(π/2)/255))
  std::array<std::int32_t, 256> cos_d{};           // round(2^B·cos(d·2π/steps)), d < steps
  int steps = 255;
};
const fixed_tables& tables(int bits, azimuth_scale a);

// The fixed-point bump unit on given tables.
constexpr std::uint8_t intensity_fixed(const fixed_tables& tb, bump_texel t, offset_colour k) noexcept {
  const int d = ((t.R - k.Q) % tb.steps + tb.steps) % tb.steps;
  const std::int64_t half = std::int64_t{1} << (tb.bits - 1);
  const std::int64_t cc =
      (static_cast<std::int64_t>(tb.cos_s[t.S]) * tb.cos_d[static_cast<std::size_t>(d)] + half) >> tb.bits;
  const std::int64_t acc =
      (static_cast<std::int64_t>(k.K1) << tb.bits) + static_cast<std::int64_t>(k.K2) * tb.sin_s[t.S] + k.K3 * cc;
  const std::int64_t out = (acc + half) >> tb.bits;
  return static_cast<std::uint8_t>(out < 0 ? 0 : out > 255 ? 255 : out);
}

// flycast's float path with its per-S sines and cosines and per-(R, Q) cos(r − q) computed once, by the
// same float operations as intensity_flycast (the sweeps use it; a test checks the two agree bit for bit).
struct flycast_tables {
  std::array<float, 256> sin_s{}, cos_s{};
  std::array<float, 65536> cos_rq{};  // [R·256 + Q]
  explicit flycast_tables(azimuth_scale a);
  float value(bump_texel t, offset_colour k) const noexcept {
    const float k1 = static_cast<float>(k.K1) / 255.0f, k2 = static_cast<float>(k.K2) / 255.0f,
                k3 = static_cast<float>(k.K3) / 255.0f;
    const float v = k1 + k2 * sin_s[t.S] + k3 * cos_s[t.S] * cos_rq[static_cast<std::size_t>(t.R) << 8 | k.Q];
    return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
  }
};

}  // namespace gsdot3::schemes::powervr
