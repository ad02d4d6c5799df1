// tests/schemes/valve/claims_test.cpp — seed 001's catalogue rows against independent references,
// and the whole-domain sweeps the catalogue runs on a sub-lattice: all 2^24 RGB8 texels (precision,
// reconstruction) and a 65×65 normal grid (RNM filtering). Figures are printed for the record.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "proofs/claim.hpp"
#include "proofs/runner.hpp"
#include "proofs/valve_sweeps.hpp"

namespace p = gsdot3::proofs;
namespace vs = gsdot3::proofs::valve_sweeps;

namespace {

p::outcome run(std::string_view id) {
  const auto* c = p::find_claim(id);
  if (c == nullptr) throw std::runtime_error("no claim " + std::string(id));
  return p::run_claim(*c, {}, p::run_config{}).result;
}

void print(const char* what, const vs::stat& s) {
  std::printf("%-44s max %.6f  mean %.6f  rmse %.6f  (n = %llu)\n", what, s.max, s.mean(), s.rmse(),
              static_cast<unsigned long long>(s.n));
}

TEST(ValveClaims, EveryRowOfTheSectionRuns) {
  const char* ids[] = {
      "valve.eq1-not-orthonormal", "valve.basis-orthonormal", "valve.float-literals",       "valve.zero-sum",
      "valve.flat-normal",         "valve.precision",         "valve.ssbump-filter-linear", "valve.rnm-filter",
      "valve.reconstruct-normal"};
  std::size_t n = 0;
  for (const auto& c : p::catalogue()) n += c.section.starts_with("Seed 001");
  EXPECT_EQ(n, std::size(ids));
  for (auto id : ids) ASSERT_NE(p::find_claim(id), nullptr) << id;
}

// By hand: eq. (1) as printed has B0 = B1 (product 1) and B0·B2 = B1·B2 = 1/3 + 1/3 = 2/3.
TEST(ValveClaims, Eq1AndSourceBasis) {
  const auto o = run("valve.eq1-not-orthonormal");
  EXPECT_EQ(o.result, p::verdict::refuted);
  EXPECT_EQ(o.counterexamples, 3u);
  EXPECT_DOUBLE_EQ(o.real("B0·B1"), 1.0);
  EXPECT_NEAR(o.real("B0·B2"), 2.0 / 3.0, 1e-15);
  EXPECT_EQ(run("valve.basis-orthonormal").result, p::verdict::proven);
}

// The literals' ulp offsets, counted by hand from the nearest floats of 1/√6 = 0.408248290463863,
// whose float neighbours are 2^-25 ≈ 2.98e-8 apart: 0.40824833512306213 − 0.408248290463863 ≈
// +4.47e-8 → +1 (nearest float is 0.408248305320739746); 0.40824821591377258 → −3.
TEST(ValveClaims, FloatLiterals) {
  const auto o = run("valve.float-literals");
  EXPECT_EQ(o.integer("B1.x_ulps"), 1);
  EXPECT_EQ(o.integer("B2.x_ulps"), -3);
  EXPECT_EQ(o.integer("B0.x_ulps"), 0);
  EXPECT_LT(o.real("bound_abs_sum_sq_minus_1"), 1e-6);
}

// Independent count of the zero-sum texels: long double evaluation of 255·N·B_i (no texel is within
// 1e-9 of a sign change: checked here, so the long double signs are exact).
TEST(ValveClaims, ZeroSumCountByLongDouble) {
  const long double s2 = std::sqrt(2.0L / 3.0L), i2 = 1 / std::sqrt(2.0L), i3 = 1 / std::sqrt(3.0L),
                    i6 = 1 / std::sqrt(6.0L);
  std::uint64_t count = 0, close = 0;
  for (int r = 0; r < 256; ++r)
    for (int g = 0; g < 256; ++g)
      for (int b = 0; b < 256; ++b) {
        const long double x = 2 * r - 255, y = 2 * g - 255, z = 2 * b - 255;
        const long double d0 = s2 * x + i3 * z, d1 = -i6 * x + i2 * y + i3 * z, d2 = -i6 * x - i2 * y + i3 * z;
        close += std::fabs(d0) < 1e-9L || std::fabs(d1) < 1e-9L || std::fabs(d2) < 1e-9L;
        count += d0 < 0 && d1 < 0 && d2 < 0;
      }
  EXPECT_EQ(close, 0u);
  const auto o = run("valve.zero-sum");
  EXPECT_EQ(o.result, p::verdict::refuted);
  EXPECT_EQ(o.counterexamples, count);
  EXPECT_EQ(o.integer("zero_sum_normal2ssbump_not_nan"), 0);
  EXPECT_EQ(o.integer("zero_sum_not_nan_fp32"), 0);
  std::printf("zero-sum texels: %llu of 2^24\n", static_cast<unsigned long long>(count));
}

// The four texels nearest the flat normal, by hand (see closed_form_test.cpp for the derivation):
// 0x8080ff → (85, 85, 83) sum 253; 0x7f7fff → (84, 84, 86) sum 254.
TEST(ValveClaims, FlatNormal) {
  const auto o = run("valve.flat-normal");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(o.integer("normal2ssbump_0x8080ff_sum"), 253);
  EXPECT_EQ(o.integer("normal2ssbump_0x7f7fff_sum"), 254);
  EXPECT_EQ(o.integer("height2ssbump_flat_texels_147"), 64);
}

// SSBump filtering is proven exact; RNM's filtered weights differ (the worst pair is opposite normals).
TEST(ValveClaims, Filtering) {
  EXPECT_EQ(run("valve.ssbump-filter-linear").result, p::verdict::proven);
  const auto o = run("valve.rnm-filter");
  EXPECT_GT(o.real("err_all_max"), 100.0);
  const auto big = vs::rnm_filtering_sweep(64, {});
  std::printf("RNM filtering, 65×65 grid: %llu texels, %llu pairs × 15 weights; over 0.5/255: %llu, over 1/255: %llu\n",
              static_cast<unsigned long long>(big.texels), static_cast<unsigned long long>(big.pairs),
              static_cast<unsigned long long>(big.over_half), static_cast<unsigned long long>(big.over_one));
  print("rnm filter err (1/255), all pairs", big.all);
  print("rnm filter err (1/255), pairs within 10°", big.near);
  for (int w = 1; w <= 15; ++w) {
    char label[64];
    std::snprintf(label, sizeof label, "rnm filter err, w = %d/16", w);
    print(label, big.by_weight[w - 1]);
  }
  std::printf("worst pair 0x%06x 0x%06x w = %d/16\n", big.worst_a, big.worst_b, big.worst_w);
  // The 65×65 grid contains the catalogue's 17×17 grid (x = −1 + 2i/16 = −1 + 2·4i/64).
  EXPECT_GE(big.all.max, o.real("err_all_max"));
}

// All 2^24 texels. Bound from an argument: normal2ssbump computes eq. (3) on the same unnormalised
// N = 2t − 1 in float as the RNM shader does in fp32, so its float weights are off the exact ones by
// what RNM fp32 is off (saturate clips N·B_i > 1 when |N| > 1, plus float rounding); its writer then
// adds < 1/255 (truncation) or ≤ 1/2 of 1/255 (rounding); the shader's t/255 adds < 1e-4.
TEST(ValveClaims, PrecisionOverAllTexels) {
  const auto r = vs::precision_sweep(vs::texel_domain::all(), {});
  EXPECT_EQ(r.domain, 1u << 24);
  std::printf("texels %llu, zero-sum %llu, unit texels %llu, normal2ssbump changed by the exact float basis %llu\n",
              static_cast<unsigned long long>(r.domain), static_cast<unsigned long long>(r.zero_sum),
              static_cast<unsigned long long>(r.unit_texels), static_cast<unsigned long long>(r.literal_changes));
  const char* names[4] = {"rnm fp32", "rnm fp24 (rne)", "ssbump normal2ssbump trunc", "ssbump normal2ssbump nearest"};
  for (int p = 0; p < 4; ++p) {
    print((std::string(names[p]) + ", all texels").c_str(), r.err[p][0]);
    print((std::string(names[p]) + ", unit texels").c_str(), r.err[p][1]);
    std::printf("  NaN results: %llu\n", static_cast<unsigned long long>(r.nan[p]));
  }
  print("reconstruct Σ D·B (deg), all", r.reconstruct[0][0]);
  print("reconstruct Σ D·B (deg), cone", r.reconstruct[0][1]);
  print("reconstruct Σ √D·B (deg), all", r.reconstruct[1][0]);
  print("reconstruct Σ √D·B (deg), cone", r.reconstruct[1][1]);
  EXPECT_LT(r.err[2][1].max, 1.0 + r.err[0][1].max + 1e-4);
  EXPECT_LT(r.err[3][1].max, 0.5 + r.err[0][1].max + 1e-4);
  EXPECT_EQ(r.nan[0], 0u);
  // The finding: on unit texels the 8-bit SSBump path is less precise than RNM's, not more.
  EXPECT_GT(r.err[2][1].rmse(), r.err[0][1].rmse());
  EXPECT_GT(r.err[3][1].rmse(), r.err[0][1].rmse());
}

}  // namespace
