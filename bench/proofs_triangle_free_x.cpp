// proofs_triangle_free_x — proofs_triangle_steep's construction with the x steps left free and the
// pixel on a row the fill rule covers: a screen of its integer data, then an exact search of the
// 12.4 geometry for the best of it. Not a benchmark, not a test and not a proof; deterministic.
//
//   proofs_triangle_free_x S [truncate_to_8] IX IY SIDE THIRD [F_MIN] [TOP] [NR SIGNS] [XZK_TOP] [ZFINE]
// Folded as in proofs_triangle_lattice (σ_c = sign n_c · SIDE; A, B the lag channels, 3 = THIRD),
// r = (0, 0), X = (0, yX), Y = (xY, 0), Z = (xZ, yZ) with yZ in (2046, 2047]. The pixel is on row
// 2046: all vertex y are <= 2047, and a pixel centre on row 2047 lies on the triangle's boundary,
// on a bottom edge or at the lowest vertex, which also lies on a right edge, and the fill rule
// (gs::covers) leaves out both, so no triangle of the window covers row 2047
// (proofs_triangle_lattice counts row floor(yZ) = 2047: K·|n_3|/128 levels·|n| more than any
// covered pixel gets). If every x step g_x,c is in (−1, 1) it truncates to 0 and the pixel's x does
// not matter: with the lag channels' y steps −(1 − δ) (truncated to 0) and the third's K + ε
// (truncated to K), in levels
//   L_c(p) = P_c(r) + m_c·2046/128 = X_c − g_y,c·yX/128 + m_c·2046/128,
//   F = Σ_c |n_c|·L_c(p) = |n_A|·(X_A + yX/128) + |n_B|·(X_B + yX/128) + |n_3|·(X_3 + K·(2046 − yX)/128) at δ = ε = 0,
// which only Z's and Y's lights tie to the geometry (proofs_triangle_steep and _lattice also fix
// g_x = −1 + 0 on every channel and equal lag planes; here each channel's x step is free in (−1, 1)).
// F falls with yX (K·|n_3| > |n_A| + |n_B| in every case of interest), and β = g_x,3 =
// (128·(Z_3 − X_3) − K·(yZ − yX))/xZ > −1 bounds yX below by yZ − (128·(Z_3 − X_3) + xZ)/K.
// Stage 1: every packed X, every packed Z with Z_A, Z_B within −32..16 of X's and the largest packed
// Z_3 for them, K = 1..15, Z at (2047, 2047) or at (2046 + 1/16, 2046 + 1/16) (the triangle's sliver
// below row 2046 still covers (2046, 2046)): F_β, F at that least yX, with the lag channels' |g_x| <
// 1 there, Y_3 >= −(S + 1) possible (K·yX <= 128·(X_3 + S + 1) + 2047) and the ray of Y's lights,
// P(r) + (xY/128)·g_x for xY in (0, 2047], passing within S + 1/2 of the centre. F_β is a screen,
// not a bound (Y is checked at the least yX only); the (X, Z, K) with F_β >= F_MIN (default 0) are
// ranked and the five best printed.
// Stage 2, for the XZK_TOP best (default 2000): yX from its least up 32/16 pixel in steps of 2/16
// and every xY in 1/16 from 1 to 2047 pixels; each channel's Y_c is the integer that puts its exact
// y step just inside its window (the largest with g_y > −1 on A, B, with g_y >= K on the third),
// Y must be packed, every |g_x| < 1 and g_y,3 < K + 1, and F is taken with those exact steps (the
// start value's truncation is left to the scorer). ZFINE = 1 puts Z at each of the 256 positions
// in (2046, 2047]² instead of stage 1's (once per X, Z, K). The TOP (default 10) cases by F, the
// five best printed, go through bench::score_near_vertices around Z (the floors, the pixel's
// coverage) with each vertex as vertex 0 (the start value is truncated toward vertex 0's value),
// and with NR and SIGNS as in proofs_triangle_steep (default 0 0) where the smooth part reaches
// 125.5. Prints the first wrapping case as a certificate row, or the best case reached. At s = 84
// under truncate_to_8 (`84 truncate_to_8 60 67 -1 2 15990 40 1 1 2000`) it finds a wrap at its
// first case.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

#include "proofs_search_args.hpp"
#include "proofs_triangle_thirds.hpp"
#include "proofs_triangle_score.hpp"
#include "proofs/domains.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;
namespace bench = gsdot3::bench;

