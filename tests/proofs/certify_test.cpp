// The certified relaxation bound (proofs/triangle_certify): weak duality against independent points
// (relaxation_value, the ledger's objective, at random geometries of a rectangle and random lights in
// the ball never exceeds the certified bound of the pattern the point lies in, the pattern read from
// a plane solved here by Cramer's rule), the exact check against the closed form of the always
// feasible dual (y_p = w: s·|w| + every charged axis lagged), the dual at the relaxation witnesses'
// geometries against their attained values, and a certified class against random general triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "proofs/paper_code.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "two_pass_triangle/triangle_certify.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;
namespace tc = gsdot3::proofs::two_pass::triangle::certify;

namespace {
using geometry = std::array<std::array<double, 2>, 3>;
using lights = std::array<std::array<double, 3>, 3>;

// The pattern of a point: bit 2c + ax set where t = −128·G_{c,ax} >= 0, G from the plane through
// the three lights (Cramer's rule on [x y 1]·(Gx, Gy, Q) = ℓ).
unsigned pattern_of(const geometry& v, const lights& l) {
  const double det =
      v[0][0] * (v[1][1] - v[2][1]) - v[0][1] * (v[1][0] - v[2][0]) + (v[1][0] * v[2][1] - v[2][0] * v[1][1]);
  unsigned pi = 0;
  for (int c = 0; c < 3; ++c) {
    const double gx =
        (l[0][c] * (v[1][1] - v[2][1]) - v[0][1] * (l[1][c] - l[2][c]) + (l[1][c] * v[2][1] - l[2][c] * v[1][1])) / det;
    const double gy =
        (v[0][0] * (l[1][c] - l[2][c]) - l[0][c] * (v[1][0] - v[2][0]) + (v[1][0] * l[2][c] - v[2][0] * l[1][c])) / det;
    if (-gx >= 0) pi |= 1u << (2 * c);
    if (-gy >= 0) pi |= 2u << (2 * c);
  }
  return pi;
}

double value(const geometry& v, int pix, const lights& l, const tc::problem& pr) {
  tt::relaxation_point x{};
  x.vertex = v;
  x.pixel = v[static_cast<std::size_t>(pix)];
  x.light = l;
  return tt::relaxation_value(x, {double(pr.w[0]), double(pr.w[1]), double(pr.w[2])}, pr.s);
}

geometry to_pixels(const tc::vertices& V) {
  geometry g{};
  for (std::size_t k = 0; k < 3; ++k) g[k] = {double(V[k][0]) / tc::coord_one, double(V[k][1]) / tc::coord_one};
  return g;
}

// A random light in the ball of radius s, or s·y/|y| moved a little (near the pattern's maximiser).
std::array<double, 3> light(std::mt19937& rng, const std::array<double, 3>& y, double s) {
  std::normal_distribution<double> n(0, 1);
  std::array<double, 3> l{};
  const double ny = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  const bool near = ny > 0 && rng() % 4 != 0;
  for (std::size_t c = 0; c < 3; ++c) l[c] = near ? s * y[c] / ny + 0.3 * n(rng) : s * n(rng) / 2;
  const double nl = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
  if (nl > s)
    for (double& c : l) c *= s / nl;
  return l;
}
}  // namespace

