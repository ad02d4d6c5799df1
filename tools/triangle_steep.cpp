// proofs_triangle steep — triangle certificates of two-pass.max-s.interpolated in which the third
// channel lags too, through a steep step on the other axis. Not a benchmark and not a test: a
// reproducible tool (no randomness); every row it prints is re-verified by the claim and replayed
// through the rasteriser in tests/proofs/triangle_test.cpp.
//
//   proofs_triangle steep S [--truncate-to-8] IX IY SIDE THIRD LX0 LX1 LX2 D1 D2 YX_LO YX_HI [BOX T1 T2 NR SIGNS MIN]
// Geometry: X = (0, yX) with yX well above the pixel's row, Y = (xY, 0), Z = (xZ, yZ) with yZ in
// 2044..2047, the pixel next to Z; the reference pixel is r = (0, 0). Wrap side SIDE (+1: top,
// −1: bottom), σ_c = SIDE·sign n_c.
//  - The two lag channels (every channel but THIRD) fall by D1 levels from X to Y and by D2 from X to
//    Z along σ, with xY − yX = 128·D1 + t1/16 and xZ + yZ − yX = 128·D2 + t2/16 pixels: both of their
//    steps are then just below one unit per pixel (checked exactly, in (0.99, 1)), truncate to 0,
//    and the pixel keeps the plane's value at r: ~2046 units of lag per axis.
//  - The THIRD channel: its x step just below one unit (−σ·(0.99, 1): the x lag) and its y step
//    σ·K plus less than 0.006 for an integer K >= 1 (a steep rise towards Z's row that truncation
//    keeps). With yX far above the pixel's row that rise lets the plane at the pixel sit far from
//    X's light on this channel, so the third channel gets a whole axis of lag on top of a value the
//    lag channels' two points do not pin down (the bound's (ii)/(iii) charge it W over P(p), with
//    nothing tying P(p) to the vertex lights but the ball; here the third vertex Y pays for it).
//  For each geometry (yX from YX_LO to YX_HI pixels in 1/16, D1 ± 2, D2 ± 2, t1 = 1, 3, .. T1,
//  t2 = 1, 5, .. T2, yZ = 2047 − 0..3) and K = 1..15, the integer differences (e1, e2) of the third
//  channel from X to Y and to Z follow from the two step windows; X's light runs over the box
//  LX ± BOX per channel, and all three lights must be packed lights of L_S. Each case is scored
//  exactly (score_near_vertices around Z). The start values (LX, D1, D2, the yX range) came from
//  a continuous relaxation of the same arithmetic (lights in the real ball, any real geometry),
//  which this tool does not contain; any values can be tried.
// The floors: the value is a sum of floors of n_c·L_c per pass (two_pass::pixel), so a case whose
// smooth part (with the normal IX, IY) is at least MIN (default 125.5) is also scored with every
// Appendix 2 normal within ±NR of (IX, IY) (default 0) and, with SIGNS = 1, under all eight sign
// patterns of (n_x, n_y, wrap side): the pattern's lights are the case's with channel c negated
// where its wrap-side sign σ_c changes, so every folded value σ_c·(L_c − 128) and the geometry stay
// as they are (the GS's truncations toward zero are odd) and only the floors and the alpha error move.
// Prints the first wrapping case as a certificate row, or the best wrap-side value reached and its
// case in the table's format.
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <utility>

#include "proofs/domains.hpp"
#include "triangle_args.hpp"
#include "triangle_score.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;
namespace tl = gsdot3::tools;

