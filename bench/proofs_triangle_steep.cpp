// proofs_triangle_steep — triangle certificates of two-pass.max-s.interpolated in which the third
// channel lags too, through a steep step on the other axis. Not a benchmark and not a test: a
// reproducible tool (no randomness); every row it prints is re-verified by the claim and replayed
// through the rasteriser in tests/proofs/triangle_test.cpp.
//
//   proofs_triangle_steep S [truncate_to_8] IX IY SIDE THIRD LX0 LX1 LX2 D1 D2 YX_LO YX_HI [BOX T1 T2 NR SIGNS MIN]
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
//  exactly (bench::score_near_vertices around Z). The start values (LX, D1, D2, the yX range) came from
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
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <utility>

#include "proofs_search_args.hpp"
#include "proofs_triangle_score.hpp"
#include "proofs/domains.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;
namespace bench = gsdot3::bench;

namespace {
constexpr int max124 = (tt::window_pixels - 1) * 16;

struct steep_args {
  int iX, iY, side, third;
  int lx[3];
  int d1, d2, yx_lo, yx_hi, box = 5, t1 = 60, t2 = 200, nr = 0, signs = 0;
  double min_smooth = 125.5;
};

steep_args parse(int argc, char** argv, int next) {
  if (argc < next + 11) {
    std::fprintf(stderr, "usage: proofs_triangle_steep S [truncate_to_8] IX IY SIDE THIRD LX0 LX1 LX2 D1 D2 YX_LO YX_HI [BOX T1 T2 NR SIGNS MIN]\n");
    std::exit(2);
  }
  auto at = [&](int k) { return std::atoi(argv[next + k]); };
  steep_args a{at(0), at(1), at(2), at(3), {at(4), at(5), at(6)}, at(7), at(8), at(9), at(10)};
  if (argc > next + 11) a.box = at(11);
  if (argc > next + 12) a.t1 = at(12);
  if (argc > next + 13) a.t2 = at(13);
  if (argc > next + 14) a.nr = at(14);
  if (argc > next + 15) a.signs = at(15);
  if (argc > next + 16) a.min_smooth = std::atof(argv[next + 16]);
  if ((a.side != 1 && a.side != -1) || a.third < 0 || a.third > 2 || a.d1 < 3 || a.yx_lo < 0 || a.yx_hi > 2047 || a.nr < 0 ||
      (a.signs != 0 && a.signs != 1)) {
    std::fprintf(stderr, "proofs_triangle_steep: SIDE is 1 or -1, THIRD 0..2, D1 >= 3, 0 <= YX_LO <= YX_HI <= 2047, NR >= 0, SIGNS 0 or 1\n");
    std::exit(2);
  }
  return a;
}
}  // namespace

int main(int argc, char** argv) {
  const auto args = bench::parse_search_args(argc, argv, "proofs_triangle_steep", " IX IY SIDE THIRD LX0 LX1 LX2 D1 D2 YX_LO YX_HI [BOX T1 T2 NR SIGNS MIN]");
  const steep_args a = parse(argc, argv, args.next);
  const int s = args.s;
  const p::two_pass::table t(args.o);
  const auto nm = p::paper::pack_normal_from(a.iX, a.iY);
  const int n[3] = {nm.iX, nm.iY, nm.iZ};
  int sg[3];
  for (int c = 0; c < 3; ++c) sg[c] = (n[c] >= 0 ? 1 : -1) * a.side;
  const int c3 = a.third, ca = (c3 + 1) % 3, cb = (c3 + 2) % 3;
  std::set<std::pair<int, int>> normals;
  for (const auto& m : p::appendix2_normals()) normals.insert({m.iX, m.iY});
  bench::found best;
  long long evaluated = 0, explored = 0;
  for (int yZ16 = max124; yZ16 >= max124 - 48; yZ16 -= 16)
    for (int yX16 = a.yx_lo * 16; yX16 <= a.yx_hi * 16; ++yX16)
      for (int d1 = a.d1 - 2; d1 <= a.d1 + 2; ++d1)
        for (int d2 = a.d2 - 2; d2 <= a.d2 + 2; ++d2)
          for (int t1 = 1; t1 <= a.t1; t1 += 2)
            for (int t2 = 1; t2 <= a.t2; t2 += 4) {
              const int xY16 = yX16 + 16 * 128 * d1 + t1, xZ16 = yX16 + 16 * 128 * d2 + t2 - yZ16;
              if (xY16 > max124 || xZ16 > max124 || xZ16 < 0) continue;
              // edge vectors X→Y, X→Z in pixels; a channel's steps g solve M·g = 128·(Δ_Y, Δ_Z)
              const double ax = xY16 / 16.0, ay = -yX16 / 16.0, bx = xZ16 / 16.0, by = (yZ16 - yX16) / 16.0, det = ax * by - bx * ay;
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
                    const double gx = sg[c3] * 128 * (e1 * by - e2 * ay) / det, gy = sg[c3] * 128 * (e2 * ax - e1 * bx) / det;
                    if (!(gx < -0.99 && gx > -1.0 && gy > 0.5 && gy - std::trunc(gy) < 0.006)) continue;
                    for (int i = -a.box; i <= a.box; ++i)
                      for (int j = -a.box; j <= a.box; ++j)
                        for (int k = -a.box; k <= a.box; ++k) {
                          p::ivec3 lx{a.lx[0] + i, a.lx[1] + j, a.lx[2] + k};
                          p::ivec3 ly = lx, lz = lx;
                          ly[ca] -= sg[ca] * d1, ly[cb] -= sg[cb] * d1, ly[c3] += e1;
                          lz[ca] -= sg[ca] * d2, lz[cb] -= sg[cb] * d2, lz[c3] += e2;
                          if (!p::is_packed_light(s, lx) || !p::is_packed_light(s, ly) || !p::is_packed_light(s, lz)) continue;
                          const tt::triangle_case c{s, a.iX, a.iY, {lx, ly, lz}, {0, yX16, xY16, 0, xZ16, yZ16}, 0, 0};
                          bench::found f{c, bench::score_near_vertices(c, args.o, t, a.side, 2, 4), a.side};
                          ++evaluated;
                          if (f.sc.value < 128 && f.sc.smooth >= a.min_smooth && (a.nr > 0 || a.signs)) {
                            f = bench::explore(c, a.side, a.nr, a.signs != 0, args.o, t, normals);
                            ++explored;
                          }
                          if (bench::better(f.sc, best.sc)) best = f;
                          if (f.sc.value >= 128) {
                            bench::print_certificate_row(f.c, f.sc, args.option_name());
                            std::printf("(side %+d; %lld cases evaluated, %lld explored)\n", f.side, evaluated, explored);
                            return 0;
                          }
                        }
                  }
              }
            }
  std::printf("s = %d (%s): no wrap, best wrap-side value %d (smooth %.3f) at (%d, %d), side %+d, %lld cases evaluated, %lld explored; its case:\n",
              s, args.option_name(), best.sc.value, best.sc.smooth, best.sc.px, best.sc.py, best.side, evaluated, explored);
  bench::print_certificate_row(best.c, best.sc, args.option_name(), "best");
  return 1;
}