TEST(TriangleCertify, WeakDualityOnRandomRectanglesAndLights) {
  std::mt19937 rng(13);
  std::uniform_int_distribution<int> weight(0, 127), fam(0, tc::family_count - 1), vertex(0, 2), exp(-2, 9);
  std::uniform_real_distribution<double> unit(0, 1);
  int points = 0, feasible = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const tc::problem pr{{weight(rng), weight(rng), weight(rng)}, 60 + trial % 40, 0};
    const int f = fam(rng), pix = vertex(rng);
    const std::int64_t size = std::int64_t{1} << (tc::coord_bits + exp(rng)), A = 2048 * tc::coord_one;
    const std::int64_t u0 = static_cast<std::int64_t>(unit(rng) * double(A - size)),
                       v0 = static_cast<std::int64_t>(unit(rng) * double(A - size));
    const tc::corners g = tc::family_cell(f, pix, u0, u0 + size, v0, v0 + size, 2048);
    std::array<tc::check, 64> bound{};
    std::array<tc::dual_real, 64> y{};
    for (unsigned pi : tc::patterns(pr)) {
      y[pi] = tc::search_dual(pr, g, pi, nullptr);
      bound[pi] = tc::check_dual(pr, g, pi, tc::to_grid(pr, y[pi], pix));
      feasible += bound[pi].feasible;
    }
    for (int q = 0; q < 400; ++q) {
      const double u = double(u0) + unit(rng) * double(size), v = double(v0) + unit(rng) * double(size);
      const geometry gv = to_pixels(tc::family_member(f, std::llround(u), std::llround(v), 2048));
      const auto& yy = y[rng() % 64];
      lights l{};
      for (std::size_t k = 0; k < 3; ++k) l[k] = light(rng, yy[k], pr.s);
      unsigned pi = pattern_of(gv, l);
      for (int c = 0; c < 3; ++c)
        if (pr.w[c] == 0) pi &= ~(3u << (2 * c));  // the duplicates patterns() leaves out (y_c = 0)
      if (!bound[pi].feasible) continue;
      // A primal ascent inside the point's pattern region: moves of the lights kept while the value
      // rises and the pattern stays (the points where a wrong dual would show).
      double val = value(gv, pix, l, pr);
      std::normal_distribution<double> step(0, 1);
      for (int it = 0; it < (q % 4 == 0 ? 300 : 0); ++it) {
        lights m = l;
        const double h = 2.0 / (1 + it / 30);
        for (auto& lk : m) {
          for (double& c : lk) c += h * step(rng);
          const double nl = std::sqrt(lk[0] * lk[0] + lk[1] * lk[1] + lk[2] * lk[2]);
          if (nl > pr.s)
            for (double& c : lk) c *= pr.s / nl;
        }
        unsigned pm = pattern_of(gv, m);
        for (int c = 0; c < 3; ++c)
          if (pr.w[c] == 0) pm &= ~(3u << (2 * c));
        if (const double vm = value(gv, pix, m, pr); pm == pi && vm > val) l = m, val = vm;
      }
      ++points;
      EXPECT_LE(val, static_cast<double>(bound[pi].levels) + 1e-9 * std::fabs(val))
          << "family " << f << " p " << pix << " pattern " << pi << " u " << u << " v " << v;
    }
  }
  EXPECT_GT(feasible, 60 * 40);  // the search's y passes the exact check almost always
  EXPECT_GT(points, 60 * 300);
}

// Weak duality where it is tight: the relaxation witnesses' lights (attained values above the wrap
// threshold) at geometries of small rectangles around theirs, which are members of F1 with box 2047
// ((0, u), (v, 0), (A, A), p = (A, A)); a rectangle reaching past the box is moved inside it.
TEST(TriangleCertify, WeakDualityAroundTheWitnesses) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> noise(0, 0.02);
  int points = 0;
  for (const auto& wit : tt::relaxation_witnesses()) {
    const auto nm = p::paper::pack_normal_from(wit.iX, wit.iY);
    const tc::problem pr{{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)}, wit.s, 0};
    ASSERT_EQ(wit.at.vertex[0][0], 0);
    ASSERT_EQ(wit.at.vertex[1][1], 0);
    ASSERT_EQ(wit.at.vertex[2][0], 2047);
    ASSERT_EQ(wit.at.vertex[2][1], 2047);
    const std::int64_t box = 2047 * tc::coord_one;
    const std::int64_t u_at = std::llround(wit.at.vertex[0][1] * tc::coord_one),
                       v_at = std::llround(wit.at.vertex[1][0] * tc::coord_one);
    double closest = -1e30;
    for (int e = -4; e <= 4; ++e) {
      const std::int64_t h = std::int64_t{1} << (tc::coord_bits + e);
      const std::int64_t u = std::min(u_at + h / 2, box),
                         v = std::min(v_at + h / 2, box);  // the rectangles' top corners
      const tc::corners g = tc::family_cell(0, 2, u - h, u, v - h, v, 2047);
      std::array<tc::check, 64> bound{};
      for (unsigned pi : tc::patterns(pr))
        bound[pi] = tc::check_dual(pr, g, pi, tc::to_grid(pr, tc::search_dual(pr, g, pi, nullptr), 2));
      for (int q = 0; q < 100; ++q) {
        const std::int64_t gu = u - static_cast<std::int64_t>(unit(rng) * double(h)),
                           gv = v - static_cast<std::int64_t>(unit(rng) * double(h));
        const geometry x = to_pixels(tc::family_member(0, gu, gv, 2047));
        lights l = wit.at.light;
        for (auto& lk : l)
          for (double& c : lk) c += noise(rng);
        const unsigned pi = pattern_of(x, l);
        ASSERT_TRUE(bound[pi].feasible) << e << " " << pi;
        const double val = value(x, 2, l, pr);
        ++points;
        closest = std::max(closest, val - static_cast<double>(bound[pi].levels));
        EXPECT_LE(val, static_cast<double>(bound[pi].levels)) << "rectangle 2^" << e << " pattern " << pi;
      }
    }
    EXPECT_GT(closest, -10) << "the points come near the bound";
  }
  EXPECT_EQ(points, 2 * 9 * 100);
}

