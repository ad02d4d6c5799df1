// Every claim of the catalogue, run under the default options (and the variants it depends on), with
// its verdict and figures checked against independent references: closed forms derived in the
// comments, or brute force in plain int arithmetic (reference.hpp) — never the model, never pasted
// output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "gs_arith/profiles.hpp"
#include "proofs/claim.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/runner.hpp"
#include "reference.hpp"

namespace p = gsdot3::proofs;

namespace {
const p::claim_result& result(std::string_view id) {
  static std::map<std::string, p::claim_result, std::less<>> cache;
  auto it = cache.find(id);
  if (it == cache.end()) {
    const auto* c = p::find_claim(id);
    if (c == nullptr) throw std::runtime_error("no claim " + std::string(id));
    it = cache.emplace(std::string(id), p::run_claim(*c, {}, p::run_config{})).first;
  }
  return it->second;
}
const p::outcome& base(std::string_view id) { return result(id).result; }
const p::outcome& variant(std::string_view id, std::string_view option, std::string_view value) {
  for (const auto& v : result(id).variants)
    if (v.option == option && v.value == value) return v.result;
  throw std::runtime_error("no variant");
}
std::int64_t fig(const p::outcome& o, std::string_view name) { return o.integer(name); }

// #{a ∈ [−127, −1], b ∈ [lo_b, 127] : a·b not a multiple of 128}.
std::uint64_t negative_a_inexact(int lo_b) {
  std::uint64_t n = 0;
  for (int a = -127; a <= -1; ++a)
    for (int b = lo_b; b <= 127; ++b)
      if ((a * b) % 128 != 0) ++n;
  return n;
}
}  // namespace

TEST(Claims, EveryCatalogueRowRunsAndIsTested) {
  // The ids of the issue, exactly; a new row must get its assertions here.
  const std::vector<std::string_view> ids = {"eq1-eq2.ranges",
                                             "eq3.identity",
                                             "eq4.signed-multiply",
                                             "eq5-eq7.split-multiply",
                                             "eq10.split-offset-multiply",
                                             "eq8.offset-multiply",
                                             "eq9.rgb-sum",
                                             "ilp.palette-permutation",
                                             "ilp.dpb-clear-zero",
                                             "ilp.light-into-lab",
                                             "lab.saturation",
                                             "step4.diffuse-times-lab",
                                             "appendix2.packing",
                                             "two-pass.na-rounding",
                                             "appendix1.sphere-map",
                                             "two-pass.error-bound",
                                             "three-pass.error-bound",
                                             "two-pass.max-s.vertex",
                                             "two-pass.max-s.interpolated",
                                             "four-pass.channel-exact",
                                             "four-pass.sum-wrap",
                                             "clamp-wrap.intermediates",
                                             "highlight.attenuation",
                                             "lod.two-vs-four",
                                             "spot.attenuation-blend",  // spot_attenuation_test.cpp
                                             "zprefill.single-light",   // z_prefill_test.cpp
                                             "alpha-layer.round-trip",  // alpha_layer_test.cpp
                                             "specular.attenuation-compensation",
                                             "dpb-clear.value",
                                             "dpb-clear.read-before-write",
                                             "dpb-clear.variants-agree",
                                             "dpb-clear.lab-layout"};
  EXPECT_EQ(std::count_if(p::catalogue().begin(), p::catalogue().end(),
                          [](const p::claim& c) { return c.section == p::claim::mikkelsen_section; }),
            static_cast<std::ptrdiff_t>(ids.size()));  // the other seeds' rows are tested with their schemes
  for (auto id : ids) EXPECT_NE(p::find_claim(id), nullptr) << id;
}

TEST(Claims, Eq1Eq2Ranges) {
  const auto& o = base("eq1-eq2.ranges");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(o.domain_size, 65536u);
  // a2 = 128 − a over a ∈ [−127, 128] is [0, 255]; b2 likewise. The product extremes: a = 128,
  // b = −128 gives −128; a = −127, b = −128 gives 16256/128 = 127.
  EXPECT_EQ(fig(o, "a2_min"), 0);
  EXPECT_EQ(fig(o, "a2_max"), 255);
  EXPECT_EQ(fig(o, "b2_min"), 0);
  EXPECT_EQ(fig(o, "b2_max"), 255);
  EXPECT_EQ(fig(o, "product_min"), ref::floor128(128 * -128));
  EXPECT_EQ(fig(o, "product_max"), ref::floor128(-127 * -128));
}

TEST(Claims, Eq3IdentityIsExact) { EXPECT_EQ(base("eq3.identity").result, p::verdict::proven); }

