// proofs_triangle_relaxation — where to look for triangle certificates of
// two-pass.max-s.interpolated: a local search over a continuous relaxation of the same arithmetic.
// Not a benchmark, not a test and not a proof (a search finds lower bounds of the relaxation's
// supremum only); reproducible (fixed seed).
//
//   proofs_triangle_relaxation W0 W1 W2 S [STEPS] [SEED]
// W = (|n_c|) a normal's weights, S the light scale. Wrap-side signs are folded in (σ_c = +1), so
// a channel is aligned on an axis where its plane falls along it. The relaxation: vertex lights
// anywhere in the real ball |l| <= S (levels), X = (0, yX), Y = (xY, 0), Z = (xZ, yZ) real in
// [0, 2047]² (r = (0, 0) is then the reference pixel), the pixel p = Z (the covered pixel farthest
// from r). Per channel the pixel's light is P_c(p) + a·t_x + b·t_y (levels, a = xZ, b = yZ), with
// t = clamp(−128·g, 0, 1)/128 for the exact step g (levels per pixel): the lag the truncated steps
// leave can approach a·min(1, |g|) units where |g| lies just below an integer; a non-aligned axis
// is charged nothing (its step an integer). Lattice lights, 12.4 vertices, the start value's
// truncation and the floors of the two passes are left out. Prints the best Σ W_c·L_c found (compare
// with 128·min(128 − #neg − e, 129 − #pos + e) from two_pass::table::alpha_error) and its case.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace {
struct relaxed_case {
  double yX, xY, xZ, yZ;
  std::array<std::array<double, 3>, 3> l;  // X, Y, Z
};

struct steps {
  double gx, gy;  // levels per pixel, along +x and +y
};

steps channel_steps(const relaxed_case& k, int c, double det) {
  const double ax = k.xY, ay = -k.yX, bx = k.xZ, by = k.yZ - k.yX;
  const double d1 = k.l[1][c] - k.l[0][c], d2 = k.l[2][c] - k.l[0][c];
  return {(d1 * by - d2 * ay) / det, (d2 * ax - d1 * bx) / det};
}

double determinant(const relaxed_case& k) { return k.xY * (k.yZ - k.yX) + k.xZ * k.yX; }

// Σ W_c·L_c(Z), or −1e9 outside the domain.
double objective(const relaxed_case& k, const double* w) {
  for (double v : {k.yX, k.xY, k.xZ, k.yZ})
    if (v < 0 || v > 2047) return -1e9;
  const double det = determinant(k);
  if (std::fabs(det) < 1) return -1e9;
  double total = 0;
  for (int c = 0; c < 3; ++c) {
    const steps g = channel_steps(k, c, det);
    const double lag = k.xZ * std::clamp(-128 * g.gx, 0.0, 1.0) / 128 + k.yZ * std::clamp(-128 * g.gy, 0.0, 1.0) / 128;
    total += w[c] * (k.l[2][static_cast<std::size_t>(c)] + lag);
  }
  return total;
}

void into_ball(std::array<double, 3>& l, double s) {
  const double n = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
  if (n > s)
    for (double& v : l) v *= s / n;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: proofs_triangle_relaxation W0 W1 W2 S [STEPS] [SEED]\n");
    return 2;
  }
  const double w[3] = {std::atof(argv[1]), std::atof(argv[2]), std::atof(argv[3])}, s = std::atof(argv[4]);
  const long n_steps = argc > 5 ? std::atol(argv[5]) : 300000;
  std::mt19937 rng(argc > 6 ? static_cast<unsigned>(std::atoi(argv[6])) : 1u);
  std::normal_distribution<double> gauss(0, 1);
  std::uniform_real_distribution<double> unit(0, 1);
  double best = -1e9;
  relaxed_case best_case{};
  for (int start = 0; start < 20; ++start) {  // simulated annealing from 20 starts
    relaxed_case k{2047, 2047, 2047, 2047, {}};
    if (start % 2) k = {2047 * unit(rng), 2047 * unit(rng), 2047 * unit(rng), 2047 * unit(rng), {}};
    for (auto& l : k.l) {
      for (double& v : l) v = s * gauss(rng);
      into_ball(l, s);
    }
    double cur = objective(k, w), temp = 1.0;
    for (long i = 0; i < n_steps; ++i, temp = std::max(1e-4, temp * 0.999995)) {
      relaxed_case next = k;
      const double scale = std::pow(10.0, -3 * unit(rng));
      if (rng() % 3 == 0) {
        double* g[4] = {&next.yX, &next.xY, &next.xZ, &next.yZ};
        *g[rng() % 4] += 300 * scale * gauss(rng);
      } else {
        auto& l = next.l[rng() % 3];
        for (double& v : l) v += 10 * scale * gauss(rng);
        into_ball(l, s);
      }
      const double v = objective(next, w);
      if (v > cur || unit(rng) < std::exp((v - cur) / temp)) k = next, cur = v;
      if (cur > best) best = cur, best_case = k;
    }
  }
  const relaxed_case& k = best_case;
  std::printf("best %.2f: X = (0, %.2f), Y = (%.2f, 0), Z = p = (%.2f, %.2f)\n", best, k.yX, k.xY, k.xZ, k.yZ);
  for (int c = 0; c < 3; ++c) {
    const steps g = channel_steps(k, c, determinant(k));
    std::printf("  channel %d: steps %.4f, %.4f units per pixel along x, y (negative: aligned)\n", c, 128 * g.gx, 128 * g.gy);
  }
  for (std::size_t v = 0; v < 3; ++v) std::printf("  light %c = (%.2f, %.2f, %.2f)\n", "XYZ"[v], k.l[v][0], k.l[v][1], k.l[v][2]);
  return 0;
}
