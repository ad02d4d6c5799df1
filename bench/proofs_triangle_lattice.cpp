// proofs_triangle_lattice — where the lattice lets proofs_triangle_steep's construction sit: its
// integer data enumerated exactly, in the limit of its step windows. Not a benchmark, not a test and
// not a proof (the windows' slack, the 12.4 vertices, the start value's truncation and the floors are
// left to proofs_triangle_steep, which scores each case exactly); deterministic.
//
//   proofs_triangle_lattice S [truncate_to_8] IX IY SIDE THIRD [F_MIN] [TOP]
// Folded (σ_c = sign n_c · SIDE, larger is closer to the wrap; packed lights are symmetric in each
// channel's sign), with A, B the lag channels and 3 = THIRD, the steep construction in the limit of
// its windows (lag steps −1 on both axes, the third channel's x step −1 and y step K, r = (0, 0),
// X = (0, yX), Y = (xY, 0), Z = (xZ, yZ)) is fixed by integers: Y = X − (D1, D1, −e1) and
// Z = X − (D2, D2, −e2) on A, B, 3, and the four coordinates solve
//   xY − yX = 128·D1,  xZ + yZ − yX = 128·D2,  xY + K·yX = −128·e1,  K·(yZ − yX) − xZ = 128·e2,
// so yX = −128·(e1 + D1)/(K + 1), yZ − yX = 128·(e2 + D2)/(K + 1), xZ = 128·D2 − (yZ − yX),
// xY = yX + 128·D1: yX and yZ − yX are multiples of 128/(K + 1) pixels, which is where a plan's real
// optimum (proofs_triangle_plan) can miss the lattice by most of a level. The pixel is the bottom row
// y_p = floor(yZ) (no triangle of the window covers row 2047, tests/proofs/triangle_test.cpp, so
// where yZ = 2047 a covered pixel gets K·|n_3|/128 less; proofs_triangle_free_x counts row 2046),
// where the lag channels keep X_c + yX/128 and the third X_3 + K·(y_p − yX)/128, so
//   F = |n_A|·(X_A + yX/128) + |n_B|·(X_B + yX/128) + |n_3|·(X_3 + K·(y_p − yX)/128).
// Under truncate_to_8 the multiply sees the light's integer level, floor(L_c/128): folded, that is
// ceil of the folded level where σ_c = −1 (a gain of up to one level) and floor where σ_c = +1, so
// F takes each channel's term that way (a folded level within 1e-6 of an integer is taken at the
// integer: the exact case, a hair off the limit, decides).
// Every packed X, D2 = 1..40, packed Z, K = 1..15, D1 = 1..20 and packed Y with all four
// coordinates in [0, 2047] is tried (a limit yZ up to 2 pixels past 2047 is moved in with yX: the
// windows' slack; the s = 85 certificates have yX = 751 for a limit of 752); the TOP (default 20) cases with F >= F_MIN (default 0) are
// printed, best first, each with the proofs_triangle_steep command that searches its window (box 1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "proofs_search_args.hpp"
#include "proofs_triangle_thirds.hpp"
#include "proofs/domains.hpp"
#include "proofs/paper_code.hpp"

namespace p = gsdot3::proofs;

namespace {
struct lattice_case {
  double f;
  p::ivec3 x, y, z;  // folded
  int K, d1, d2;
  double yX, xY, xZ, yZ;
};
}  // namespace