TEST(Claims, Eq4AndEq8ProvenUnderFloorRefutedUnderTruncation) {
  // (128 − a2)·b2 = a·(b + 128) = a·b + 128·a, so floor(.../128) + a2 − 128 = floor(a·b/128): exact.
  // Truncation differs from floor exactly when a·(b + 128) < 0 (a < 0, b > −128) is not a multiple
  // of 128, i.e. when a·b is not.
  for (auto id : {"eq4.signed-multiply", "eq8.offset-multiply"}) {
    EXPECT_EQ(base(id).result, p::verdict::proven) << id;
    const auto& t = variant(id, "blend_shift", "truncate");
    EXPECT_EQ(t.result, p::verdict::refuted) << id;
    EXPECT_EQ(t.counterexamples, negative_a_inexact(-127)) << id;
  }
  const auto& o = base("eq8.offset-multiply");
  EXPECT_EQ(fig(o, "out_min"), 0);  // a·b + 128 with a·b ∈ [−128, 127]
  EXPECT_EQ(fig(o, "out_max"), 255);
  EXPECT_EQ(fig(o, "needs_clamp_or_wrap"), 0);
}

TEST(Claims, Eq5Eq7AndEq10AreOffByOneForNegativeA) {
  // a >= 0: floor(a·b2/128) + c2 − 128 = floor(a·b/128) + a − a: exact. a < 0, m = −a:
  // −floor(m·b2/128) + m = −floor(m·b/128) = ceil(a·b/128): one more than floor unless 128 | a·b.
  // Count = 127·256 − Σ_{m=1}^{127} #{b : 128 | m·b} = 127·256 − Σ 2^(v2(m)+1).
  std::uint64_t divisible = 0;
  for (int m = 1; m <= 127; ++m) {
    int v = 0;
    while ((m >> v) % 2 == 0) ++v;
    divisible += std::uint64_t{2} << v;
  }
  const std::uint64_t expected = 127 * 256 - divisible;
  EXPECT_EQ(expected, negative_a_inexact(-128));
  for (auto id : {"eq5-eq7.split-multiply", "eq10.split-offset-multiply"}) {
    const auto& o = base(id);
    EXPECT_EQ(o.result, p::verdict::refuted) << id;
    EXPECT_EQ(o.counterexamples, expected) << id;
    EXPECT_EQ(fig(o, "err_min"), 0) << id;
    EXPECT_EQ(fig(o, "err_max"), 1) << id;
    for (const auto& v : result(id).variants) EXPECT_FALSE(v.changed) << id << " " << v.option;
  }
}

TEST(Claims, Eq9RgbSumExactIffInRange) {
  const auto& o = base("eq9.rgb-sum");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(fig(o, "sum_min"), -384);
  EXPECT_EQ(fig(o, "sum_max"), 255 * 3 - 384);
  // Triples with r + g + b outside [256, 511]: count sums by convolution.
  std::vector<std::uint64_t> two(511, 0), three(766, 0);
  for (int r = 0; r < 256; ++r)
    for (int g = 0; g < 256; ++g) ++two[static_cast<std::size_t>(r + g)];
  for (int t = 0; t < 511; ++t)
    for (int b = 0; b < 256; ++b) three[static_cast<std::size_t>(t + b)] += two[static_cast<std::size_t>(t)];
  std::uint64_t outside = 0;
  for (int t = 0; t < 766; ++t)
    if (t < 256 || t > 511) outside += three[static_cast<std::size_t>(t)];
  EXPECT_EQ(fig(o, "wrapping_pixels"), static_cast<std::int64_t>(outside));
}

TEST(Claims, IlpRotationAndTheClearValue) {
  EXPECT_EQ(base("ilp.palette-permutation").result, p::verdict::proven);
  // Clear 0x00808080: r+g+b = 384 ≡ 128, the offset-keeping index of dot 0; entry 0 of the paper's
  // ILP is 1. Two-pass adds 3·a = 0. So intensity 1, three times; 0x0080807F gives dot −1 -> 0.
  const auto& o = base("ilp.dpb-clear-zero");
  EXPECT_EQ(o.result, p::verdict::refuted);
  EXPECT_EQ(o.counterexamples, 3u);
  EXPECT_EQ(fig(o, "intensity_four_pass"), 1);
  EXPECT_EQ(fig(o, "intensity_four_pass_minus_128"), 1);
  EXPECT_EQ(fig(o, "intensity_two_pass"), 1);
  EXPECT_EQ(fig(o, "intensity_clear_0x0080807F"), 0);
}

// Section 3.1 steps 2, 2.6 and 4: the LAB. The saturated counts are written another way: for an ILP
// entry i and colour c the LAB bytes d that overflow are those above 255 − floor(i·c/128), i.e.
// floor(i·c/128) of them; a diffuse·LAB product saturates when t·l ≥ 256·128.
TEST(Claims, LabAccumulationAndTheDiffuseMultiply) {
  const auto& ilp = base("ilp.light-into-lab");
  EXPECT_EQ(ilp.result, p::verdict::proven);
  std::int64_t over = 0;
  for (int i = 0; i <= 128; ++i)
    for (int c = 0; c < 256; ++c) over += i * c / 128;
  EXPECT_EQ(fig(ilp, "saturated"), over);
  EXPECT_EQ(fig(ilp, "loss_max_128ths"), 127);  // e.g. i = 127, c = 1: 127/128 dropped
  EXPECT_EQ(fig(ilp, "full_intensity_not_light"), 0);
  EXPECT_EQ(base("lab.saturation").result, p::verdict::proven);
  EXPECT_EQ(fig(base("lab.saturation"), "default_green_lights_to_saturate"), 2);  // 0x10 + 2·0x98 = 320
  const auto& s4 = base("step4.diffuse-times-lab");
  EXPECT_EQ(s4.result, p::verdict::proven);
  std::int64_t sat = 0;
  for (int t = 1; t < 256; ++t) sat += std::max(0, 256 - (32768 + t - 1) / t);  // l >= ceil(32768 / t)
  EXPECT_EQ(fig(s4, "saturated"), sat);
  EXPECT_EQ(fig(s4, "loss_max_128ths"), 127);
  EXPECT_EQ(fig(s4, "lab_0x80_not_identity"), 0);
}

