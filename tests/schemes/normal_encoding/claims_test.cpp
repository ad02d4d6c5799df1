// The seed 002 rows of the catalogue, checked against independent references: integer counts of the
// codes inside the unit disc, the singular inputs worked out by hand, and published sampled maxima
// (which a supremum can never be below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "normal_encoding/seed_2009.hpp"
#include "proofs/claim.hpp"
#include "proofs/runner.hpp"

namespace p = gsdot3::proofs;

namespace {
p::outcome run(std::string_view id) {
  const auto* c = p::find_claim(id);
  if (c == nullptr) throw std::runtime_error("no claim " + std::string(id));
  return p::run_claim(*c, {}, p::run_config{}).result;
}
int codes_in_disc() {  // (2i − 255)² + (2j − 255)² <= 255²
  int n = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j)
      if ((2 * i - 255) * (2 * i - 255) + (2 * j - 255) * (2 * j - 255) <= 255 * 255) ++n;
  return n;
}
}  // namespace

TEST(NormalEncodingClaims, CodesAgainstTheDiscCount) {
  const auto o = run("normal-encoding.codes");
  const int inside = codes_in_disc();
  for (auto m : {"xy", "spheremap", "cryengine3", "lambert", "view-space"}) {
    EXPECT_EQ(o.integer(std::string(m) + ".nan_inf"), 65536 - inside) << m;
    EXPECT_EQ(o.integer(std::string(m) + ".unit"), inside) << m;
  }
  EXPECT_EQ(o.integer("xy-sign.nan_inf"), 2 * (65536 - inside));
  for (auto m : {"octahedral", "octahedral-snorm", "stereographic", "spherical"})
    EXPECT_EQ(o.integer(std::string(m) + ".nan_inf"), 0) << m;
  // Distinct directions, counted by hand in exhaustive_test.cpp: octahedral 254² + 4·128 − 3,
  // spherical 254·255 + 2 (poles and the φ = ±π seam identified), stereographic all 65 536.
  EXPECT_EQ(o.integer("octahedral.distinct_directions"), 254 * 254 + 4 * 128 - 3);
  EXPECT_EQ(o.integer("spherical.distinct_directions"), 254 * 255 + 2);
  EXPECT_EQ(o.integer("stereographic.distinct_directions"), 65536);
  EXPECT_EQ(o.integer("lambert.distinct_directions"), inside);
}

TEST(NormalEncodingClaims, WorstCaseNotBelowPublishedSampledMaxima) {
  const auto o = run("normal-encoding.worst-case");
  EXPECT_EQ(o.result, p::verdict::bound);
  // liamtyler.github.io "octahedral analysis": 8+8 bits unorm nearest, 10^6 random directions: max 0.9465°.
  EXPECT_GE(o.real("octahedral.sup_deg"), 0.9465);
  EXPECT_LT(o.real("octahedral.sup_deg"), 1.0);
  // Precise is bounded by nearest's supremum and beats it on the sample.
  EXPECT_LT(o.real("octahedral-precise.sampled_max_deg"), o.real("octahedral.sampled_max_deg"));
  // #1 at (0, 0, −1): code (128, 128) decodes to (1/255, 1/255, sqrt(1 − 2/255²)): the angle is
  // 180° − atan(sqrt(2)/255 / sqrt(1 − 2/255²)) = 179.6822...°.
  EXPECT_NEAR(o.real("xy.sup_deg"),
              180 - std::atan(std::sqrt(2.0) / 255 / std::sqrt(1 - 2.0 / 65025)) * 180 / std::numbers::pi, 1e-6);
  for (auto m : {"spheremap", "cryengine3", "lambert"})
    EXPECT_GT(o.integer(std::string(m) + ".cells_nan_decode"), 0) << m;
}

