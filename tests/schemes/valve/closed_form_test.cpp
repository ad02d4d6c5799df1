// tests/schemes/valve/closed_form_test.cpp — the basis, the shader float formats and both shader
// paths against closed forms worked out by hand (or written another way, e.g. Parseval's identity).
#include <gtest/gtest.h>

#include <cmath>

#include "valve/basis.hpp"
#include "valve/decode.hpp"
#include "valve/encode.hpp"
#include "valve/evaluate.hpp"
#include "valve/q23.hpp"

namespace gsdot3::valve {
namespace {

TEST(ValveBasis, ConstantsAreTheNearestDoubles) {
  // In long double (64-bit significand), then rounded once to double.
  EXPECT_EQ(sqrt_2_3, static_cast<double>(std::sqrt(2.0L / 3.0L)));
  EXPECT_EQ(inv_sqrt2, std::sqrt(0.5));  // 0.5 is exact, sqrt correctly rounded
  EXPECT_EQ(inv_sqrt3, static_cast<double>(1.0L / std::sqrt(3.0L)));
  EXPECT_EQ(inv_sqrt6, static_cast<double>(1.0L / std::sqrt(6.0L)));
}

TEST(ValveBasis, ExactFieldValuesMatchTheDoubles) {
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(exact_basis_q23[i].x.value(), exact_basis[i].x, 1e-15);
    EXPECT_NEAR(exact_basis_q23[i].y.value(), exact_basis[i].y, 1e-15);
    EXPECT_NEAR(exact_basis_q23[i].z.value(), exact_basis[i].z, 1e-15);
    EXPECT_NEAR(printed_basis_q23[i].x.value(), printed_basis[i].x, 1e-15);
    EXPECT_NEAR(printed_basis_q23[i].z.value(), printed_basis[i].z, 1e-15);
  }
}

TEST(ValveBasis, GramMatricesByHand) {
  // Source: B0·B1 = −√(2/3)/√6 + 0 + 1/3 = −1/3 + 1/3 = 0; B1·B2 = 1/6 − 1/2 + 1/3 = 0; |B_i|² = 1.
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_EQ(dot(exact_basis_q23[i], exact_basis_q23[j]), q23::rational(i == j ? 1 : 0)) << i << j;
  // Eq. (1) as printed: B0 = B1 (product 1), B0·B2 = √2/(√6·√3) + 1/3 = 1/3 + 1/3 = 2/3.
  const auto& P = printed_basis_q23;
  EXPECT_EQ(dot(P[0], P[1]), q23::rational(1));
  EXPECT_EQ(dot(P[0], P[2]), q23::rational(2, 3));
  EXPECT_EQ(dot(P[1], P[2]), q23::rational(2, 3));
  EXPECT_EQ(dot(P[2], P[2]), q23::rational(1));
}

TEST(ValveShaderFloat, Fp24RoundsToSeventeenBitsTiesToEven) {
  EXPECT_EQ(round_fp24(1.0 + std::ldexp(1.0, -17)), 1.0);                             // tie → even (down)
  EXPECT_EQ(round_fp24(1.0 + 3 * std::ldexp(1.0, -17)), 1.0 + std::ldexp(1.0, -15));  // tie → even (up)
  EXPECT_EQ(round_fp24(1.0 + std::ldexp(1.0, -16)), 1.0 + std::ldexp(1.0, -16));      // representable
  EXPECT_EQ(round_fp24(1.0 / 3.0), 87381.0 / 262144.0);  // round(2^18/3) = 87381, a 17-bit significand
  EXPECT_EQ(round_fp24(-1.0 / 3.0), -87381.0 / 262144.0);
  EXPECT_EQ(round_fp24(2.0 - std::ldexp(1.0, -20)), 2.0);  // carries into the exponent
  EXPECT_EQ(rounded(precision::fp32, 1.0 / 3.0), static_cast<double>(1.0f / 3.0f));
}

// The flat texel (128, 128, 255) encodes N = (1/255, 1/255, 1). All N·B_i > 0, so by Parseval
// Σ (N·B_i)² = |N|² = 1 + 2/255², and D_i = (N·B_i)² / |N|².
TEST(ValveClosedForm, FlatTexelWeights) {
  const double e = 1.0 / 255.0, len2 = 1.0 + 2.0 * e * e;
  const double p0 = sqrt_2_3 * e + inv_sqrt3, p1 = (inv_sqrt2 - inv_sqrt6) * e + inv_sqrt3,
               p2 = -(inv_sqrt2 + inv_sqrt6) * e + inv_sqrt3;
  vec3<double> D;
  ASSERT_TRUE(exact_weights(encoded_normal({128, 128, 255}), D));
  EXPECT_NEAR(D.x, p0 * p0 / len2, 1e-15);
  EXPECT_NEAR(D.y, p1 * p1 / len2, 1e-15);
  EXPECT_NEAR(D.z, p2 * p2 / len2, 1e-15);
  // The exactly flat normal: (1/√3)² each over 1.
  ASSERT_TRUE(exact_weights({0, 0, 1}, D));
  EXPECT_NEAR(D.x, 1.0 / 3.0, 1e-16);
  EXPECT_NEAR(D.y, 1.0 / 3.0, 1e-16);
  EXPECT_NEAR(D.z, 1.0 / 3.0, 1e-16);
  // The shader (fp32 and fp24) lights with unit lightmap i give D_i to within their precision.
  for (precision p : {precision::fp32, precision::fp24}) {
    const shader_arith a{p};
    const double tol = p == precision::fp32 ? 1e-6 : 1e-4;
    EXPECT_NEAR(rnm_diffuse(a, {128, 128, 255}, {1, 0, 0}), p0 * p0 / len2, tol) << name(p);
    EXPECT_NEAR(rnm_diffuse(a, {128, 128, 255}, {0, 1, 0}), p1 * p1 / len2, tol) << name(p);
    EXPECT_NEAR(rnm_diffuse(a, {128, 128, 255}, {0, 0, 1}), p2 * p2 / len2, tol) << name(p);
  }
}

// normal2ssbump of (128, 128, 255): 255·D = (85.943, 85.343, 83.714) by the formula above, which
// Source's truncating writer stores as (85, 85, 83); rounding would give (86, 85, 84).
TEST(ValveClosedForm, Normal2SsbumpFlatTexel) {
  const vec3<float> D = normal2ssbump({128, 128, 255});
  EXPECT_NEAR(255.0 * D.x, 85.943, 1e-3);
  EXPECT_NEAR(255.0 * D.y, 85.343, 1e-3);
  EXPECT_NEAR(255.0 * D.z, 83.714, 1e-3);
  EXPECT_EQ(ssbump_texel(D), (texel{85, 85, 83}));
  EXPECT_EQ(ssbump_texel(D, quantise::nearest), (texel{86, 85, 84}));
  // SSBump evaluation of that texel with unit lightmaps returns the texel / 255 exactly in fp32.
  EXPECT_EQ(ssbump_diffuse(shader_arith{precision::fp32}, {85, 85, 83}, {1, 0, 0}),
            static_cast<double>(85.0f / 255.0f));
}

// A normal on basis vector B_i: B_j·B_i = 0 for j ≠ i, so D = e_i.
TEST(ValveClosedForm, NormalsOnTheBasisVectors) {
  for (std::size_t i = 0; i < 3; ++i) {
    vec3<double> D;
    ASSERT_TRUE(exact_weights(exact_basis[i], D));
    EXPECT_NEAR(D.x, i == 0, 1e-15);
    EXPECT_NEAR(D.y, i == 1, 1e-15);
    EXPECT_NEAR(D.z, i == 2, 1e-15);
  }
  // Their nearest RGB8 texels: round(127.5·B + 127.5) by hand: B0 → (232, 128, 201),
  // B1 → (75, 218, 201), B2 → (75, 37, 201).
  EXPECT_EQ(encode_normal_rgb8(exact_basis[0]), (texel{232, 128, 201}));
  EXPECT_EQ(encode_normal_rgb8(exact_basis[1]), (texel{75, 218, 201}));
  EXPECT_EQ(encode_normal_rgb8(exact_basis[2]), (texel{75, 37, 201}));
  // On those texels RNM puts almost all weight on channel i.
  const shader_arith a{precision::fp32};
  EXPECT_GT(rnm_diffuse(a, {232, 128, 201}, {1, 0, 0}), 0.99);
  EXPECT_GT(rnm_diffuse(a, {75, 218, 201}, {0, 1, 0}), 0.99);
  EXPECT_GT(rnm_diffuse(a, {75, 37, 201}, {0, 0, 1}), 0.99);
}

// (128, 128, 0) encodes N = (1/255, 1/255, −1): N·B0 = √(2/3)/255 − 1/√3 < 0 and likewise for B1, B2,
// so Σd = 0 and Listing 1 computes 0/0.
TEST(ValveClosedForm, ZeroSumTexel) {
  vec3<double> D;
  EXPECT_FALSE(exact_weights(encoded_normal({128, 128, 0}), D));
  for (precision p : {precision::fp32, precision::fp24})
    EXPECT_TRUE(std::isnan(rnm_diffuse(shader_arith{p}, {128, 128, 0}, {1, 1, 1}))) << name(p);
  EXPECT_TRUE(std::isnan(normal2ssbump({128, 128, 0}).x));
  EXPECT_EQ(ssbump_texel(normal2ssbump({128, 128, 0})), (texel{0, 0, 0}));  // NaN → 0 in our writer
}

TEST(ValveClosedForm, ReconstructionOfBasisAndFlatNormals) {
  for (std::size_t i = 0; i < 3; ++i) {
    const vec3<double> e{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
    const auto n = reconstruct_normal(e);
    EXPECT_NEAR(n.x, exact_basis[i].x, 1e-15);
    EXPECT_NEAR(n.y, exact_basis[i].y, 1e-15);
  }
  const auto f = reconstruct_normal({1.0 / 3, 1.0 / 3, 1.0 / 3});
  EXPECT_NEAR(f.z, 1.0, 1e-15);
  // N = (√(1/2), 0, √(1/2)): N·B = (0.5774 + 0.4082, −0.2887 + 0.4082, same) — the square-root inverse returns N.
  const vec3<double> n{inv_sqrt2, 0, inv_sqrt2};
  vec3<double> D;
  ASSERT_TRUE(exact_weights(n, D));
  const auto r = reconstruct_normal_sqrt(D);
  EXPECT_NEAR(r.x, n.x, 1e-12);
  EXPECT_NEAR(r.z, n.z, 1e-12);
}

}  // namespace
}  // namespace gsdot3::valve