TEST(Claims, Appendix2PackingAndNaRounding) {
  std::int64_t count = 0;
  for (int x = -127; x <= 127; ++x)
    if (x * x <= 16358) count += 2 * ref::isqrt(16358 - x * x) + 1;
  int amin = 1000, amax = -1000, zmin = 1000, zmax = -1, namin = 1000, namax = -1000, over = 0;
  for (const auto& n : ref::appendix2_normals()) {
    const int na = 384 - (n.x + n.y + n.z);
    amin = std::min(amin, n.alpha), amax = std::max(amax, n.alpha);
    zmin = std::min(zmin, n.z), zmax = std::max(zmax, n.z);
    namin = std::min(namin, na), namax = std::max(namax, na);
    over += na > 255;
  }
  const auto& o = base("appendix2.packing");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(fig(o, "normals"), count);
  EXPECT_EQ(fig(o, "alpha_min"), amin);
  EXPECT_EQ(fig(o, "alpha_max"), amax);
  EXPECT_EQ(fig(o, "iz_min"), zmin);
  EXPECT_EQ(fig(o, "iz_max"), 128);
  EXPECT_EQ(zmax, 128);
  EXPECT_EQ(fig(o, "b_neg_nonzero"), 0);
  EXPECT_EQ(fig(o, "alpha_clamp_changes"), 0);
  EXPECT_EQ(fig(o, "iX_gt_255_branch"), 0);
  const auto& r = base("two-pass.na-rounding");
  EXPECT_EQ(r.result, p::verdict::bound);
  EXPECT_EQ(fig(r, "na_min"), namin);
  EXPECT_EQ(fig(r, "na_max"), namax);
  EXPECT_GT(namax, 255);  // the paper: "n_a is potentially larger than 255"
  EXPECT_EQ(fig(r, "na_over_255"), over);
  EXPECT_EQ(fig(r, "na_prime_min"), (namin + 1) / 3);
  EXPECT_EQ(fig(r, "na_prime_max"), (namax + 1) / 3);
  // 3·((n + 1) div 3) − n is −1, 0, +1 for n ≡ 1, 0, 2 (mod 3); all residues occur.
  EXPECT_EQ(fig(r, "error_min"), -1);
  EXPECT_EQ(fig(r, "error_max"), 1);
  // Bilinear filtering (4-bit weights w = 0..15, c0 + floor((c1 − c0)·w/16)) of every pair of n_a
  // values: stored mod 256 vs the wide filter; stored as n'_a, three times the filtered n'_a.
  std::vector<bool> seen(1024);
  for (const auto& n : ref::appendix2_normals()) seen[static_cast<std::size_t>(384 - (n.x + n.y + n.z))] = true;
  auto lerp = [](int c0, int c1, int w) {
    const int d = (c1 - c0) * w;
    return c0 + (d >= 0 ? d / 16 : -((-d + 15) / 16));
  };
  std::int64_t cases = 0, wrong = 0;
  int smin = 100, smax = -100;
  for (int x0 = 0; x0 < 1024; ++x0)
    for (int x1 = 0; x1 < 1024; ++x1)
      if (seen[static_cast<std::size_t>(x0)] && seen[static_cast<std::size_t>(x1)])
        for (int w = 0; w < 16; ++w) {
          ++cases;
          wrong += lerp(x0 % 256, x1 % 256, w) != lerp(x0, x1, w) % 256;
          const int e = 3 * lerp((x0 + 1) / 3, (x1 + 1) / 3, w) - lerp(x0, x1, w);
          smin = std::min(smin, e), smax = std::max(smax, e);
        }
  EXPECT_EQ(fig(r, "filter_cases"), cases);
  EXPECT_EQ(fig(r, "unscaled_filter_wrong"), wrong);
  EXPECT_EQ(fig(r, "scaled_filter_err_min"), smin);
  EXPECT_EQ(fig(r, "scaled_filter_err_max"), smax);
  const auto& nearest = variant("two-pass.na-rounding", "bilinear", "nearest");
  EXPECT_EQ(fig(nearest, "unscaled_filter_wrong"), 0);  // weight 0 only: each texel as stored
}