namespace {
constexpr int max124 = (tt::window_pixels - 1) * 16;

struct steep_args {
  tl::search_args search;
  int iX = 0, iY = 0, side = 1, third = 0;
  std::array<int, 3> lx{};
  int d1 = 0, d2 = 0, yx_lo = 0, yx_hi = 0, box = 5, t1 = 60, t2 = 200, nr = 0, signs = 0;
  double min_smooth = 125.5;
};

int run(const steep_args& a) {
  const auto& args = a.search;
  const int s = args.s;
  const gs::model_options o = args.options();
  const p::two_pass::table t(o);
  const auto nm = p::paper::pack_normal_from(a.iX, a.iY);
  const int n[3] = {nm.iX, nm.iY, nm.iZ};
  int sg[3];
  for (int c = 0; c < 3; ++c) sg[c] = (n[c] >= 0 ? 1 : -1) * a.side;
  const int c3 = a.third, ca = (c3 + 1) % 3, cb = (c3 + 2) % 3;
  std::set<std::pair<int, int>> normals;
  for (const auto& m : p::appendix2_normals()) normals.insert({m.iX, m.iY});
  tl::found best;
  long long evaluated = 0, explored = 0;
  tl::progress rows("steep: yZ, yX rows", 4LL * (16 * (a.yx_hi - a.yx_lo) + 1));
  long long row = 0;
  for (int yZ16 = max124; yZ16 >= max124 - 48; yZ16 -= 16)
    for (int yX16 = a.yx_lo * 16; yX16 <= a.yx_hi * 16; ++yX16, rows.at(++row))
      for (int d1 = a.d1 - 2; d1 <= a.d1 + 2; ++d1)
        for (int d2 = a.d2 - 2; d2 <= a.d2 + 2; ++d2)
          for (int t1 = 1; t1 <= a.t1; t1 += 2)
            for (int t2 = 1; t2 <= a.t2; t2 += 4) {
              const int xY16 = yX16 + 16 * 128 * d1 + t1, xZ16 = yX16 + 16 * 128 * d2 + t2 - yZ16;
              if (xY16 > max124 || xZ16 > max124 || xZ16 < 0) continue;
              // edge vectors X→Y, X→Z in pixels; a channel's steps g solve M·g = 128·(Δ_Y, Δ_Z)
              const double ax = xY16 / 16.0, ay = -yX16 / 16.0, bx = xZ16 / 16.0, by = (yZ16 - yX16) / 16.0,
                           det = ax * by - bx * ay;
              const double lag_x = 128 * (d1 * by - d2 * ay) / det, lag_y = 128 * (d2 * ax - d1 * bx) / det;
              if (!(lag_x > 0.99 && lag_x < 1.0 && lag_y > 0.99 && lag_y < 1.0)) continue;
              for (int K = 1; K <= 15; ++K) {
                // the third channel's (e1, e2) for steps in the window: e·128 = M·g at its corners
                double lo1 = 1e9, hi1 = -1e9, lo2 = 1e9, hi2 = -1e9;
                for (double gx : {-1.0, -0.99})
                  for (double gy : {double(K), K + 0.006}) {
                    const double v1 = sg[c3] * (ax * gx + ay * gy) / 128, v2 = sg[c3] * (bx * gx + by * gy) / 128;
                    lo1 = std::min(lo1, v1), hi1 = std::max(hi1, v1), lo2 = std::min(lo2, v2), hi2 = std::max(hi2, v2);
                  }
                for (int e1 = static_cast<int>(std::ceil(lo1)); e1 <= static_cast<int>(std::floor(hi1)); ++e1)
                  for (int e2 = static_cast<int>(std::ceil(lo2)); e2 <= static_cast<int>(std::floor(hi2)); ++e2) {
                    const double gx = sg[c3] * 128 * (e1 * by - e2 * ay) / det,
                                 gy = sg[c3] * 128 * (e2 * ax - e1 * bx) / det;
                    if (!(gx < -0.99 && gx > -1.0 && gy > 0.5 && gy - std::trunc(gy) < 0.006)) continue;
                    for (int i = -a.box; i <= a.box; ++i)
                      for (int j = -a.box; j <= a.box; ++j)
                        for (int k = -a.box; k <= a.box; ++k) {
                          p::ivec3 lx{a.lx[0] + i, a.lx[1] + j, a.lx[2] + k};
                          p::ivec3 ly = lx, lz = lx;
                          ly[ca] -= sg[ca] * d1, ly[cb] -= sg[cb] * d1, ly[c3] += e1;
                          lz[ca] -= sg[ca] * d2, lz[cb] -= sg[cb] * d2, lz[c3] += e2;
                          if (!p::is_packed_light(s, lx) || !p::is_packed_light(s, ly) || !p::is_packed_light(s, lz))
                            continue;
                          const tt::triangle_case c{s, a.iX, a.iY, {lx, ly, lz}, {0, yX16, xY16, 0, xZ16, yZ16}, 0, 0};
                          tl::found f{c, tl::score_near_vertices(c, o, t, a.side, 2, 4), a.side};
                          ++evaluated;
                          if (f.sc.value < 128 && f.sc.smooth >= a.min_smooth && (a.nr > 0 || a.signs)) {
                            f = tl::explore(c, a.side, a.nr, a.signs != 0, o, t, normals);
                            ++explored;
                          }
                          if (tl::better(f.sc, best.sc)) best = f;
                          if (f.sc.value >= 128) {
                            tl::print_certificate_row(f.c, f.sc, args.option_name());
                            std::printf("(side %+d; %lld cases evaluated, %lld explored)\n", f.side, evaluated,
                                        explored);
                            return 0;
                          }
                        }
                  }
              }
            }
  std::printf(
      "s = %d (%s): no wrap, best wrap-side value %d (smooth %.3f) at (%d, %d), side %+d, %lld cases evaluated, %lld "
      "explored; its case:\n",
      s, args.option_name(), best.sc.value, best.sc.smooth, best.sc.px, best.sc.py, best.side, evaluated, explored);
  tl::print_certificate_row(best.c, best.sc, args.option_name(), "best");
  return 1;
}
}  // namespace

