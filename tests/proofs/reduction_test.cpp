// The reductions and fast paths of the catalogue, checked against brute force on smaller instances
// (subsampled normal sets, smaller s) with plain int arithmetic (reference.hpp) or the full pixel
// pipeline through the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/colclamp.hpp"
#include "proofs/domains.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"
#include "reference.hpp"

namespace p = gsdot3::proofs;
namespace tp = gsdot3::proofs::two_pass;

namespace {
// The normals with iX <= max_x (the corner where the s = 126 wraps are).
std::vector<p::paper::packed_normal> normals_up_to_x(int max_x) {
  std::vector<p::paper::packed_normal> out;
  for (const auto& n : p::appendix2_normals())
    if (n.iX <= max_x) out.push_back(n);
  return out;
}
std::vector<p::paper::packed_normal> every_nth_normal(std::size_t n) {
  std::vector<p::paper::packed_normal> out;
  const auto& all = p::appendix2_normals();
  for (std::size_t i = 0; i < all.size(); i += n) out.push_back(all[i]);
  return out;
}
}  // namespace

TEST(Reduction, Appendix2DomainMatchesThePaperCodeOnEveryNormal) {
  // Same pairs as the plain enumeration, and the packed fields equal the closed forms.
  const auto& all = p::appendix2_normals();
  const auto ref_all = ref::appendix2_normals();
  ASSERT_EQ(all.size(), ref_all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    ASSERT_EQ(all[i].iX, ref_all[i].x);
    ASSERT_EQ(all[i].iY, ref_all[i].y);
    ASSERT_EQ(all[i].iZ, ref_all[i].z);
    ASSERT_EQ(all[i].alpha, ref_all[i].alpha);
  }
}

TEST(Reduction, PackedLightsAreExactlyTheTruncationsOfUnitVectors) {
  // Sampled directions must land in the set, and every member must be hit by its own cell's
  // nearest point scaled to the sphere (a constructive check of Σk² <= s² < Σ(|k|+1)²) for s = 20.
  const int s = 20;
  const auto lights = p::packed_lights(s);
  auto member = [&](int x, int y, int z) {
    return std::binary_search(lights.begin(), lights.end(), p::ivec3{x, y, z});
  };
  for (int i = 0; i < 20000; ++i) {
    const double u = (i * 0.6180339887) - static_cast<int>(i * 0.6180339887), v = (i + 0.5) / 20000.0;
    const double zc = 2 * v - 1, r = std::sqrt(1 - zc * zc), ph = 2 * 3.14159265358979 * u;
    const double T[3] = {r * std::cos(ph), r * std::sin(ph), zc};
    EXPECT_TRUE(member(static_cast<int>(s * T[0]), static_cast<int>(s * T[1]), static_cast<int>(s * T[2])));
  }
  for (const auto& l : lights) {
    int lo = 0, hi = 0;
    for (int c : l) lo += c * c, hi += (std::abs(c) + 1) * (std::abs(c) + 1);
    EXPECT_LE(lo, s * s);
    EXPECT_GT(hi, s * s);
  }
}

TEST(Reduction, TwoPassTableEqualsThePixelPipelineAndThePlainFormula) {
  const gs::model_options o{};
  const tp::table t(o);
  for (int n = -127; n <= 128; ++n)
    for (int l = -128; l <= 127; ++l) ASSERT_EQ(t.channel(n, l), ref::two_pass_channel(n, 128 + l)) << n << " " << l;
  const auto normals = every_nth_normal(61);
  const tp::light_grid g(122);
  for (const auto& nm : normals)
    for (std::size_t j = 0; j < g.lights.size(); j += 97) {
      const auto& l = g.lights[j];
      const auto px = tp::pixel(nm, tp::vertex_light(l), o);
      ASSERT_EQ(t.value(nm, l), px.value);
      ASSERT_EQ(px.value, ref::two_pass_value(ref::appendix2(nm.iX, nm.iY), l[0], l[1], l[2]));
      ASSERT_EQ(px.dot, px.value);  // s = 122 never wraps
    }
}

// The three-pass variant: the table (terms through pass 3 of the model) against the whole pixel
// (three passes and r + g + b through the model) and the plain formula.
TEST(Reduction, ThreePassTableEqualsThePixelPipelineAndThePlainFormula) {
  const gs::model_options o{};
  const tp::table t(o, tp::na_term::additive_pass);
  for (int n = -127; n <= 128; ++n) ASSERT_EQ(t.term(n), 128 - n) << n;
  const auto normals = every_nth_normal(61);
  const tp::light_grid g(122);
  for (const auto& nm : normals) {
    ASSERT_EQ(t.alpha_error(nm), 0);
    for (std::size_t j = 0; j < g.lights.size(); j += 97) {
      const auto& l = g.lights[j];
      const auto px = tp::pixel(nm, tp::vertex_light(l), o, tp::na_term::additive_pass);
      ASSERT_EQ(t.value(nm, l), px.value);
      ASSERT_EQ(px.value, ref::three_pass_value(ref::appendix2(nm.iX, nm.iY), l[0], l[1], l[2]));
      ASSERT_EQ(px.dot, px.value);
    }
  }
}