// check_dual against the same sums in long double, exact here: coordinates on a 2^-4 pixel grid and
// |y| <= 200 keep every product and sum below 2^64.
TEST(TriangleCertify, ExactCheckAgreesWithLongDoubleOnAGrid) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> weight(0, 127), fam(0, tc::family_count - 1), vertex(0, 2), grid(0, 2048 * 16);
  std::uniform_real_distribution<double> unit(-1, 1);
  int feasible = 0, infeasible = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const tc::problem pr{{weight(rng), weight(rng), weight(rng)}, 1 + trial % 127, 0};
    const int f = fam(rng), pix = vertex(rng);
    std::int64_t c[4];
    for (auto& x : c) x = std::int64_t{grid(rng)} << (tc::coord_bits - 4);
    if (trial % 3 == 0) c[1] = c[0], c[3] = c[2];  // one geometry
    const tc::corners g = tc::family_cell(f, pix, std::min(c[0], c[1]), std::max(c[0], c[1]), std::min(c[2], c[3]),
                                          std::max(c[2], c[3]), 2048);
    const unsigned pi = static_cast<unsigned>(rng() % 64);
    tc::dual_real y = trial % 2 ? tc::search_dual(pr, g, pi, nullptr) : tc::dual_real{};
    const double noise = trial % 4 < 2 ? 0 : std::ldexp(1.0, -static_cast<int>(rng() % 30));
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t ch = 0; ch < 3; ++ch) y[k][ch] = std::clamp(y[k][ch] + noise * 100 * unit(rng), -200.0, 200.0);
    const tc::dual_grid Y = tc::to_grid(pr, y, pix);
    bool ok = true;
    long double lag = 0;
    for (const auto& V : g.at) {
      long double sum = 0;
      for (std::size_t ch = 0; ch < 3; ++ch)
        for (std::size_t ax = 0; ax < 2; ++ax) {
          long double kappa = 0, m = 0;
          for (std::size_t k = 0; k < 3; ++k) {
            kappa += static_cast<long double>(Y[k][ch]) *
                     static_cast<long double>(V[static_cast<std::size_t>(pix)][ax] - V[k][ax]);
            m += static_cast<long double>(Y[k][ch]) * static_cast<long double>(V[k][ax]) / 0x1p44L;
          }
          const bool charged = pi >> (2 * ch + ax) & 1;
          if (charged ? kappa < 0 : kappa > 0) ok = false;
          if (charged && m > 0) sum += m / 128;
        }
      lag = std::max(lag, sum);
    }
    long double norms = 0;
    for (const auto& yk : Y) {
      long double n2 = 0;
      for (std::int64_t v : yk) n2 += static_cast<long double>(v) * static_cast<long double>(v);
      norms += std::sqrt(n2) / 0x1p24L;
    }
    const tc::check k = tc::check_dual(pr, g, pi, Y);
    ASSERT_EQ(k.feasible, ok) << trial;
    (ok ? feasible : infeasible)++;
    if (ok) {
      const long double expect = pr.s * norms + lag;
      // above by at most the three square roots' rounding up (2^-24 each, times s)
      EXPECT_GE(k.levels, expect - 1e-9L) << trial;
      EXPECT_LE(k.levels, expect + pr.s * 3 * 0x1p-24L + 1e-9L) << trial;
    }
  }
  EXPECT_GT(feasible, 300);
  EXPECT_GT(infeasible, 300);
}