TEST(Claims, Appendix1SphereMap) {
  const auto& o = base("appendix1.sphere-map");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(o.domain_size, 16u * 16 + 32 * 32 + 64 * 64 + 128 * 128 + 256 * 256);
  for (int w : {16, 32, 64, 128, 256}) {
    // Inside the disc: ρ² = s2² + t2² <= 1 with s2 = (2x + 1 − w)/w: integers only.
    std::int64_t inside = 0;
    for (int y = 0; y < w; ++y)
      for (int x = 0; x < w; ++x)
        inside += (2 * x + 1 - w) * (2 * x + 1 - w) + (2 * y + 1 - w) * (2 * y + 1 - w) <= w * w;
    EXPECT_EQ(fig(o, "inside_" + std::to_string(w)), inside) << w;
  }
  // Each component is rounded by at most 1/2 (plus float noise), so the error vector is at most
  // √3/2 long against a vector of length >= 127 − √3/2: angle <= asin(0.8661/126.13) = 0.3935°.
  EXPECT_GT(o.real("worst_angle_deg"), 0.0);
  EXPECT_LE(o.real("worst_angle_deg"), 0.3935);
}

TEST(Claims, TwoPassErrorBound) {
  // error = e − floor(Σ r_c) with e ∈ {−1, 0, 1}, Σ r_c ∈ (−2, 3): |error| <= 3, and the claim must
  // report witnesses reaching both ends (re-checked in plain ints in reduction_test).
  const auto& o = base("two-pass.error-bound");
  EXPECT_EQ(o.result, p::verdict::bound);
  EXPECT_EQ(fig(o, "err_min"), -3);
  EXPECT_EQ(fig(o, "err_max"), 3);
  EXPECT_EQ(fig(o, "normals"), static_cast<std::int64_t>(ref::appendix2_normals().size()));
}

TEST(Claims, ThreePassErrorBound) {
  // error = −floor(Σ r_c) once pass 3 adds n_a exactly: [−2, 2], both ends reached.
  const auto& o = base("three-pass.error-bound");
  EXPECT_EQ(o.result, p::verdict::bound);
  EXPECT_EQ(fig(o, "err_min"), -2);
  EXPECT_EQ(fig(o, "err_max"), 2);
  EXPECT_EQ(fig(o, "normals_na_not_exact"), 0);
  // Two-pass's n'_a = (n_a + 1)/3 with n_a = 384 − (x + y + z): 3·n'_a != n_a unless 3 divides n_a.
  std::int64_t inexact = 0;
  for (const auto& n : ref::appendix2_normals()) inexact += 3 * n.alpha != 384 - (n.x + n.y + n.z);
  EXPECT_EQ(fig(o, "two_pass_normals_na_not_exact"), inexact);
  // The err_max witness, re-derived in plain ints.
  ASSERT_EQ(o.witnesses.size(), 2u);
  EXPECT_NE(o.witnesses[1].find("n = (-127, -15, 5)"), std::string::npos) << o.witnesses[1];
  EXPECT_NE(o.witnesses[1].find("l = (-121, -15, 0)"), std::string::npos) << o.witnesses[1];
  const auto w = ref::appendix2(-127, -15);
  EXPECT_EQ(ref::three_pass_value(w, -121, -15, 0) - ref::floor128(w.x * -121 + w.y * -15 + w.z * 0), 2);
}

TEST(Claims, TwoPassMaxSVertex) {
  const auto& o = base("two-pass.max-s.vertex");
  EXPECT_EQ(o.result, p::verdict::bound);
  EXPECT_EQ(fig(o, "s_max"), 125);  // bound −s−3 <= value <= s+2 rules out s <= 125; witness at 126
  EXPECT_EQ(fig(o, "margin"), 3);
  EXPECT_GT(fig(o, "wrapping_pairs_at_s_max_plus_1"), 0);
  // The reported first witness, re-derived in plain ints: n = (−127, −15, 5), l = (−125, −15, 0):
  // channels −floor(127·3/128) = −2, −floor(15·113/128) = −13, floor(5·128/128) = 5, alpha 174:
  // −2 − 13 + 5 + 522 − 384 = 128 > 127.
  const auto n = ref::appendix2(-127, -15);
  EXPECT_EQ(n.z, 5);
  EXPECT_EQ(n.alpha, 174);
  EXPECT_EQ(ref::two_pass_value(n, -125, -15, 0), 128);
  ASSERT_FALSE(o.witnesses.empty());
  EXPECT_NE(o.witnesses[0].find("n = (-127, -15, 5)"), std::string::npos) << o.witnesses[0];
}