namespace {
// Plain-int brute force: pairs with value >= hi or <= lo, and the first few indices.
p::tally brute(const std::vector<p::paper::packed_normal>& normals, const tp::light_grid& g, int hi, int lo) {
  p::tally t;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const auto n = ref::appendix2(normals[i].iX, normals[i].iY);
    for (std::size_t j = 0; j < g.lights.size(); ++j) {
      const auto& l = g.lights[j];
      const int v = ref::two_pass_value(n, l[0], l[1], l[2]);
      if (v >= hi || v <= lo) t.add(i * g.lights.size() + j);
    }
  }
  return t;
}
}  // namespace

TEST(Reduction, PrunedWrapSearchEqualsBruteForceOnSmallerInstances) {
  const tp::table t(gs::model_options{});
  p::sweep_config cfg;
  struct instance {
    int s, hi, lo;
    std::vector<p::paper::packed_normal> normals;
  };
  // Thresholds just inside the bound −s − 3 <= value <= s + 2, so both searches find hits; s = 125
  // and 126 on the normals with iX <= −122 (where the s = 126 wraps are).
  for (const auto& in :
       {instance{40, 41, -42, every_nth_normal(8)}, instance{40, 42, -43, every_nth_normal(8)},
        instance{126, 128, -129, normals_up_to_x(-122)}, instance{125, 128, -129, normals_up_to_x(-122)}}) {
    const auto& normals = in.normals;
    const tp::light_grid g(in.s);
    const auto pruned = tp::wrap_search(normals, g, t, in.hi, in.lo, cfg);
    const auto table_brute = tp::wrap_search_brute(normals, g, t, in.hi, in.lo, cfg);
    const auto plain = brute(normals, g, in.hi, in.lo);
    EXPECT_EQ(pruned.hits.count, plain.count) << "s " << in.s << " hi " << in.hi;
    EXPECT_TRUE(pruned.hits.first == plain.first) << "s " << in.s;
    EXPECT_EQ(table_brute.hits.count, plain.count);
    EXPECT_LT(pruned.evaluated, table_brute.evaluated);
    if (in.s == 125) {
      EXPECT_EQ(plain.count, 0u) << "the bound says s = 125 cannot wrap";
    } else {
      EXPECT_GT(plain.count, 0u) << "s " << in.s << " hi " << in.hi;
    }
  }
}

namespace {
// error_extremes of one variant (na) against plain-int brute force on subsampled normals: `value` is
// the variant's formula (reference.hpp), `bound` the argument's |error| bound.
template <class Value>
void expect_error_extremes_equal_brute_force(tp::na_term na, Value value, int bound) {
  const tp::table t(gs::model_options{}, na);
  p::sweep_config cfg;
  for (std::size_t every : {std::size_t{37}, std::size_t{1000}}) {
    const auto normals = every_nth_normal(every);
    const tp::light_grid g(122);
    const auto r = tp::error_extremes(normals, g, t, cfg);
    int lo = 100, hi = -100;
    for (const auto& nm : normals) {
      const auto n = ref::appendix2(nm.iX, nm.iY);
      for (const auto& l : g.lights) {
        const int e = value(n, l[0], l[1], l[2]) - ref::floor128(n.x * l[0] + n.y * l[1] + n.z * l[2]);
        lo = std::min(lo, e), hi = std::max(hi, e);
      }
    }
    EXPECT_GE(lo, -bound);
    EXPECT_LE(hi, bound);
    EXPECT_EQ(r.err.min, lo) << "every " << every;
    EXPECT_EQ(r.err.max, hi) << "every " << every;
  }
}
}  // namespace

TEST(Reduction, ErrorExtremesEqualBruteForceOnSubsampledNormals) {
  expect_error_extremes_equal_brute_force(tp::na_term::thirds_in_alpha, ref::two_pass_value, 3);
}

// The three-pass variant: e = 0, so the ends are ±2.
TEST(Reduction, ThreePassErrorExtremesEqualBruteForceOnSubsampledNormals) {
  expect_error_extremes_equal_brute_force(tp::na_term::additive_pass, ref::three_pass_value, 2);
}