TEST(TriangleCertify, ExactCheckOfTheTrivialDualIsItsClosedForm) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> weight(0, 127), fam(0, tc::family_count - 1), vertex(0, 2);
  std::uniform_int_distribution<std::int64_t> coord(0, 2048 * tc::coord_one);
  for (int trial = 0; trial < 200; ++trial) {
    const tc::problem pr{{weight(rng), weight(rng), weight(rng)}, 1 + trial % 127, 0};
    const int f = fam(rng), pix = vertex(rng);
    std::int64_t u0 = coord(rng), u1 = coord(rng), v0 = coord(rng), v1 = coord(rng);
    if (u0 > u1) std::swap(u0, u1);
    if (v0 > v1) std::swap(v0, v1);
    const tc::corners g = tc::family_cell(f, pix, u0, u1, v0, v1, 2048);
    tc::dual_real y{};
    for (std::size_t c = 0; c < 3; ++c) y[static_cast<std::size_t>(pix)][c] = pr.w[c];
    const unsigned pi = static_cast<unsigned>(rng() % 64) & [&] {
      unsigned m = 0;
      for (int c = 0; c < 3; ++c) m |= pr.w[c] ? 3u << (2 * c) : 0;
      return m;
    }();
    const tc::check k = tc::check_dual(pr, g, pi, tc::to_grid(pr, y, pix));
    ASSERT_TRUE(k.feasible);
    // s·|w| + max over the corners of Σ_charged w_c·p_ax/128 (p is the pixel's coordinates there).
    double lag = 0;
    for (const auto& V : g.at) {
      double sum = 0;
      for (int c = 0; c < 3; ++c)
        for (int ax = 0; ax < 2; ++ax)
          if (pi >> (2 * c + ax) & 1)
            sum += pr.w[c] * double(V[static_cast<std::size_t>(pix)][ax]) / tc::coord_one / 128;
      lag = std::max(lag, sum);
    }
    const double expect = pr.s * std::sqrt(double(pr.w[0] * pr.w[0] + pr.w[1] * pr.w[1] + pr.w[2] * pr.w[2])) + lag;
    EXPECT_NEAR(static_cast<double>(k.levels), expect, 1e-4) << trial;
    EXPECT_GE(static_cast<double>(k.levels), expect - 1e-9);  // the square root is rounded up
  }
}

TEST(TriangleCertify, DualAtTheWitnessGeometriesMatchesTheirAttainedValue) {
  for (const auto& wit : tt::relaxation_witnesses()) {
    const auto nm = p::paper::pack_normal_from(wit.iX, wit.iY);
    const tc::problem pr{{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)}, wit.s, 0};
    tc::corners g;
    g.p = 2;  // the witnesses' pixel is their third vertex
    ASSERT_EQ(wit.at.pixel, wit.at.vertex[2]);
    tc::vertices V{};
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t ax = 0; ax < 2; ++ax) V[k][ax] = std::llround(wit.at.vertex[k][ax] * tc::coord_one);
    g.at = {V};
    const geometry gv = to_pixels(V);
    const double witness = value(gv, 2, wit.at.light, pr);
    double best = -1e30, best_attained = -1e30;
    for (unsigned pi : tc::patterns(pr)) {
      const tc::dual_real y = tc::search_dual(pr, g, pi, nullptr);
      const tc::check k = tc::check_dual(pr, g, pi, tc::to_grid(pr, y, 2));
      ASSERT_TRUE(k.feasible) << pi;
      best = std::max(best, static_cast<double>(k.levels));
      best_attained = std::max(best_attained, tc::attained(pr, gv, 2, y));
    }
    // The dual's least bound is an upper bound of every point (weak duality); its own lights attain
    // it (no duality gap) and improve on the witness (lights of the θ-dual's optimum, to three decimals).
    EXPECT_GE(best, witness);
    EXPECT_LE(best_attained, best + 1e-9);
    EXPECT_GT(best_attained, best - 0.05) << "attained " << best_attained << " dual " << best;
    EXPECT_GE(best_attained, witness);
    EXPECT_LT(best - witness, 8.0) << "witness " << witness << " dual " << best;
  }
}

