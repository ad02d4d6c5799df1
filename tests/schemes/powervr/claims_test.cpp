// tests/schemes/powervr/claims_test.cpp — the seed 004 catalogue rows, their verdicts and figures
// against independent references: closed forms derived here, or a different method of search.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bounds.hpp"
#include "proofs/claim.hpp"
#include "proofs/runner.hpp"

namespace p = gsdot3::proofs;
namespace pvr = gsdot3::schemes::powervr;

namespace {
p::outcome run(std::string_view id) {
  const auto* c = p::find_claim(id);
  if (c == nullptr) throw std::runtime_error("no claim " + std::string(id));
  return p::run_claim(*c, {}, p::run_config{}).result;
}
constexpr double pi = std::numbers::pi;

TEST(PowervrClaims, SectionIsSeed004) {
  for (auto id : {"powervr.identity", "powervr.flipped-uv"})
    EXPECT_EQ(p::find_claim(id)->section, "Seed 004: Imagination Technologies 1999, Bump Mapping Tricks for Series 2");
}

TEST(PowervrClaims, IdentityProvenInDouble) {
  const auto o = run("powervr.identity");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(o.domain_size, 65536u * 10 * 8 * 2);
  EXPECT_LT(o.real("max_abs_difference"), 1e-12);
}

TEST(PowervrClaims, Identity8BitWithinTheDerivedBound) {
  const auto o = run("powervr.identity-8bit");
  EXPECT_EQ(o.result, p::verdict::bound);
  EXPECT_EQ(o.domain_size, 65536u * 8 * 7 * 4);
  for (auto pr : pvr::all_precisions) {
    const std::string n = pvr::name(pr);
    EXPECT_LE(o.real(n + ".max_abs"), pvr::test::identity_error_bound(pr)) << n;
    EXPECT_LE(o.real(n + ".rmse"), o.real(n + ".max_abs")) << n;
    EXPECT_GE(o.real(n + ".max_abs"), 0.5) << n;  // the output rounding alone reaches ~1/2 somewhere
  }
}

TEST(PowervrClaims, PrintedArctanTurnsHalfTheLightsBy180Degrees) {
  const auto o = run("powervr.q-quadrant");
  // Azimuths (i + 0.5)·0.1°: Px < 0 exactly for 90° < φ < 270°, i.e. i = 900..2699.
  EXPECT_EQ(o.result, p::verdict::refuted);
  EXPECT_EQ(o.counterexamples, 1800u);
  EXPECT_NEAR(o.real("max_azimuth_error_deg"), 180.0, 1e-9);
  EXPECT_EQ(o.integer("atan2.wrong_azimuths"), 0);
}

TEST(PowervrClaims, AzimuthScaleMismatchClosedForms) {
  const auto o = run("powervr.azimuth-255-256");
  EXPECT_DOUBLE_EQ(o.real("pvrtex.max_azimuth_error_deg"), 360.0 / 256.0);  // 255·360/255 − 255·360/256
  EXPECT_EQ(o.integer("pvrtex.at_R"), 255);
  // max over r of |cos(r − a) − cos(r − b)| = 2|sin((a − b)/2)|, at Q = 255: a − b = 2π/256; the sweep's
  // r are discrete, so it reaches the supremum only approximately (within 255·(1 − cos(π/255))).
  const double sup = 255.0 * 2.0 * std::sin(pi / 256.0);
  EXPECT_LE(o.real("offset_q.max_output_error"), sup + 1e-9);
  EXPECT_GE(o.real("offset_q.max_output_error"), sup * std::cos(pi / 255.0) - 1e-9);
}

TEST(PowervrClaims, SdkQuadraticArctanAgainstNewtonOnTheDerivative) {
  // e(s) = s(43.562812 − 11.562812 s) − (128/π) atan s; e'(s) = 43.562812 − 23.125624 s − (128/π)/(1 + s²).
  // Its extremes in (0, 1) are roots of e': found by bisection here, independently of the claim's grid.
  auto e = [](double s) { return (-11.562812 * s + 43.562812) * s - 128.0 / pi * std::atan(s); };
  auto de = [](double s) { return 43.562812 - 23.125624 * s - 128.0 / pi / (1.0 + s * s); };
  double best = std::max(std::abs(e(0.0)), std::abs(e(1.0)));
  for (int k = 0; k < 100; ++k) {  // brackets of width 0.01
    double lo = k / 100.0, hi = (k + 1) / 100.0;
    if ((de(lo) > 0) == (de(hi) > 0)) continue;
    for (int it = 0; it < 200; ++it) {
      const double mid = (lo + hi) / 2;
      ((de(mid) > 0) == (de(lo) > 0) ? lo : hi) = mid;
    }
    best = std::max(best, std::abs(e(lo)));
  }
  const auto o = run("powervr.sdk-arctan");
  EXPECT_NEAR(o.real("quadratic.max_error_256ths"), best, 1e-9);
  EXPECT_NEAR(o.real("quadratic.max_error_deg"), best * 360.0 / 256.0, 1e-9);
  // The whole routine: quadratic error + at most half a 1/256 turn of rounding, except at the wrap.
  EXPECT_LE(o.real("routine.max_q_error_deg_below_358.6"), (best + 0.5) * 360.0 / 256.0 + 1e-6);
  EXPECT_NEAR(o.real("routine.max_q_error_deg"), 360.0 / 256.0 - 0.01, 0.011);  // 359.99° clamped to 255/256 turn
}

TEST(PowervrClaims, PackBumpTruncatesByLessThanOneStep) {
  // (u8)(x) ≤ round(x) ≤ (u8)(x) + 1 for x ≥ 0; K1 = 255 − (u8)(255h) ≥ round(255 − 255h).
  const auto o = run("powervr.pack-bump");
  EXPECT_EQ(o.integer("K2.min"), -1);
  EXPECT_EQ(o.integer("K2.max"), 0);
  EXPECT_EQ(o.integer("K3.min"), -1);
  EXPECT_EQ(o.integer("K3.max"), 0);
  EXPECT_EQ(o.integer("Q.min"), -1);
  EXPECT_EQ(o.integer("Q.max"), 0);
  EXPECT_EQ(o.integer("K1.min"), 0);
  EXPECT_EQ(o.integer("K1.max"), 1);
}

TEST(PowervrClaims, FlippedUvFixLeavesQuantisationOnly) {
  const auto o = run("powervr.flipped-uv");
  EXPECT_EQ(o.result, p::verdict::proven);
  // Without the fix, texel (S, R) = (0, 0) under a light at azimuth 0°, 30° up: the mirrored normal is
  // (−1, 0, 0), so the truth is −255·cos 30°, the hardware gives +K3 = round(255·cos 30°).
  EXPECT_GE(o.real("nofix.max_error"), 255.0 * std::cos(pi / 6) + std::round(255.0 * std::cos(pi / 6)) - 1e-9);
  EXPECT_LE(o.real("fix.max_error"), std::sqrt(2.0) / 2 + pi * std::cos(pi / 6));
}

}  // namespace