TEST(Reduction, InterpolatedLightsDoNotWrapAtTheArguedS) {
  // Short spans (the pre-triangle model of two-pass.max-s.interpolated): no span of <= 128 pixels
  // wraps for s <= 123, since the lag stays below 1 level per channel.
  // Brute force on the part of the domain nearest to wrapping: s = 123, the normals with iX = −127
  // (where the vertex wraps of s = 126 are), every ordered pair of vertex lights with n·l/128 >= 121.5
  // at Chebyshev distance 1, every span length and pixel; plain
  // ints: 8.7 channel = 128·c0 + k·trunc(128·Δ/n), pass 1 − pass 2 = ±floor(|n|·L87/2^14).
  const int s = 123;
  const tp::light_grid g(s);
  std::int64_t pixels = 0;
  int worst_hi = -1000, worst_lo = 1000;
  for (const auto& nm : normals_up_to_x(-127)) {
    const auto n = ref::appendix2(nm.iX, nm.iY);
    std::vector<p::ivec3> cap;
    for (const auto& l : g.lights) {
      const int nl = n.x * l[0] + n.y * l[1] + n.z * l[2];
      if (nl >= 128 * 121 + 64) cap.push_back(l);
    }
    const int nc[3] = {n.x, n.y, n.z};
    for (const auto& a : cap)
      for (const auto& b : cap) {
        if (a == b || std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])}) > 1) continue;
        for (int len = 1; len <= 128; ++len)
          for (int k = 0; k <= len; ++k) {
            int value = 3 * n.alpha - 384;
            for (int c = 0; c < 3; ++c) {
              const int c0 = 128 + a[static_cast<std::size_t>(c)], c1 = 128 + b[static_cast<std::size_t>(c)];
              const int L = 128 * c0 + k * ((128 * (c1 - c0)) / len);
              value += nc[c] >= 0 ? (nc[c] * L) / 16384 : -((-nc[c] * L) / 16384);
            }
            ++pixels;
            worst_hi = std::max(worst_hi, value), worst_lo = std::min(worst_lo, value);
          }
      }
  }
  EXPECT_GT(pixels, 1000000) << pixels;
  std::printf("s = 123: %lld pixels, value in [%d, %d]\n", static_cast<long long>(pixels), worst_lo, worst_hi);
  EXPECT_LE(worst_hi, 127) << "a wrap at s = 123 would contradict the argument";
  EXPECT_LE(worst_hi, s + 4);
  EXPECT_GE(worst_lo, -s - 5);
}

TEST(Reduction, AttenuatedLightsKeepTheTwoPassBoundsAtSmallerS) {
  // Domain option tolight = attenuated_T: the claims argue their bounds with |l| <= s only, so on
  // the whole ball of lights (not just the unit-T shell) at s = 40, by brute force in plain ints,
  // the error stays in [−3, 3] and the value in [−s − 3, s + 2], and the extremes over the ball are
  // those over the shell.
  const int s = 40;
  const auto ball = p::attenuated_lights(s), shell = p::packed_lights(s);
  EXPECT_GT(ball.size(), 2 * shell.size());
  for (const auto& l : shell) EXPECT_TRUE(std::binary_search(ball.begin(), ball.end(), l));
  auto extremes = [&](const std::vector<p::ivec3>& lights, int& vlo, int& vhi, int& elo, int& ehi) {
    vlo = elo = 1000, vhi = ehi = -1000;
    for (const auto& nm : every_nth_normal(7)) {
      const auto n = ref::appendix2(nm.iX, nm.iY);
      for (const auto& l : lights) {
        const int v = ref::two_pass_value(n, l[0], l[1], l[2]);
        const int e = v - ref::floor128(n.x * l[0] + n.y * l[1] + n.z * l[2]);
        vlo = std::min(vlo, v), vhi = std::max(vhi, v), elo = std::min(elo, e), ehi = std::max(ehi, e);
      }
    }
  };
  int bvlo, bvhi, belo, behi, svlo, svhi, selo, sehi;
  extremes(ball, bvlo, bvhi, belo, behi);
  extremes(shell, svlo, svhi, selo, sehi);
  EXPECT_GE(bvlo, -s - 3);
  EXPECT_LE(bvhi, s + 2);
  EXPECT_GE(belo, -3);
  EXPECT_LE(behi, 3);
  EXPECT_EQ(bvhi, svhi);
  EXPECT_EQ(bvlo, svlo);
  EXPECT_EQ(behi, sehi);
  EXPECT_EQ(belo, selo);
}

// lab.saturation sweeps two additions and argues n by induction; here three and four lights added in
// turn through the model's blend and clamp, against min(255, sum), on every 7th byte.
TEST(Reduction, LabSaturationHoldsForThreeAndFourLights) {
  namespace m = gsdot3::proofs::methods;
  const gs::model_options o{};
  auto add = [&](int d, int x) {
    return gs::colclamp(gs::alpha_blend(m::add_blend, m::grey(x, 0), m::grey(d, 0), o), m::byte(0), true).r.value();
  };
  std::uint64_t checked = 0;
  for (int d = 0; d < 256; d += 7)
    for (int x = 0; x < 256; x += 7)
      for (int y = 0; y < 256; y += 7)
        for (int z = 0; z < 256; z += 7) {
          ASSERT_EQ(add(add(add(d, x), y), z), std::min(255, d + x + y + z)) << d << " " << x << " " << y << " " << z;
          ASSERT_EQ(add(add(add(add(d, x), y), z), x), std::min(255, d + 2 * x + y + z));
          ++checked;
        }
  EXPECT_EQ(checked, 37u * 37 * 37 * 37);
}