TEST(TriangleCertify, ACertifiedClassHoldsOnRandomGeneralTriangles) {
  // |n| = (67, 73, 81) at s = 83 under keep_fraction, the first class of `tools/proofs_triangle certify
  // 83`: threshold 15998.2734 = (16384·125 − |n|_1)/128, 128 − #neg − e = 125 (without the floors'
  // 1/16384 level per negative channel that the ledger's threshold adds: stricter than the ledger's).
  const tc::problem pr{{67, 73, 81}, 83, std::int64_t{16384} * 125 - 221};
  const tc::outcome r = tc::certify_class(pr, 2048, std::int64_t{1} << (tc::coord_bits - 2), 200000);
  ASSERT_EQ(r.open_count, 0);
  EXPECT_LT(r.worst_closed * 128, static_cast<long double>(pr.threshold128));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(0, 2047);
  double best = -1e30;
  for (int q = 0; q < 300; ++q) {
    geometry gv{};
    for (auto& v : gv) v = {coord(rng), coord(rng)};
    const double mx = std::min({gv[0][0], gv[1][0], gv[2][0]}), my = std::min({gv[0][1], gv[1][1], gv[2][1]});
    for (auto& v : gv) v[0] -= mx, v[1] -= my;  // r = (0, 0): the least vertex coordinates
    const int pix = q % 3;
    tc::corners g;
    g.p = pix;
    tc::vertices V{};
    for (std::size_t k = 0; k < 3; ++k)
      V[k] = {std::llround(gv[k][0] * tc::coord_one), std::llround(gv[k][1] * tc::coord_one)};
    g.at = {V};
    for (unsigned pi : tc::patterns(pr))
      best = std::max(best, tc::attained(pr, to_pixels(V), pix, tc::search_dual(pr, g, pi, nullptr)));
  }
  EXPECT_LT(best * 128, static_cast<double>(pr.threshold128));
  // above what equal lights s·w/|w| attain without any lag: the search's lights use the lag
  EXPECT_GT(best, pr.s * std::sqrt(67.0 * 67 + 73 * 73 + 81 * 81));
}

TEST(TriangleCertify, TheWitnessesClassesDoNotClose) {
  // Each relaxation witness is a point of the relaxation above its threshold (relaxation_margin, the
  // ledger's figure): the branch and bound of its class must stop there open, never report it closed.
  for (const auto& wit : tt::relaxation_witnesses()) {
    gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
    o.gouraud = wit.gouraud;
    const p::two_pass::table t(o);
    ASSERT_GT(tt::relaxation_margin(wit, t, o), 0);
    const auto nm = p::paper::pack_normal_from(wit.iX, wit.iY);
    const int e = t.alpha_error(nm);
    const int l1 = std::abs(nm.iX) + std::abs(nm.iY) + std::abs(nm.iZ);
    const tc::problem pr{{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)},
                         wit.s,
                         tt::wrap_threshold_units(nm, e, wit.side, o) - tt::truncation_units(nm, wit.side, o) - l1};
    const tc::outcome r = tc::certify_class(pr, 2048, std::int64_t{1} << (tc::coord_bits - 2), 200000);
    EXPECT_GT(r.open_count, 0);
    EXPECT_TRUE(r.exceeds);
    EXPECT_GT(r.witness.attained * 128, static_cast<double>(pr.threshold128));
  }
}

TEST(TriangleCertify, TheRelaxationExceedsAt83UnderTruncate) {
  // The point `tools/proofs_triangle certify 83 --truncate-to-8` (its defaults: box 2047) stops at for
  // class #0 (bottom of pack(67, 73)), box 2047, lights as printed (9 decimals): relaxation_margin,
  // the ledger's figure, is positive, so s = 83 under truncate_to_8 is beyond the relaxation.
  // It is the truncate_to_8 row of relaxation_witnesses().
  const auto rows = tt::relaxation_witnesses();
  const auto it = std::find_if(rows.begin(), rows.end(), [](const tt::relaxation_witness& r) { return r.s == 83; });
  ASSERT_NE(it, rows.end());
  const tt::relaxation_witness& w = *it;
  EXPECT_EQ(w.gouraud, gs::gouraud_fraction::truncate_to_8);
  gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
  o.gouraud = w.gouraud;
  const p::two_pass::table t(o);
  const double margin = tt::relaxation_margin(w, t, o);
  EXPECT_GT(margin, 0.015);
  EXPECT_LT(margin, 0.02);
}