TEST(Claims, TwoPassMaxSInterpolated) {
  // Whole triangles, per gouraud_setup. Default per_pixel_floor: no pixel lags, so the claim is the vertex
  // lights' (two-pass.max-s.vertex, settled there by an exhaustive search above its argument): safe up
  // to 125, and only the flat triangle (the vertex claim's witness as three equal vertex lights) wraps,
  // at 126.
  const auto& e = base("two-pass.max-s.interpolated");
  const auto& vertex = base("two-pass.max-s.vertex");
  EXPECT_EQ(e.result, p::verdict::bound);
  EXPECT_EQ(fig(e, "s_max"), fig(vertex, "s_max"));
  EXPECT_EQ(fig(e, "s_max_upper"), fig(vertex, "s_max"));
  EXPECT_EQ(fig(e, "first_wrapping_s"), fig(vertex, "s_max") + 1);
  EXPECT_EQ(fig(e, "certificates_not_wrapping"), 24);  // every row but the flat one
  EXPECT_EQ(fig(e, "bound_limit_s"), 0);               // the relaxation witnesses charge a lag per_pixel has not
  ASSERT_EQ(e.witnesses.size(), 1u);
  EXPECT_EQ(e.witnesses[0].rfind("s = 126: n = (-127, -15, 5)", 0), 0u) << e.witnesses[0];
  EXPECT_NE(e.note.find("the bound meets the lowest certificate"), std::string::npos) << e.note;
  EXPECT_NE(e.note.find("The paper's s = 122 is safe"), std::string::npos) << e.note;
  // The table: two header rows and twelve, one per set-up (six) and gouraud_fraction (two).
  EXPECT_EQ(e.table.size(), 14u);
  // plane_steps (the model's DDA, no source): the paper's s = 122 wraps (a certificate, replayed through
  // the pipeline in triangle_test.cpp); the bound proves s <= 79 (78 under truncate_to_8: the same
  // inequality in doubles, triangle_test.cpp); the lowest certificate is s = 85 (84 under truncate_to_8).
  const auto& o = variant("two-pass.max-s.interpolated", "gouraud_setup", "plane_steps");
  EXPECT_EQ(o.result, p::verdict::refuted);
  EXPECT_EQ(fig(o, "s_max"), 83);
  EXPECT_EQ(fig(o, "bound_s_max"), 79);             // the error bound alone (triangle_test checks it in doubles)
  EXPECT_EQ(fig(o, "relaxation_certified_s"), 83);  // re-run by proofs_certify_survey
  EXPECT_EQ(fig(o, "first_wrapping_s"), 85);
  EXPECT_EQ(fig(o, "s_max_upper"), 84);
  EXPECT_EQ(fig(o, "certificates_not_wrapping"),
            13);                       // the truncate_to_8 rows, the per_pixel one and the four pcsx2_rows ones
  EXPECT_EQ(o.witnesses.size(), 12u);  // s = 85, 86, 89, 90, 91, 98, 100, 122..125 and the flat 126
  // The verdict text follows the figures: the bracket is 80..84 and the lowest certificate's s is named.
  EXPECT_NE(o.note.find("s = 84 is bracketed"), std::string::npos) << o.note;
  EXPECT_NE(o.note.find("the lowest s = 85"), std::string::npos) << o.note;
  // The bound's own statements admit a wrap from s = 84 (a relaxation witness; triangle_test.cpp
  // recomputes it), 83 under truncate_to_8 (whose lattice already wraps at 84; s = 82 is certified).
  EXPECT_EQ(fig(o, "bound_limit_s"), 84);
  EXPECT_NE(o.note.find("admit a wrap from s = 84"), std::string::npos) << o.note;
  bool paper = false;
  for (const auto& w : o.witnesses) paper = paper || w.rfind("s = 122:", 0) == 0;
  EXPECT_TRUE(paper);
  auto under = [](const char* setup, const char* fraction) {
    gs::model_options v;
    EXPECT_FALSE(gs::set_option(v, "gouraud_setup", setup).has_value());
    EXPECT_FALSE(gs::set_option(v, "gouraud_fraction", fraction).has_value());
    p::run_config cfg;
    cfg.variants = false;
    return p::run_claim(*p::find_claim("two-pass.max-s.interpolated"), v, cfg).result;
  };
  const auto t = under("plane_steps", "truncate_to_8");
  EXPECT_EQ(t.result, p::verdict::refuted);
  EXPECT_EQ(fig(t, "s_max"), 82);
  EXPECT_EQ(fig(t, "bound_s_max"), 78);
  EXPECT_EQ(fig(t, "first_wrapping_s"), 84);
  EXPECT_EQ(fig(t, "s_max_upper"), 83);
  EXPECT_NE(t.note.find("s = 83 is bracketed"), std::string::npos) << t.note;
  EXPECT_NE(t.note.find("the lowest s = 84"), std::string::npos) << t.note;
  EXPECT_EQ(fig(t, "bound_limit_s"), 83);
  // pcsx2_rows_8 (PCSX2 SW on AVX2): a steep row's saturated second vector wraps the paper's s = 122
  // (and s = 110); the cube bound of that per-channel mix proves s <= 72.
  const auto r8 = under("pcsx2_rows_8", "keep_fraction");
  EXPECT_EQ(r8.result, p::verdict::refuted);
  EXPECT_EQ(fig(r8, "s_max"), 72);
  EXPECT_EQ(fig(r8, "first_wrapping_s"), 110);
  // per_pixel_level (parallel-gs): within 128 units of the plane, safe up to 123; the s = 124 certificate
  // (a whole level, as truncate_to_8) wraps.
  const auto lv = under("per_pixel_level", "keep_fraction");
  EXPECT_EQ(lv.result, p::verdict::bound);
  EXPECT_EQ(fig(lv, "s_max"), 123);
  EXPECT_EQ(fig(lv, "first_wrapping_s"), 124);
  const auto r4 = under("pcsx2_rows_4", "keep_fraction");
  EXPECT_EQ(r4.result, p::verdict::refuted);
  EXPECT_EQ(fig(r4, "first_wrapping_s"), 100);
  // The dobiestation profile (per_pixel_floor with truncate_to_8, issue 53): the multiply's floor hands a pixel the
  // integer light of the unit box its exact light lies in, which can sit just outside the packed
  // shell: safe up to 123 by the bound, and the s = 124 certificate's box m = (−27, −63, −105) has
  // the plain-int value −129 for n = (24, 59, 111).
  gs::model_options dobie;
  ASSERT_FALSE(gs::apply_profile(dobie, "dobiestation").has_value());
  const auto d = p::run_claim(*p::find_claim("two-pass.max-s.interpolated"), dobie, p::run_config{}).result;
  EXPECT_EQ(d.result, p::verdict::bound);
  EXPECT_EQ(fig(d, "s_max"), 123);
  EXPECT_EQ(fig(d, "s_max_upper"), 123);
  const auto n = ref::appendix2(24, 59);
  EXPECT_EQ(n.z, 111);
  EXPECT_EQ(ref::two_pass_value(n, -27, -63, -105), -129);
  ASSERT_FALSE(d.witnesses.empty());
  EXPECT_EQ(d.witnesses[0].rfind("s = 124: n = (24, 59, 111)", 0), 0u) << d.witnesses[0];
}

