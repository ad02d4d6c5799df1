// proofs_triangle relaxation — how far the bound of two-pass.max-s.interpolated can go for one
// normal: the exact value of its continuous relaxation at one geometry, and a search over geometries
// that prints the best point it attains (the keep_fraction row of relaxation_witnesses). Not a test
// and not a proof (the search gives lower bounds of the relaxation's supremum; proofs_triangle certify
// gives the certified upper bounds); reproducible (fixed seed).
//
//   proofs_triangle relaxation S [--truncate-to-8] IX IY [STARTS EVALS]
// The relaxation is what the bound's statements allow (two_pass_triangle.hpp (i)–(iii)): vertex
// lights anywhere in the real ball |l| <= S (levels), real vertices X = (0, yX), Y = (xY, 0),
// Z = (xZ, yZ) in [0, 2047]² (r = (0, 0) the reference pixel) and the pixel p = Z, and per channel
// σ_c·L_c(p) = σ_c·P_c(p) + 1 unit + a·clamp(t_x, 0, 1) + b·clamp(t_y, 0, 1) units, t = −σ_c·(the exact
// step in units per pixel), a = xZ, b = yZ: the lag of truncated steps approaches a·min(1, |g|)
// where an axis is aligned, and nothing where it is not. Σ_c |n_c|·σ_c·(L_c − 16384) above the
// wrap side's threshold (128·(128 − #neg − e) levels·|n| at the top, 128·(129 − #pos + e) at the
// bottom; truncate_to_8 adds two_pass_triangle's truncation_units) means no argument built from those statements can
// prove the normal safe at S.
// At one geometry the maximum over the lights is exact through its dual: for each alignment
// pattern π (which axes of which channel are charged) the objective is concave in the lights, and
// min(1, t) = min over θ in [0, 1] of θ + (1 − θ)·t turns it into a linear function whose maximum
// over the three balls is S·Σ_k ‖Γ_k(θ)‖ + K(θ), with Γ_k,c = |n_c|·β_k(z_c), z_c = p moved
// (1 − θ)·a (resp. b) towards r on each charged axis, β_k the barycentric coordinates, and
// K = Σ_c |n_c|·(θ_x·a + θ_y·b) (levels). Every θ gives an upper bound (`upper`: the least found,
// maximised over the 64 patterns); the lights that maximise it at the best θ, put through the
// objective itself, give a lower bound (`lower`, an attained value). The search maximises `lower`
// over the geometry (hill climbing with shrinking Gaussian steps from fixed and random starts).
//
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>

#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"
#include "triangle_args.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
using lights = std::array<std::array<double, 3>, 3>;  // X, Y, Z; levels
// Three vertices (pixels, r = (0, 0)) and which of them is the pixel p.
struct geometry {
  double v[3][2];
  int p = 2;
  double a() const { return v[p][0]; }
  double b() const { return v[p][1]; }
};
geometry corner_case(double yX, double xY, double xZ, double yZ) { return {{{0, yX}, {xY, 0}, {xZ, yZ}}, 2}; }
// β_k(z) = A_k + Bx_k·z_x + By_k·z_y.
struct barycentric {
  double A[3], Bx[3], By[3];
  double at(int k, double x, double y) const { return A[k] + Bx[k] * x + By[k] * y; }
};

bool barycentric_of(const geometry& g, barycentric& b, double side) {
  for (const auto& q : g.v)
    if (q[0] < 0 || q[0] > side || q[1] < 0 || q[1] > side) return false;
  const auto& P = g.v;
  const double det = (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[2][0] - P[0][0]) * (P[1][1] - P[0][1]);
  if (std::fabs(det) < 1) return false;
  for (int k = 0; k < 3; ++k) {  // β_k(z) = ((P_i − z) × (P_j − z)) / det
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    b.A[k] = (P[i][0] * P[j][1] - P[j][0] * P[i][1]) / det;
    b.Bx[k] = (P[i][1] - P[j][1]) / det;
    b.By[k] = (P[j][0] - P[i][0]) / det;
  }
  return true;
}

