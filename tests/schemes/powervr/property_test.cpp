// tests/schemes/powervr/property_test.cpp — rapidcheck laws of the bump unit: the identity within the
// a-priori bound, and the output non-increasing in the light intensity S_l up to twice that bound
// (the exact value (1 − S_l) + S_l·N·L is non-increasing in S_l since N·L ≤ 1).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bounds.hpp"
#include "powervr/encode.hpp"
#include "powervr/texture.hpp"

namespace gsdot3::schemes::powervr {
namespace {

constexpr auto a = azimuth_scale::flycast_255;

double exact(bump_texel t, double S_l, double T, int Q) {
  const glm::dvec3 N = decode_normal(t, a);
  const double q = azimuth_of(Q, a);
  const double NL = N.x * std::cos(T) * std::cos(q) + N.y * std::cos(T) * std::sin(q) + N.z * std::sin(T);
  return 255.0 * std::clamp((1.0 - S_l) + S_l * NL, 0.0, 1.0);
}

int output(bump_texel t, double S_l, double T, int Q, precision p) {
  offset_colour k = offset_nearest({S_l, T, azimuth_of(Q, a)}, a);
  k.Q = static_cast<std::uint8_t>(Q);
  return intensity(t, k, a, p);
}

RC_GTEST_PROP(PowervrProperty, IdentityWithinTheBound,
              (std::uint16_t texel, std::uint8_t Q, std::uint16_t t16, std::uint16_t s16)) {
  const double T = t16 / 65535.0 * std::numbers::pi / 2, S_l = s16 / 65535.0;
  const auto t = bump_texel::unpack(texel);
  for (auto p : all_precisions)
    RC_ASSERT(std::abs(output(t, S_l, T, Q, p) - exact(t, S_l, T, Q)) <= test::identity_error_bound(p));
}

RC_GTEST_PROP(PowervrProperty, NonIncreasingInLightIntensity,
              (std::uint16_t texel, std::uint8_t Q, std::uint16_t t16, std::uint16_t s1, std::uint16_t s2)) {
  const double T = t16 / 65535.0 * std::numbers::pi / 2;
  const double lo = std::min(s1, s2) / 65535.0, hi = std::max(s1, s2) / 65535.0;
  const auto t = bump_texel::unpack(texel);
  RC_ASSERT(exact(t, hi, T, Q) <= exact(t, lo, T, Q) + 1e-9);
  for (auto p : all_precisions)
    RC_ASSERT(output(t, hi, T, Q, p) <= output(t, lo, T, Q, p) + 2 * test::identity_error_bound(p));
}

RC_GTEST_PROP(PowervrProperty, EncoderRoundTripIsStable, (std::uint16_t texel)) {
  // A texel decoded and encoded again (nearest, same convention) is the same texel, unless it is
  // flat (S = 255, every R the same normal).
  const auto t = bump_texel::unpack(texel);
  RC_PRE(t.S != 255);
  for (auto sc : {azimuth_scale::flycast_255, azimuth_scale::kos_256}) {
    RC_PRE(t.R < azimuth_steps(sc));
    RC_ASSERT(encode_normal(decode_normal(t, sc), texel_rounding::nearest, sc) == t);
  }
}

}  // namespace
}  // namespace gsdot3::schemes::powervr