TEST(Claims, FourPassChannelExact) {
  EXPECT_EQ(base("four-pass.channel-exact").result, p::verdict::proven);
  const auto& t = variant("four-pass.channel-exact", "blend_shift", "truncate");
  EXPECT_EQ(t.counterexamples, 3 * negative_a_inexact(-127));
}

namespace {
// Normal-map vectors written as distances: the cell of b meets the sphere of radius 127.
std::vector<std::array<int, 3>> normal_map_vectors() {
  std::vector<std::array<int, 3>> out;
  for (int x = -127; x <= 127; ++x)
    for (int y = -127; y <= 127; ++y)
      for (int z = 0; z <= 127; ++z) {
        double near = 0, far = 0;
        for (int c : {x, y, z}) {
          const double d = std::max(0.0, std::abs(c) - 0.5);
          near += d * d;
          far += (std::abs(c) + 0.5) * (std::abs(c) + 0.5);
        }
        if (near <= 127.0 * 127.0 && far >= 127.0 * 127.0) out.push_back({x, y, z});
      }
  return out;
}
}  // namespace

TEST(Claims, FourPassSumWrapAgainstPlainIntegers) {
  auto normals = normal_map_vectors();  // scan() reads it; the full_sphere check below widens it
  std::vector<std::array<int, 3>> plain, faded;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const auto t = p::paper::sphere_map_texel(x, y, 64, 64);
      plain.push_back({128 - t.r, 128 - t.g, 128 - t.b});
      if (!t.inside) {
        faded.push_back({0, 0, 0});
        continue;
      }
      // HIGHLIGHT with RGB k, A 128 − k: min(255, floor(c·k/128) + 128 − k).
      const int k = p::paper::nearest(std::clamp(6.0f * t.lz, 0.0f, 1.0f) * 128.0f);
      auto f = [&](int c) { return 128 - std::min(255, c * k / 128 + 128 - k); };
      faded.push_back({f(t.r), f(t.g), f(t.b)});
    }
  auto scan = [&](const std::vector<std::array<int, 3>>& lights, int& lo, int& hi, std::int64_t& wraps) {
    int l2[2] = {1000, 1000}, h2[2] = {-1000, -1000};
    std::int64_t w2[2] = {0, 0};
    ref::two_halves(lights.size(), [&](std::size_t begin, std::size_t end) {
      const int h = begin == 0 ? 0 : 1;
      for (std::size_t i = begin; i < end; ++i)
        for (const auto& b : normals) {
          const auto& a = lights[i];
          const int s = ref::floor128(a[0] * b[0]) + ref::floor128(a[1] * b[1]) + ref::floor128(a[2] * b[2]);
          l2[h] = std::min(l2[h], s), h2[h] = std::max(h2[h], s);
          w2[h] += s < -128 || s > 127;
        }
    });
    lo = std::min(l2[0], l2[1]), hi = std::max(h2[0], h2[1]), wraps = w2[0] + w2[1];
  };
  int lo, hi, flo, fhi;
  std::int64_t wraps, fwraps;
  scan(plain, lo, hi, wraps);
  scan(faded, flo, fhi, fwraps);
  const auto& o = base("four-pass.sum-wrap");
  EXPECT_EQ(fig(o, "normal_map_vectors"), static_cast<std::int64_t>(normals.size()));
  EXPECT_EQ(o.domain_size, 4096u * normals.size());
  EXPECT_EQ(fig(o, "sum_min"), lo);
  EXPECT_EQ(fig(o, "sum_max"), hi);
  EXPECT_EQ(fig(o, "count"), wraps);
  EXPECT_EQ(o.result, wraps > 0 ? p::verdict::refuted : p::verdict::proven);
  EXPECT_EQ(fig(o, "fade_sum_min"), flo);
  EXPECT_EQ(fig(o, "fade_sum_max"), fhi);
  EXPECT_EQ(fig(o, "fade_count"), fwraps);

  // Domain option fade_att = any_vertex: the faded domain is the plain one.
  const auto& any = variant("four-pass.sum-wrap", "fade_att", "any_vertex");
  EXPECT_EQ(fig(any, "fade_count"), wraps);
  EXPECT_EQ(fig(any, "fade_sum_min"), lo);
  // Domain option normal_map = full_sphere: the cell test is symmetric in z, so the set is the
  // n_z >= 0 one and its mirror image in z for n_z > 0.
  auto full = normals;
  for (const auto& b : normals)
    if (b[2] > 0) full.push_back({b[0], b[1], -b[2]});
  normals = full;
  scan(plain, lo, hi, wraps);
  scan(faded, flo, fhi, fwraps);
  const auto& fs = variant("four-pass.sum-wrap", "normal_map", "full_sphere");
  EXPECT_EQ(fig(fs, "normal_map_vectors"), static_cast<std::int64_t>(full.size()));
  EXPECT_EQ(fig(fs, "sum_min"), lo);
  EXPECT_EQ(fig(fs, "sum_max"), hi);
  EXPECT_EQ(fig(fs, "count"), wraps);
  EXPECT_EQ(fig(fs, "fade_count"), fwraps);
}