struct relaxation {
  std::array<double, 3> w;  // |n_c|
  double s;

  // The pattern's Γ_k for θ (2 per channel: x, y), and K.
  double gammas(const geometry& g, const barycentric& b, unsigned pattern, const double* th, double G[3][3]) const {
    double K = 0;
    for (int c = 0; c < 3; ++c) {
      const unsigned m = pattern >> (2 * c) & 3;
      double zx = g.a(), zy = g.b();
      if (m & 1) zx -= (1 - th[2 * c]) * g.a(), K += w[c] * th[2 * c] * g.a() / 128;
      if (m & 2) zy -= (1 - th[2 * c + 1]) * g.b(), K += w[c] * th[2 * c + 1] * g.b() / 128;
      for (int k = 0; k < 3; ++k) G[k][c] = w[c] * b.at(k, zx, zy);
    }
    return K;
  }
  double dual(const geometry& g, const barycentric& b, unsigned pattern, const double* th) const {
    double G[3][3];
    const double K = gammas(g, b, pattern, th, G);
    double sum = 0;
    for (auto& row : G) sum += std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]);
    return s * sum + K;
  }
  // The objective itself (levels·|n|, σ folded in, without the start error): the ledger's.
  double primal(const geometry& g, const lights& l) const {
    tt::relaxation_point x{};
    for (std::size_t k = 0; k < 3; ++k) x.vertex[k] = {g.v[k][0], g.v[k][1]};
    x.pixel = {g.a(), g.b()};
    x.light = l;
    return tt::relaxation_value(x, w, s);
  }
};

struct evaluation {
  double upper = -1e18, lower = -1e18;
  lights l{};
};

