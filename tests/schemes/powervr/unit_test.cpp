// tests/schemes/powervr/unit_test.cpp — the bump unit's closed forms, the encoders' documented
// outputs, round trips within the quantisation bound (derived here, not taken from the code).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "powervr/encode.hpp"
#include "powervr/evaluate.hpp"
#include "powervr/texture.hpp"

namespace gsdot3::schemes::powervr {
namespace {

constexpr double pi = std::numbers::pi;
constexpr std::array<azimuth_scale, 2> scales{azimuth_scale::flycast_255, azimuth_scale::kos_256};

TEST(PowervrUnit, StraightOutIsK1PlusK2) {
  // S = 255: sin S = 1, cos S = 0, so the output is min(K1 + K2, 255) whatever K3, Q and R are.
  for (auto a : scales)
    for (auto p : all_precisions)
      for (int k1 = 0; k1 < 256; k1 += 3)
        for (int k2 = 0; k2 < 256; k2 += 5)
          for (int k3 : {0, 77, 255})
            for (int q : {0, 100, 255}) {
              const offset_colour k{static_cast<std::uint8_t>(k1), static_cast<std::uint8_t>(k2),
                                    static_cast<std::uint8_t>(k3), static_cast<std::uint8_t>(q)};
              ASSERT_EQ(intensity({255, 17}, k, a, p), std::min(k1 + k2, 255))
                  << name(p) << " " << name(a) << " K = " << k.packed();
            }
}

TEST(PowervrUnit, AzimuthEqualToQLeavesK3CosS) {
  // R = Q, K1 = K2 = 0: the output is K3·cos(S·π/510), rounded: float within 1/2 (+ float error),
  // fixedB within 1/2 + K3·2^−(B+1) (the cos S table entry is off by at most half a table step).
  for (auto a : scales)
    for (auto p : all_precisions)
      for (int S = 0; S < 256; ++S)
        for (int k3 = 0; k3 < 256; k3 += 17)
          for (int q : {0, 64, 200}) {
            const offset_colour k{0, 0, static_cast<std::uint8_t>(k3), static_cast<std::uint8_t>(q)};
            const double exact = k3 * std::cos(S * pi / 510.0);
            const double bound = p == precision::float32 ? 0.5 + 1e-3 : 0.5 + k3 * std::ldexp(0.5, -table_bits(p));
            ASSERT_LE(
                std::abs(intensity({static_cast<std::uint8_t>(S), static_cast<std::uint8_t>(q)}, k, a, p) - exact),
                bound)
                << name(p) << " S = " << S << " K3 = " << k3;
          }
}

TEST(PowervrUnit, FlycastTablesAreTheFloatFormulaBitForBit) {
  for (auto a : scales) {
    const flycast_tables t(a);
    for (int i = 0; i < 65536; i += 7)
      for (std::uint32_t kw : {0x00FF0010u, 0x4080C0F0u, 0xFF00FFFFu, 0x10203040u}) {
        const offset_colour k{static_cast<std::uint8_t>(kw >> 24), static_cast<std::uint8_t>(kw >> 16),
                              static_cast<std::uint8_t>(kw >> 8), static_cast<std::uint8_t>(kw)};
        const auto tx = bump_texel::unpack(static_cast<std::uint16_t>(i));
        ASSERT_EQ(t.value(tx, k), intensity_flycast(tx, k, a)) << i;
      }
  }
}

TEST(PowervrUnit, PackBumpMatchesKallistiOSExample) {
  // A KallistiOS example program (found with find_string "pvr_pack_bump(.5f, F_PI / 2, 0)") states:
  // "Zero-angle bump texels with overhead lighting produce K1 = 128/255 ... half-bright".
  const offset_colour k = pvr_pack_bump(0.5f, 3.1415926f / 2, 0.0f);
  EXPECT_EQ(k.K1, 128);
  EXPECT_EQ(k.K2, 127);  // (u8)(127·sin(π/2))
  EXPECT_EQ(k.K3, 0);
  EXPECT_EQ(k.Q, 0);
  for (auto p : all_precisions) EXPECT_EQ(intensity({0, 0}, k, azimuth_scale::flycast_255, p), 128) << name(p);
  // h = 1, t = 0: K1 = ~255 = 0, K2 = 0, K3 = 255; q just below 2π truncates to 254 (255·(1 − ε)).
  EXPECT_EQ(pvr_pack_bump(1.0f, 0.0f, 6.28f).packed(), 0x0000FFFEu);
}

TEST(PowervrUnit, SdkArctanOctantsAndEndpoints) {
  EXPECT_EQ(sdk_quadratic_arctan(0.0), 0.0);
  EXPECT_NEAR(sdk_quadratic_arctan(1.0), 32.0, 1e-12);  // 45° = 32/256 turn
  // The axis directions in the SDK's frame (y = normal, azimuth in x-z): 0°, 90°, 180°, 270° = 0, 64, 128, 192.
  EXPECT_EQ(fxyz_light_dir_to_skk(1, 0, 0).s, 0);
  EXPECT_EQ(fxyz_light_dir_to_skk(0, 0, 1).s, 64);
  EXPECT_EQ(fxyz_light_dir_to_skk(-1, 0, 0).s, 128);
  EXPECT_EQ(fxyz_light_dir_to_skk(0, 0, -1).s, 192);
  EXPECT_EQ(fxyz_light_dir_to_skk(1, 0, 1).s, 32);
  // Straight up: sin T = 1 → 256 → clamped to 255; cos T = 0.
  const skk up = fxyz_light_dir_to_skk(0, 1, 0);
  EXPECT_EQ(up.sinT, 255);
  EXPECT_EQ(up.cosT, 0);
  // Below the surface (y < 0): y is replaced by 0.00001, so the light lies in the plane.
  EXPECT_EQ(fxyz_light_dir_to_skk(1, -0.5f, 0).cosT, 255);
}

TEST(PowervrUnit, SdkStandardMethodOffsetColour) {
  // KMBumpShade, standard method: K1 = 0, K2 = 255, K3 = skk[2], Q = skk[0]. A light in the surface
  // along x: cos T = 1 → 256 → 255, azimuth 0; on the texel lying along x (S = 0, R = 0) the output is
  // K3·cos 0·cos 0 = 255, and on the flat texel (S = 255) it is K2 = 255.
  const offset_colour k = sdk_standard(fxyz_light_dir_to_skk(1, 0, 0));
  EXPECT_EQ(k.packed(), 0x00FFFF00u);
  for (auto p : all_precisions) {
    EXPECT_EQ(intensity({0, 0}, k, azimuth_scale::kos_256, p), 255) << name(p);
    EXPECT_EQ(intensity({255, 0}, k, azimuth_scale::kos_256, p), 255) << name(p);
    EXPECT_EQ(intensity({0, 128}, k, azimuth_scale::kos_256, p), 0) << name(p);  // R = 180°: −255, clamped
  }
}

TEST(PowervrUnit, SeedPrintedQLosesTheQuadrant) {
  const glm::dvec3 P = glm::normalize(glm::dvec3(-1, 1, 1));  // azimuth 135°
  EXPECT_NEAR(seed_atan2(P, 1).Q, 0.75 * pi, 1e-12);
  EXPECT_NEAR(seed_printed(P, 1).Q, 1.75 * pi, 1e-12);  // arctan(−1) = −45° → 315°
  EXPECT_NEAR(seed_printed(P, 1).T, std::asin(1 / std::sqrt(3.0)), 1e-12);
}

TEST(PowervrUnit, KallistiOSTexelEncoderExamples) {
  // pxlFloattoSpherical: straight out → altitude 0 → 0 ^ 0xFF = 255; in-plane → 255 ^ 0xFF = 0.
  EXPECT_EQ(encode_normal({0, 0, 1}, texel_rounding::kallistios, azimuth_scale::flycast_255), (bump_texel{255, 0}));
  EXPECT_EQ(encode_normal({1, 0, 0}, texel_rounding::kallistios, azimuth_scale::flycast_255), (bump_texel{0, 0}));
  EXPECT_EQ(encode_normal({0, 1, 0}, texel_rounding::kallistios, azimuth_scale::flycast_255),
            (bump_texel{0, 64}));  // 63.75 + 0.5
  EXPECT_EQ(encode_normal({-1, 0, 0}, texel_rounding::kallistios, azimuth_scale::flycast_255),
            (bump_texel{0, 128}));  // 127.5 + 0.5
  EXPECT_EQ(encode_normal({0, 1, 0}, texel_rounding::nearest, azimuth_scale::kos_256), (bump_texel{0, 64}));
  EXPECT_EQ(encode_normal({0, 0, 0}, texel_rounding::nearest, azimuth_scale::kos_256), (bump_texel{255, 0}));
}

TEST(PowervrUnit, RoundTripsWithinTheQuantisationBound) {
  // Nearest: |Δe| ≤ (π/2)/255/2 and |Δa| ≤ π/steps; the angle between the two directions is at most
  // |Δe| + cos(e)·|Δa| (go along the meridian, then along a parallel, which is no shorter than the
  // great circle). KallistiOS rounds the polar angle, so the same bound holds, plus float error.
  for (auto r : {texel_rounding::kallistios, texel_rounding::nearest})
    for (auto a : scales) {
      const auto dec = r == texel_rounding::kallistios ? azimuth_scale::flycast_255 : a;
      const double da = pi / azimuth_steps(dec), de = pi / 1020.0;
      for (int ie = 0; ie <= 90; ++ie)
        for (int ia = 0; ia < 360; ++ia) {
          const double e = ie * pi / 180.0, az = ia * pi / 180.0 + 0.013;
          const glm::dvec3 n{std::cos(e) * std::cos(az), std::cos(e) * std::sin(az), std::sin(e)};
          const glm::dvec3 back = decode_normal(encode_normal(n, r, a), dec);
          const double angle = std::acos(std::clamp(glm::dot(n, back), -1.0, 1.0));
          ASSERT_LE(angle, de + std::cos(std::max(0.0, e - de)) * da + 1e-5)
              << name(r) << " e = " << ie << " az = " << ia;
        }
    }
}

}  // namespace
}  // namespace gsdot3::schemes::powervr