namespace {
constexpr int max124 = (tt::window_pixels - 1) * 16, pixel_row = tt::window_pixels - 2;

// Every vertex as vertex 0 (the order X, Y, Z rotated), Z's new index in `z`.
tt::triangle_case rotated(const tt::triangle_case& c, int k, unsigned& z_bit) {
  tt::triangle_case q = c;
  for (int v = 0; v < 3; ++v) {
    const int from = (v + k) % 3;
    q.light[static_cast<std::size_t>(v)] = c.light[static_cast<std::size_t>(from)];
    q.xy16[static_cast<std::size_t>(2 * v)] = c.xy16[static_cast<std::size_t>(2 * from)];
    q.xy16[static_cast<std::size_t>(2 * v + 1)] = c.xy16[static_cast<std::size_t>(2 * from + 1)];
    if (from == 2) z_bit = 1u << v;
  }
  return q;
}
}  // namespace

int main(int argc, char** argv) {
  const auto args = bench::parse_search_args(argc, argv, "proofs_triangle_free_x", " IX IY SIDE THIRD [F_MIN] [TOP] [NR SIGNS] [XZK_TOP] [ZFINE]");
  const auto st = gsdot3::bench::parse_steep_args(argc, argv, args, "proofs_triangle_free_x",
                                                  "IX IY SIDE THIRD [F_MIN] [TOP] [NR SIGNS] [XZK_TOP] [ZFINE]", 10);
  const int at = args.next;
  const int s = args.s, iX = st.iX, iY = st.iY, side = st.side, c3 = st.third, top = st.top;
  const double f_min = st.f_min;
  const int nr = argc > at + 6 ? std::atoi(argv[at + 6]) : 0, signs = argc > at + 7 ? std::atoi(argv[at + 7]) : 0;
  const std::size_t xzk_top = argc > at + 8 ? static_cast<std::size_t>(std::atoi(argv[at + 8])) : 2000;
  const bool zfine = argc > at + 9 && std::atoi(argv[at + 9]) != 0;
  const bool truncate = args.o.gouraud == gs::gouraud_fraction::truncate_to_8;
  if (nr < 0 || (signs != 0 && signs != 1)) {
    std::fprintf(stderr, "proofs_triangle_free_x: NR >= 0, SIGNS 0 or 1\n");
    return 2;
  }
  std::set<std::pair<int, int>> normals;
  for (const auto& m : p::appendix2_normals()) normals.insert({m.iX, m.iY});
  if (!normals.count({iX, iY})) {
    std::fprintf(stderr, "proofs_triangle_free_x: (%d, %d) is not an Appendix 2 normal\n", iX, iY);
    return 2;
  }
  const auto nm = p::paper::pack_normal_from(iX, iY);
  const int n[3] = {nm.iX, nm.iY, nm.iZ};
  const std::size_t c = static_cast<std::size_t>(c3), ca = (c + 1) % 3, cb = (c + 2) % 3;
  const double wa = std::abs(n[ca]), wb = std::abs(n[cb]), w3 = std::abs(n[c]);
  int sg[3];
  for (int ch = 0; ch < 3; ++ch) sg[ch] = (n[ch] >= 0 ? 1 : -1) * side;
  auto seen = [&](std::size_t ch, double level) { return gsdot3::bench::seen_level(level, truncate, sg[ch]); };

  const p::two_pass::table t(args.o);
  const double threshold = static_cast<double>(tt::wrap_threshold_units(nm, t.alpha_error(nm), side, args.o)) / 128;  // F must pass it

  const gsdot3::bench::packed_thirds third_values(s, c);  // the third channel's packed values for A, B

  constexpr double W = 2047, row = pixel_row;
  // Stage 1: (X, Z, K) by F_β (see the header).
  struct xzk {
    double f;
    p::ivec3 x, z;
    int K, zpos;
  };
  // Z at the corner, or just below row 2046 (a sliver of the triangle still covers (2046, 2046)):
  // β = −1 puts yX at yZ − (128·e2 + xZ)/K, 1 − 1/K pixels less.
  constexpr int zpos16[2][2] = {{max124, max124}, {16 * pixel_row + 1, 16 * pixel_row + 1}};
  std::vector<xzk> bounds;
  for (int zp = 0; zp < 2; ++zp)
  for (const auto& x : p::packed_lights(s)) {
    if (wa * (x[ca] + W / 128 + 1) + wb * (x[cb] + W / 128 + 1) + w3 * (s + W / 128 + 1) < f_min) continue;
    const double xZ = zpos16[zp][0] / 16.0, yZ = zpos16[zp][1] / 16.0;
    for (int za = x[ca] - 32; za <= x[ca] + 16; ++za)
      for (int zb = x[cb] - 32; zb <= x[cb] + 16; ++zb) {
        const auto& v = third_values(za, zb);
        if (v.empty()) continue;
        const int z3 = v.back();  // the largest: yX at its least
        for (int K = 1; K <= 15; ++K) {
          const double yX = std::max(0.0, yZ - (128.0 * (z3 - x[c]) + xZ) / K);
          // the lag channels' |g_x| < 1; and Y_3 = X_3 + (β·xY − K·yX)/128 >= −(s + 1) with β < 1, xY <= 2047
          if (yX >= yZ || std::fabs(128.0 * (za - x[ca]) + (yZ - yX)) >= xZ || std::fabs(128.0 * (zb - x[cb]) + (yZ - yX)) >= xZ ||
              K * yX > 128.0 * (x[c] + s + 1) + W)
            continue;
          const double f = wa * seen(ca, x[ca] + yX / 128) + wb * seen(cb, x[cb] + yX / 128) + w3 * seen(c, x[c] + K * (row - yX) / 128);
          if (f < f_min) continue;
          p::ivec3 z{};
          z[ca] = za, z[cb] = zb, z[c] = z3;
          // Y(t) = P(r) + t·g_x (t = xY/128 in (0, 16], xZ = yZ = 2047) must come within s + 1/2 of the centre
          double P[3], g[3], pg = 0, gg = 0, pp = 0;
          for (std::size_t ch = 0; ch < 3; ++ch) {
            const double G = ch == c ? K : -1.0;
            P[ch] = x[ch] - G * yX / 128, g[ch] = (128.0 * (z[ch] - x[ch]) - G * (yZ - yX)) / xZ;
            pg += P[ch] * g[ch], gg += g[ch] * g[ch], pp += P[ch] * P[ch];
          }
          const double tm = std::clamp(-pg / gg, 1.0 / 128, W / 128);
          if (pp + 2 * tm * pg + tm * tm * gg > (s + 0.5) * (s + 0.5)) continue;
          bounds.push_back({f, x, z, K, zp});
        }
      }
  }
  std::sort(bounds.begin(), bounds.end(), [](const xzk& a, const xzk& b) { return a.f > b.f; });
  std::printf("s = %d (%s), n = (%d, %d, %d), side %+d, third channel %d, threshold %.2f: %zu (X, Z, K) with F_beta >= %g%s\n", s,
              args.option_name(), n[0], n[1], n[2], side, c3, threshold, bounds.size(), f_min, bounds.empty() ? "" : ", best:");
  for (std::size_t i = 0; i < std::min<std::size_t>(5, bounds.size()); ++i)
    std::printf("  F_beta %.2f  K %d  folded X (%d, %d, %d) Z (%d, %d, %d) at (%g, %g)\n", bounds[i].f, bounds[i].K, bounds[i].x[0],
                bounds[i].x[1], bounds[i].x[2], bounds[i].z[0], bounds[i].z[1], bounds[i].z[2], zpos16[bounds[i].zpos][0] / 16.0,
                zpos16[bounds[i].zpos][1] / 16.0);
  // Stage 2: the best XZK_TOP of them on the 12.4 grid (see the header).
  struct candidate {
    double f;
    std::array<p::ivec3, 3> l;  // folded X, Y, Z
    std::array<int, 6> xy16;
    int K;
  };
  std::vector<candidate> found;
  std::set<std::array<int, 7>> seen_xzk;
  for (std::size_t i = 0; i < std::min<std::size_t>(xzk_top, bounds.size()); ++i) {
    const auto& [fb, x, z, K, zp] = bounds[i];
    if (!seen_xzk.insert({x[0], x[1], x[2], z[0], z[1], z[2], K}).second && zfine) continue;
    for (int zq = 0; zq < (zfine ? 256 : 1); ++zq) {
    const int z3 = z[c], xZ16 = zfine ? max124 - zq % 16 : zpos16[zp][0], yZ16 = zfine ? max124 - zq / 16 : zpos16[zp][1];
    const double xZ = xZ16 / 16.0, yZ = yZ16 / 16.0;
    const double yXb = std::max(0.0, yZ - (128.0 * (z3 - x[c]) + xZ) / K);
    for (int yX16 = static_cast<int>(std::ceil(16 * yXb)); yX16 <= static_cast<int>(std::ceil(16 * yXb)) + 32; yX16 += 2) {
      const double yX = yX16 / 16.0;
      for (int xY16 = 16; xY16 <= max124; ++xY16) {
        const double xY = xY16 / 16.0, det = yX * xZ + (yZ - yX) * xY;
        double f = 0;
        p::ivec3 y{};
        bool ok = true;
        for (std::size_t ch = 0; ch < 3 && ok; ++ch) {
          const int dz = z[ch] - x[ch];
          const double G = ch == c ? K : -1.0, target = (dz * xY - G * det / 128) / xZ;  // ΔY_c with g_y = G
          const double dy = ch == c ? std::floor(target) : std::ceil(target) - 1;
          const double gy = -128 * (dy * xZ - dz * xY) / det, gx = (128.0 * dz - gy * (yZ - yX)) / xZ;
          if (std::fabs(gx) >= 1 || (ch == c ? gy >= K + 1 : gy <= -1)) ok = false;
          y[ch] = x[ch] + static_cast<int>(dy);
          f += std::abs(n[ch]) * seen(ch, x[ch] + (-gy * yX + (ch == c ? K * row : 0)) / 128);
        }
        if (!ok || f < f_min || !p::is_packed_light(s, y)) continue;
        found.push_back({f, {x, y, z}, {0, yX16, xY16, 0, xZ16, yZ16}, K});
      }
    }
    }
  }
  std::sort(found.begin(), found.end(), [](const candidate& a, const candidate& b) { return a.f > b.f; });
  std::printf("%zu cases with F >= %g\n", found.size(), f_min);
  bench::found overall;
  for (int i = 0; i < top && i < static_cast<int>(found.size()); ++i) {
    const candidate& k = found[static_cast<std::size_t>(i)];
    tt::triangle_case cs{s, iX, iY, {}, k.xy16, 0, 0};
    for (std::size_t v = 0; v < 3; ++v)
      for (std::size_t ch = 0; ch < 3; ++ch) cs.light[v][ch] = sg[ch] * k.l[v][ch];
    if (i < 5)
      std::printf("F %.2f  K %d  X = (0, %.4f) Y = (%.4f, 0) Z = (%.4f, %.4f)  folded X (%d, %d, %d) Y (%d, %d, %d) Z (%d, %d, %d)\n", k.f, k.K,
                  k.xy16[1] / 16.0, k.xy16[2] / 16.0, k.xy16[4] / 16.0, k.xy16[5] / 16.0, k.l[0][0], k.l[0][1], k.l[0][2], k.l[1][0],
                  k.l[1][1], k.l[1][2], k.l[2][0], k.l[2][1], k.l[2][2]);
    for (int r = 0; r < 3; ++r) {
      unsigned z_bit = 4;
      const tt::triangle_case q = rotated(cs, r, z_bit);
      bench::found f{q, bench::score_near_vertices(q, args.o, t, side, 2, z_bit), side};
      if (f.sc.value < 128 && f.sc.smooth >= 125.5 && (nr > 0 || signs)) f = bench::explore(q, side, nr, signs != 0, args.o, t, normals, z_bit);
      if (bench::better(f.sc, overall.sc)) overall = f;
      if (f.sc.value >= 128) {
        bench::print_certificate_row(f.c, f.sc, args.option_name());
        std::printf("(side %+d; case %d, vertex 0 = %c)\n", f.side, i + 1, "XYZ"[r]);
        return 0;
      }
    }
  }
  if (overall.sc.px < 0) {
    std::printf("s = %d (%s): no wrap, no case scored\n", s, args.option_name());
    return 1;
  }
  std::printf("s = %d (%s): no wrap, best wrap-side value %d (smooth %.3f) at (%d, %d), side %+d; its case:\n", s, args.option_name(),
              overall.sc.value, overall.sc.smooth, overall.sc.px, overall.sc.py, overall.side);
  bench::print_certificate_row(overall.c, overall.sc, args.option_name(), "best");
  return 1;
}