TEST(NormalEncodingClaims, EquivalenceSingularitiesRanking) {
  EXPECT_EQ(run("normal-encoding.equivalence").result, p::verdict::proven);
  // Counterexamples worked out by hand: #1 the four equator axes (sqrt < 0) and (0,0,−1) (179.7°) = 5;
  // #2 the four equator axes = 4; sphere map and Lambert (0,0,−1) = 1 + 1; CryEngine 3 both poles = 2;
  // #8 (front hemisphere, z >= 0) the four equator axes = 4. The diagonals are all < 90° off. Total 17.
  const auto s = run("normal-encoding.singularities");
  EXPECT_EQ(s.result, p::verdict::refuted);
  EXPECT_EQ(s.counterexamples, 17u);
  const auto w = run("normal-encoding.xy-wrong-sign");
  EXPECT_LE(w.integer("wrong_z_sign"), 32768);  // the Fibonacci set has exactly N/2 points with z < 0
  EXPECT_GT(w.real("share_wrong_z_sign"), 0.45);
  const auto r = run("normal-encoding.ranking");
  ASSERT_EQ(r.witnesses.size(), 3u);
  EXPECT_NE(r.witnesses[0].substr(r.witnesses[0].find(':')), r.witnesses[1].substr(r.witnesses[1].find(':')));
}

TEST(NormalEncodingClaims, SeedMeasure2009) {
  // The seed's 2009 measure on faceted spheres. References: xyz stores the vector it is given, so
  // against that vector its error is 8-bit quantisation alone, 10·log10(3·255²) = 52.90 dB (uniform
  // error on ±1/255 per channel); against normalize(v) it also carries (1 − |v|) along v, so its MSE
  // per channel is E[(1 − |v|)²]/3 plus that quantisation (the two uncorrelated).
  namespace ne = gsdot3::normal_encoding;
  const auto o = run("normal-encoding.seed-2009-measure");
  EXPECT_EQ(o.result, p::verdict::bound);
  const double q2 = 1.0 / (3 * 255.0 * 255.0);
  double previous_spread = 1e9, previous_length = 0;
  for (const auto& t : ne::sphere_tessellations) {
    const std::string tag = "sphere" + std::to_string(t.rings) + "x" + std::to_string(t.segments);
    EXPECT_NEAR(o.real(tag + ".xyz.psnr"), 10 * std::log10(3.0 * 255 * 255), 0.1) << tag;
    double deficit = 0, length = 0;
    const auto pixels = ne::faceted_sphere_normals(t.rings, t.segments, ne::sphere_pixels);
    for (const auto& v : pixels) {
      deficit += (1 - ne::length(v)) * (1 - ne::length(v));
      length += ne::length(v);
    }
    deficit /= static_cast<double>(pixels.size());
    EXPECT_NEAR(o.real(tag + ".xyz.psnr_vs_unit"), -10 * std::log10(deficit / 3 + q2), 0.2) << tag;
    EXPECT_NEAR(o.real(tag + ".mean_length"), length / static_cast<double>(pixels.size()), 1e-12) << tag;
    EXPECT_GT(o.real(tag + ".mean_length"), previous_length) << tag;  // finer facets, longer normals
    previous_length = o.real(tag + ".mean_length");
    // The three methods that are one mapping for unit input score apart, less so as |v| nears 1.
    const double sph = o.real(tag + ".spheremap.psnr"), lam = o.real(tag + ".lambert.psnr"),
                 cry = o.real(tag + ".cryengine3.psnr");
    EXPECT_GT(std::fabs(sph - lam), 0.05) << tag;
    EXPECT_GT(std::fabs(lam - cry), 0.05) << tag;
    EXPECT_GT(std::fabs(sph - cry), 0.05) << tag;
    const double spread = std::max({sph, lam, cry}) - std::min({sph, lam, cry});
    EXPECT_LT(spread, previous_spread) << tag;
    previous_spread = spread;
    // seed_order says whether they rank as the seed's table does: 44.781 > 43.054 > 40.355.
    EXPECT_EQ(o.integer(tag + ".seed_order"), sph > lam && lam > cry ? 1 : 0) << tag;
  }
}