int main(int argc, char** argv) {
  const auto args = gsdot3::bench::parse_search_args(argc, argv, "proofs_triangle_lattice", " IX IY SIDE THIRD [F_MIN] [TOP]");
  const auto st = gsdot3::bench::parse_steep_args(argc, argv, args, "proofs_triangle_lattice", "IX IY SIDE THIRD [F_MIN] [TOP]", 20);
  const int s = args.s, iX = st.iX, iY = st.iY, side = st.side, c3 = st.third, top = st.top;
  const double f_min = st.f_min;
  const bool truncate = args.o.gouraud == gs::gouraud_fraction::truncate_to_8;
  const auto nm = p::paper::pack_normal_from(iX, iY);
  const int n[3] = {nm.iX, nm.iY, nm.iZ};
  const std::size_t c = static_cast<std::size_t>(c3), ca = (c + 1) % 3, cb = (c + 2) % 3;
  const double wa = std::abs(n[ca]), wb = std::abs(n[cb]), w3 = std::abs(n[c]);
  // a channel's folded level at the pixel as the multiply sees it
  auto seen = [&](std::size_t ch, double level) { return gsdot3::bench::seen_level(level, truncate, (n[ch] >= 0 ? side : -side)); };

  constexpr double W = 2047;
  const gsdot3::bench::packed_thirds third_values(s, c);  // the third channel's packed values for A, B

  std::vector<lattice_case> found;
  for (const auto& x : p::packed_lights(s)) {
    // an upper bound on F for this X: yX <= W, and the third channel at most s + W/128 (one axis's lag),
    // each up to a level more under truncate_to_8
    if (wa * (x[ca] + W / 128 + 1) + wb * (x[cb] + W / 128 + 1) + w3 * (s + W / 128 + 1) < f_min) continue;
    for (int d2 = 1; d2 <= 40; ++d2)
      for (int z3 : third_values(x[ca] - d2, x[cb] - d2)) {
        const int e2 = z3 - x[c];
        for (int K = 1; K <= 15; ++K) {
          const double unit = 128.0 / (K + 1), rise = unit * (e2 + d2), xZ = 128.0 * d2 - rise;
          if (rise <= 0 || xZ < 0 || xZ > W) continue;
          for (int d1 = 1; d1 <= 20; ++d1)
            for (int y3 : third_values(x[ca] - d1, x[cb] - d1)) {
              // the windows' slack (the steps a hundredth of a unit and 0.006 off their limits) lets the
              // geometry move a pixel or two: a limit yZ up to 2 pixels past the window is moved in
              const double over = std::max(0.0, -unit * (y3 - x[c] + d1) + rise - W);
              const double yX = -unit * (y3 - x[c] + d1) - over, xY = yX + 128.0 * d1, yZ = yX + rise;
              if (over > 2 || yX < 0 || xY > W) continue;
              const double f = wa * seen(ca, x[ca] + yX / 128) + wb * seen(cb, x[cb] + yX / 128) +
                               w3 * seen(c, x[c] + K * (std::floor(yZ) - yX) / 128);
              if (f < f_min) continue;
              p::ivec3 y = x, z = x;
              y[ca] -= d1, y[cb] -= d1, y[c] = y3;
              z[ca] -= d2, z[cb] -= d2, z[c] = z3;
              found.push_back({f, x, y, z, K, d1, d2, yX, xY, xZ, yZ});
            }
        }
      }
  }
  std::sort(found.begin(), found.end(), [](const lattice_case& a, const lattice_case& b) { return a.f > b.f; });
  std::printf("s = %d (%s), n = (%d, %d, %d), side %+d, third channel %d: %zu lattice cases with F >= %g\n", s, args.option_name(), n[0], n[1],
              n[2], side, c3, found.size(), f_min);
  for (int i = 0; i < top && i < static_cast<int>(found.size()); ++i) {
    const lattice_case& k = found[static_cast<std::size_t>(i)];
    int lx[3];
    for (std::size_t ch = 0; ch < 3; ++ch) lx[ch] = (n[ch] >= 0 ? 1 : -1) * side * k.x[ch];
    std::printf("F %.2f  K %d  X = (0, %.2f) Y = (%.2f, 0) Z = (%.2f, %.2f)  folded X (%d, %d, %d) Y (%d, %d, %d) Z (%d, %d, %d)\n", k.f, k.K,
                k.yX, k.xY, k.xZ, k.yZ, k.x[0], k.x[1], k.x[2], k.y[0], k.y[1], k.y[2], k.z[0], k.z[1], k.z[2]);
    std::printf("      steep: proofs_triangle_steep %d%s %d %d %d %d %d %d %d %d %d %d %d 1\n", s, truncate ? " truncate_to_8" : "", iX, iY, side, c3,
                lx[0], lx[1], lx[2], k.d1, k.d2,
                std::max(0, static_cast<int>(std::floor(k.yX)) - 3), std::min(2047, static_cast<int>(std::ceil(k.yX)) + 1));
  }
  return 0;
}