// Coordinate descent on the convex dual of each pattern (ternary search per coordinate).
evaluation evaluate(const relaxation& r, const geometry& g, double side = 2047, int sweeps = 25, int iterations = 40) {
  evaluation out;
  barycentric b;
  if (!barycentric_of(g, b, side)) return out;
  for (unsigned pattern = 0; pattern < 64; ++pattern) {
    double th[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    int free[6], d = 0;
    for (int c = 0; c < 3; ++c) {
      if (pattern >> (2 * c) & 1) free[d++] = 2 * c;
      if (pattern >> (2 * c) & 2) free[d++] = 2 * c + 1;
    }
    for (int sweep = 0; sweep < (d > 1 ? sweeps : 1); ++sweep)
      for (int q = 0; q < d; ++q) {
        double lo = 0, hi = 1;
        for (int it = 0; it < iterations; ++it) {
          const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
          th[free[q]] = m1;
          const double f1 = r.dual(g, b, pattern, th);
          th[free[q]] = m2;
          if (f1 < r.dual(g, b, pattern, th))
            hi = m2;
          else
            lo = m1;
        }
        th[free[q]] = (lo + hi) / 2;
      }
    out.upper = std::max(out.upper, r.dual(g, b, pattern, th));
    double G[3][3];
    (void)r.gammas(g, b, pattern, th, G);
    lights l{};
    for (int k = 0; k < 3; ++k) {
      const double n = std::sqrt(G[k][0] * G[k][0] + G[k][1] * G[k][1] + G[k][2] * G[k][2]);
      for (int c = 0; c < 3; ++c) l[k][c] = n > 0 ? r.s * G[k][c] / n : 0;
    }
    const double v = r.primal(g, l);
    if (v > out.lower) out.lower = v, out.l = l;
  }
  return out;
}

struct found {
  geometry g{};
  evaluation e;
};

found search(const relaxation& r, int starts, int evals, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> any(0, 2047);
  std::normal_distribution<double> gauss(0, 1);
  const geometry fixed[] = {corner_case(2047, 845, 2047, 2047), corner_case(845, 2047, 2047, 2047),
                            corner_case(880, 1520, 2033, 2047)};
  found best;
  for (int k = 0; k < starts; ++k) {
    geometry g = k < 3 ? fixed[k] : corner_case(any(rng), any(rng), any(rng), any(rng));
    evaluation cur = evaluate(r, g);
    double step = 300;
    for (int i = 0; i < evals; ++i) {
      geometry n = g;
      for (double* v : {&n.v[0][1], &n.v[1][0], &n.v[2][0], &n.v[2][1]})
        *v = std::clamp(*v + step * gauss(rng), 0.0, 2047.0);
      const evaluation e = evaluate(r, n);
      if (e.lower > cur.lower)
        g = n, cur = e;
      else
        step = std::max(0.25, step * 0.985);
    }
    if (cur.lower > best.e.lower) best = {g, cur};
  }
  return best;
}

// The wrap-side thresholds of one normal in levels·|n| (start error and truncate_to_8 moved to the
// left: the objective plus them must exceed it).
struct side_threshold {
  double top, bottom;
};
side_threshold thresholds(const p::paper::packed_normal& nm, const p::two_pass::table& t, const gs::model_options& o) {
  const int e = t.alpha_error(nm);
  return {tt::relaxation_threshold(nm, e, 1, o), tt::relaxation_threshold(nm, e, -1, o)};
}

void print_found(const found& f, double threshold) {
  std::printf(
      "  lower %.3f upper %.3f threshold %.3f margin %+.3f at (%.2f, %.2f), (%.2f, %.2f), (%.2f, %.2f), p = vertex "
      "%d\n",
      f.e.lower, f.e.upper, threshold, f.e.lower - threshold, f.g.v[0][0], f.g.v[0][1], f.g.v[1][0], f.g.v[1][1],
      f.g.v[2][0], f.g.v[2][1], f.g.p);
  for (int k = 0; k < 3; ++k)
    std::printf("    light %d = (%.3f, %.3f, %.3f)\n", k, f.e.l[k][0], f.e.l[k][1], f.e.l[k][2]);
}

struct relaxation_args {
  gsdot3::tools::search_args search;
  int iX = 0, iY = 0, starts = 8, evals = 400;
};

int run(const relaxation_args& a) {
  const auto& args = a.search;
  const int s = args.s;
  const gs::model_options o = args.options();
  const p::two_pass::table t(o);
  const auto nm = p::paper::pack_normal_from(a.iX, a.iY);
  const relaxation r{{double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))}, double(s)};
  const auto th = thresholds(nm, t, o);
  const found f = search(r, a.starts, a.evals, 1);
  std::printf("s = %d (%s), n = (%d, %d, %d): top side\n", s, args.option_name(), nm.iX, nm.iY, nm.iZ);
  print_found(f, th.top);
  std::printf("bottom side: threshold %.3f margin %+.3f\n", th.bottom, f.e.lower - th.bottom);
  return 0;
}
}  // namespace

void gsdot3::tools::add_relaxation_command(CLI::App& app, int& rc) {
  auto a = std::make_shared<relaxation_args>();
  CLI::App* cmd = app.add_subcommand(
      "relaxation",
      "The continuous relaxation of the error bound for one normal: the keep_fraction relaxation witness");
  cmd->footer(
      "Prints the best point found (vertices, lights to three decimals) and its margin over each side's threshold; "
      "a positive margin: the bound's statements admit a wrap. `84 -89 -65 4 150`: ~6 s.");
  add_search_args(*cmd, a->search);
  cmd->add_option("IX", a->iX, "The normal pack(IX, IY)")->required()->check(CLI::Range(-127, 127));
  cmd->add_option("IY", a->iY, "")->required()->check(CLI::Range(-127, 127));
  cmd->add_option("STARTS", a->starts, "Search starts: three fixed geometries, then random ones (default 8)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("EVALS", a->evals, "Steps per start (default 400)")->check(CLI::NonNegativeNumber);
  cmd->callback([a, &rc] { rc = run(*a); });
}