TEST(Claims, ClampWrapIntermediates) {
  const auto& o = base("clamp-wrap.intermediates");
  EXPECT_EQ(o.result, p::verdict::proven);
  EXPECT_EQ(fig(o, "tfx_clamp_bites"), 0);
  EXPECT_EQ(fig(o, "two_pass_wrong_wraps"), 0);
  EXPECT_EQ(fig(o, "four_pass_blend_outside_byte"), 0);
  // Pass 2 is negative (and wraps, as wanted) when n = −m < 0 and floor(m·L87/2^14) >= 1, i.e.
  // L87 >= ceil(16384/m): 32768 − ceil(16384/m) light values for each m.
  std::int64_t wanted = 0;
  for (int m = 1; m <= 127; ++m) wanted += 32768 - (16384 + m - 1) / m;
  EXPECT_EQ(fig(o, "two_pass_wraps_wanted"), wanted);
}

TEST(Claims, HighlightAttenuation) {
  // 128·GS − exact·128 = 128·floor(sph·k/128) − sph·k = −(sph·k mod 128) ∈ [−127, 0]; −127 is
  // reached (sph·k = 127), 0 at k = 0. No clamp: floor(255·k/128) + 128 − k <= 255.
  const auto& o = base("highlight.attenuation");
  EXPECT_EQ(o.result, p::verdict::bound);
  EXPECT_EQ(fig(o, "err_min_128ths"), -127);
  EXPECT_EQ(fig(o, "err_max_128ths"), 0);
  EXPECT_EQ(fig(o, "clamps"), 0);
}

TEST(Claims, SpecularCompensation) {
  double cmin = 1e9, cmax = -1e9, umin = 1e9, umax = -1e9;
  for (int n = 2; n <= 64; ++n)
    for (int a = 0; a <= 128; ++a)
      for (int i = 0; i < 128; ++i) {
        const double want = 128.0 * (a / 128.0) * std::pow((i + 1) / 128.0, n);
        const int k = static_cast<int>(std::lround(128.0 * std::pow(a / 128.0, 1.0 / n)));
        auto ilp = [&](int j) { return std::round(128.0 * std::pow((j + 1) / 128.0, n)); };
        const double c = ilp(i * k / 128) - want, u = ilp(i * a / 128) - want;
        cmin = std::min(cmin, c), cmax = std::max(cmax, c), umin = std::min(umin, u), umax = std::max(umax, u);
      }
  const auto& o = base("specular.attenuation-compensation");
  EXPECT_DOUBLE_EQ(o.real("err_min"), cmin);
  EXPECT_DOUBLE_EQ(o.real("err_max"), cmax);
  EXPECT_DOUBLE_EQ(o.real("uncompensated_err_min"), umin);
  EXPECT_DOUBLE_EQ(o.real("uncompensated_err_max"), umax);
}