void gsdot3::tools::add_steep_command(CLI::App& app, int& rc) {
  auto a = std::make_shared<steep_args>();
  CLI::App* cmd = app.add_subcommand("steep",
                                     "The steep third-channel construction: the certificate rows at s = 86, 85 (one "
                                     "per option) and 84 (truncate_to_8)");
  cmd->footer(
      "Prints the first wrapping case as a certificate row (exit status 0), or the best case reached (1). Seconds to "
      "minutes.");
  add_search_args(*cmd, a->search);
  cmd->add_option("IX", a->iX, "The normal pack(IX, IY)")->required();
  cmd->add_option("IY", a->iY, "")->required();
  cmd->add_option("SIDE", a->side, "The wrap side: 1 top (value >= 128), -1 bottom (<= -129)")
      ->required()
      ->check(CLI::IsMember({1, -1}));
  cmd->add_option("THIRD", a->third, "The channel that gets the steep y step (0..2)")
      ->required()
      ->check(CLI::Range(0, 2));
  cmd->add_option("LX0", a->lx[0], "X's light, the centre of the box searched")->required();
  cmd->add_option("LX1", a->lx[1], "")->required();
  cmd->add_option("LX2", a->lx[2], "")->required();
  cmd->add_option("D1", a->d1, "The lag channels' fall from X to Y, levels (searched ±2)")
      ->required()
      ->check(CLI::Range(3, 255));
  cmd->add_option("D2", a->d2, "The lag channels' fall from X to Z, levels (searched ±2)")->required();
  cmd->add_option("YX_LO", a->yx_lo, "X's y, pixels: from")->required()->check(CLI::Range(0, 2047));
  cmd->add_option("YX_HI", a->yx_hi, "to")->required()->check(CLI::Range(0, 2047));
  cmd->add_option("BOX", a->box, "X's light runs over LX ± BOX per channel (default 5)")->check(CLI::NonNegativeNumber);
  cmd->add_option("T1", a->t1, "Y's x offsets 1, 3, .. T1 sixteenths (default 60)");
  cmd->add_option("T2", a->t2, "Z's x offsets 1, 5, .. T2 sixteenths (default 200)");
  cmd->add_option("NR", a->nr, "Also score the normals within ±NR of (IX, IY) (default 0)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("SIGNS", a->signs, "1: also every sign pattern of (n_x, n_y, side) (default 0)")
      ->check(CLI::IsMember({0, 1}));
  cmd->add_option("MIN", a->min_smooth, "The smooth part from which NR and SIGNS apply (default 125.5)");
  cmd->callback([a, &rc] {
    if (a->yx_lo > a->yx_hi) throw CLI::ValidationError("YX_LO", "must not exceed YX_HI");
    rc = run(*a);
  });
}
