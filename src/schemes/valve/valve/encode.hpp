// valve/encode.hpp — making the 8-bit maps: a unit normal as an RGB8 normal-map texel, the exact
// RNM weights of a normal (seed eq. (3)), and Source's normal2ssbump (Source SDK 2013
// src/utils/normal2ssbump/normal2ssbump.cpp, read in the stored copy: RangeAdjust(x) = 2(x − .5),
// saturate_and_square of N·B_i with the shipped float basis, dp *= 1.0/sum, float arithmetic),
// whose float result Source writes with FloatBitMap_t::WriteTGAFile, converting each channel as
// (unsigned char)max(0, min(255, 255·f)): truncation (src/public/bitmap/floatbitmap.h, stored copy).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "valve/basis.hpp"
#include "valve/decode.hpp"

namespace gsdot3::valve {

// A unit normal as RGB8: round(127.5·n + 127.5) per channel (the scene's normal-map packing).
inline texel encode_normal_rgb8(const vec3<double>& n) noexcept {
  auto c = [](double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(127.5 * v + 127.5), 0L, 255L)); };
  return {c(n.x), c(n.y), c(n.z)};
}

// Eq. (3) exactly (double): d_i = saturate(N·B_i)², D = d / Σd. Returns false when Σd = 0.
inline bool exact_weights(const vec3<double>& N, vec3<double>& D, const basis3& B = exact_basis) noexcept {
  auto d = [&](const vec3<double>& b) {
    const double s = std::clamp(dot(N, b), 0.0, 1.0);
    return s * s;
  };
  const double d0 = d(B[0]), d1 = d(B[1]), d2 = d(B[2]), sum = d0 + d1 + d2;
  if (sum == 0.0) return false;
  D = {d0 / sum, d1 / sum, d2 / sum};
  return true;
}

// normal2ssbump's float weights for an 8-bit normal-map texel (FloatBitMap reads c/255 as float).
// NaN components when Σd = 0 (the tool divides by zero too).
// `B` defaults to the shipped literals; exact_basis_float is the alternative the claims compare.
inline vec3<float> normal2ssbump(const texel& t, const std::array<vec3<float>, 3>& B = source_basis_float) noexcept {
  auto range_adjust = [](std::uint8_t c) { return 2.0f * (static_cast<float>(c) / 255.0f - 0.5f); };
  auto saturate_and_square = [](float x) {
    x = std::max(0.0f, std::min(1.0f, x));
    return x * x;
  };
  const vec3<float> n{range_adjust(t.r), range_adjust(t.g), range_adjust(t.b)};
  const vec3<float> dp{saturate_and_square(dot(n, B[0])), saturate_and_square(dot(n, B[1])),
                       saturate_and_square(dot(n, B[2]))};
  const float sum = dot(dp, vec3<float>{1.0f, 1.0f, 1.0f});
  const float scale = static_cast<float>(1.0 / static_cast<double>(sum));  // Vector::operator*=(float) of 1.0/sum
  return {dp.x * scale, dp.y * scale, dp.z * scale};
}

enum class quantise { truncate, nearest };  // Source's PixRGBA8 truncates

// A float weight in [0, 1] (NaN → 0) as an 8-bit channel.
inline std::uint8_t to_unorm8(double f, quantise q) noexcept {
  if (!(f > 0.0)) return 0;
  const double v = std::min(255.0, 255.0 * f);
  return static_cast<std::uint8_t>(q == quantise::truncate ? v : std::floor(v + 0.5));
}

inline texel ssbump_texel(const vec3<float>& D, quantise q = quantise::truncate) noexcept {
  return {to_unorm8(D.x, q), to_unorm8(D.y, q), to_unorm8(D.z, q)};
}

}  // namespace gsdot3::valve