TEST(Claims, LodTwoVersusFourAgainstPlainIntegers) {
  const auto normals = normal_map_vectors();
  struct light {
    int a[3], l[3];
  };
  std::vector<light> lights;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const auto t = p::paper::sphere_map_texel(x, y, 64, 64);
      if (!t.inside) continue;
      lights.push_back(
          {{128 - t.r, 128 - t.g, 128 - t.b},
           {static_cast<int>(122.0f * t.lx), static_cast<int>(122.0f * t.ly), static_cast<int>(122.0f * t.lz)}});
    }
  int l2[2] = {1000, 1000}, h2[2] = {-1000, -1000}, vl2[2] = {1000, 1000}, vh2[2] = {-1000, -1000};
  ref::two_halves(normals.size(), [&](std::size_t begin, std::size_t end) {
    const int h = begin == 0 ? 0 : 1;
    for (std::size_t j = begin; j < end; ++j) {
      const auto& b = normals[j];
      const double len = std::sqrt(double(b[0]) * b[0] + double(b[1]) * b[1] + double(b[2]) * b[2]);
      const int ix = static_cast<int>(static_cast<float>(b[0] / len) * 127.9f);
      const int iy = static_cast<int>(static_cast<float>(b[1] / len) * 127.9f);
      const auto n = ref::appendix2(ix, iy);
      for (const auto& L : lights) {
        const int two = ref::two_pass_value(n, L.l[0], L.l[1], L.l[2]);
        const int four = ref::floor128(L.a[0] * b[0]) + ref::floor128(L.a[1] * b[1]) + ref::floor128(L.a[2] * b[2]);
        l2[h] = std::min(l2[h], two - four), h2[h] = std::max(h2[h], two - four);
        const int visible = std::max(two, 0) - std::max(four, 0);
        vl2[h] = std::min(vl2[h], visible), vh2[h] = std::max(vh2[h], visible);
      }
    }
  });
  const int lo = std::min(l2[0], l2[1]), hi = std::max(h2[0], h2[1]);
  const auto& o = base("lod.two-vs-four");
  EXPECT_EQ(fig(o, "diff_min"), lo);
  EXPECT_EQ(fig(o, "diff_max"), hi);
  EXPECT_EQ(fig(o, "visible_diff_min"), std::min(vl2[0], vl2[1]));
  EXPECT_EQ(fig(o, "visible_diff_max"), std::max(vh2[0], vh2[1]));
}

// Section 3.4, counted by hand: PSMZ24 keeps alpha, so (a) fails on every pixel of both variants for
// the 255 non-zero alphas; z-trick-psmz32's Z writes from the top two 32x16 quarters (rows 0-15) land on
// the bottom two, which are read later: 1024 texels per ZBUF format, unless the buffer holds the page.
TEST(Claims, DpbClearTrick) {
  const gs::model_options o;
  const auto value = p::find_claim("dpb-clear.value")->evaluate(o, {});
  EXPECT_EQ(value.counterexamples, 2u * 255u * 2048u);
  EXPECT_EQ(fig(value, "counterexamples_psmz32"), 0);
  for (const auto tb : {gs::texture_buffer::quarter_page, gs::texture_buffer::per_fragment, gs::texture_buffer::page,
                        gs::texture_buffer::draw_snapshot}) {
    gs::model_options t;
    t.tex_buffer = tb;
    const bool holds_page = tb == gs::texture_buffer::page || tb == gs::texture_buffer::draw_snapshot;
    const auto rbw = p::find_claim("dpb-clear.read-before-write")->evaluate(t, {});
    EXPECT_EQ(fig(rbw, "counterexamples_z_trick"), 0);
    EXPECT_EQ(fig(rbw, "counterexamples_z_trick_psmz32"), holds_page ? 0 : 2 * 1024);
    EXPECT_EQ(p::find_claim("dpb-clear.variants-agree")->evaluate(t, {}).counterexamples, holds_page ? 0u : 2u * 1024u);
    const auto layout = p::find_claim("dpb-clear.lab-layout")->evaluate(t, {});
    EXPECT_EQ(fig(layout, "counterexamples_z_trick"), 0);
    EXPECT_EQ(layout.result == p::verdict::proven, holds_page);
  }
}

TEST(Claims, TwoPassClaimsAreTheSameUnderAttenuatedLights) {
  // Domain option tolight = attenuated_T (argument beside claims_two_pass.cpp for_domain, brute
  // force at s = 40 in reduction_test.cpp): verdict and figures as for unit T.
  for (const char* id : {"two-pass.error-bound", "two-pass.max-s.vertex", "two-pass.max-s.interpolated"}) {
    const auto& o = base(id);
    const auto& a = variant(id, "tolight", "attenuated_T");
    EXPECT_EQ(a.result, o.result) << id;
    ASSERT_EQ(a.figures.size(), o.figures.size()) << id;
    for (std::size_t k = 0; k < o.figures.size(); ++k)
      EXPECT_EQ(a.figures[k], o.figures[k]) << id << " " << o.figures[k].name << " " << p::to_string(o.figures[k].value)
                                            << " vs " << a.figures[k].name << " " << p::to_string(a.figures[k].value);
    EXPECT_EQ(a.witnesses, o.witnesses) << id;
  }
}
