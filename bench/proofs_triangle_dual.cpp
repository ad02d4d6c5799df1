// proofs_triangle_dual — how far the bound of two-pass.max-s.interpolated can go: the exact value of
// its continuous relaxation at one geometry, and a search over geometries. Not a benchmark, not a
// test and not a proof (the search gives lower bounds of the relaxation's supremum); reproducible.
//
//   proofs_triangle_dual S [truncate_to_8] IX IY [STARTS EVALS]   one normal
//   proofs_triangle_dual S [truncate_to_8] survey [LIMIT]         the normals the bound leaves open at S
//   proofs_triangle_dual S [truncate_to_8] families IX IY [STEP]   one normal over the reduced geometry
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
// The geometry reduces to five two-parameter families (`families`; an argument, not yet a proof
// in the ledger: it is what a certified search of the relaxation would enumerate).
//  1. Translation: a lattice case's least vertex coordinates lie in (r − 1, r]; moving the triangle
//     and p by less than one pixel so that they equal r keeps the barycentric coordinates and the
//     steps and does not shorten a or b. So r = (0, 0) is the least vertex x and the least vertex y,
//     and every vertex coordinate is below 2048.
//  2. Scaling: diag(λ, μ) about r with λ, μ >= 1 keeps P_c(p) (barycentric coordinates are affine
//     invariants), divides the x steps by λ and the y steps by μ, and multiplies a by λ and b by μ;
//     λ·a·min(1, t/λ) = min(λ·a, a·t) >= a·min(1, t) for t >= 0, so the objective never falls. So the
//     bounding box is [0, 2048]².
//  3. The pixel: for fixed vertices and lights the objective is linear in p (P_c(p) is, and so are
//     p_x·clamp(t_x) and p_y·clamp(t_y), t depending on the vertices and lights only), so its maximum
//     over the closed triangle is at a vertex.
//  4. Three vertices attain the box's four extremes, so one of them is a corner of it. One corner
//     vertex: the other two lie on the two edges the corner does not touch (F1: corner (A, A), F2:
//     (A, 0), F3: (0, A), the mirror image of F2 under x <-> y, which maps the relaxation onto itself,
//     F4: (0, 0)); two corner vertices, opposite (A1, A2; the third anywhere) or adjacent (a case of the
//     others). A = 2048.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "proofs_search_args.hpp"
#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "proofs/two_pass_triangle.hpp"
#include "proofs/triangle_relaxation.hpp"

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
          if (f1 < r.dual(g, b, pattern, th)) hi = m2;
          else lo = m1;
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

// The family every full search has ended in so far: X = (0, 2047), Z = p = (2047, 2047), Y = (xY, 0),
// xY by ternary search on the attained value (a screen, not a supremum).
found corner_family(const relaxation& r) {
  double lo = 400, hi = 1400;
  auto at = [&](double xY) { return evaluate(r, corner_case(2047, xY, 2047, 2047)); };
  for (int it = 0; it < 24; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (at(m1).lower < at(m2).lower) lo = m1;
    else hi = m2;
  }
  const geometry g = corner_case(2047, (lo + hi) / 2, 2047, 2047);
  return {g, evaluate(r, g)};
}

found search(const relaxation& r, int starts, int evals, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> any(0, 2047);
  std::normal_distribution<double> gauss(0, 1);
  const geometry fixed[] = {corner_case(2047, 845, 2047, 2047), corner_case(845, 2047, 2047, 2047), corner_case(880, 1520, 2033, 2047)};
  found best;
  for (int k = 0; k < starts; ++k) {
    geometry g = k < 3 ? fixed[k] : corner_case(any(rng), any(rng), any(rng), any(rng));
    evaluation cur = evaluate(r, g);
    double step = 300;
    for (int i = 0; i < evals; ++i) {
      geometry n = g;
      for (double* v : {&n.v[0][1], &n.v[1][0], &n.v[2][0], &n.v[2][1]}) *v = std::clamp(*v + step * gauss(rng), 0.0, 2047.0);
      const evaluation e = evaluate(r, n);
      if (e.lower > cur.lower) g = n, cur = e;
      else step = std::max(0.25, step * 0.985);
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
  std::printf("  lower %.3f upper %.3f threshold %.3f margin %+.3f at (%.2f, %.2f), (%.2f, %.2f), (%.2f, %.2f), p = vertex %d\n",
              f.e.lower, f.e.upper, threshold, f.e.lower - threshold, f.g.v[0][0], f.g.v[0][1], f.g.v[1][0], f.g.v[1][1], f.g.v[2][0],
              f.g.v[2][1], f.g.p);
  for (int k = 0; k < 3; ++k) std::printf("    light %d = (%.3f, %.3f, %.3f)\n", k, f.e.l[k][0], f.e.l[k][1], f.e.l[k][2]);
}

// The reduction of the relaxation's supremum to five two-parameter families (argument in the
// header): the bounding box scaled to [0, 2048]², p a vertex, and a vertex at a corner of the box.
constexpr double box = 2048;
geometry family_member(int family, double u, double v, int p) {
  switch (family) {
    case 0: return {{{0, u}, {v, 0}, {box, box}}, p};    // F1: corner (A, A), the others on the left and top edges
    case 1: return {{{0, u}, {box, 0}, {v, box}}, p};    // F2: corner (A, 0), the others on the left and bottom edges (F3 is its mirror)
    case 2: return {{{0, 0}, {box, u}, {v, box}}, p};    // F4: corner (0, 0) = r, the others on the right and bottom edges
    case 3: return {{{0, 0}, {box, box}, {u, v}}, p};    // A1: two opposite corners, the third vertex anywhere
    default: return {{{0, box}, {box, 0}, {u, v}}, p};   // A2: the other two corners
  }
}
constexpr const char* family_names[] = {"F1", "F2", "F4", "A1", "A2"};

// Every family and choice of p on a grid of `step` pixels (a cheap dual), then a local search from
// the best grid point of each (full precision, attained values).
void families(const relaxation& r, double step, double threshold) {
  found overall;
  for (int f = 0; f < 5; ++f)
    for (int p = 0; p < 3; ++p) {
      double best_upper = -1e18, bu = 0, bv = 0;
      for (double u = 0; u <= box; u += step)
        for (double v = 0; v <= box; v += step) {
          const auto e = evaluate(r, family_member(f, u, v, p), box, 8, 30);
          if (e.upper > best_upper) best_upper = e.upper, bu = u, bv = v;
        }
      double u = bu, v = bv, h = step;
      evaluation cur = evaluate(r, family_member(f, u, v, p), box);
      while (h > 0.25) {
        bool moved = false;
        for (const auto& [du, dv] : {std::pair{h, 0.0}, {-h, 0.0}, {0.0, h}, {0.0, -h}}) {
          const double nu = std::clamp(u + du, 0.0, box), nv = std::clamp(v + dv, 0.0, box);
          const auto e = evaluate(r, family_member(f, nu, nv, p), box);
          if (e.lower > cur.lower) u = nu, v = nv, cur = e, moved = true;
        }
        if (!moved) h /= 2;
      }
      std::printf("  %s, p = vertex %d: grid upper %.1f at (%g, %g); attained %.3f (upper %.3f) at u = %.2f, v = %.2f, margin %+.3f\n",
                  family_names[f], p, best_upper, bu, bv, cur.lower, cur.upper, u, v, cur.lower - threshold);
      std::fflush(stdout);
      if (cur.lower > overall.e.lower) overall = {family_member(f, u, v, p), cur};
    }
  std::printf("best over the families:\n");
  print_found(overall, threshold);
}
}  // namespace

int main(int argc, char** argv) {
  const auto args = gsdot3::bench::parse_search_args(argc, argv, "proofs_triangle_dual", " (IX IY [STARTS EVALS] | survey [LIMIT])");
  const int s = args.s;
  const p::two_pass::table t(args.o);
  if (argc > args.next && std::strcmp(argv[args.next], "survey") == 0) {
    const int limit = argc > args.next + 1 ? std::atoi(argv[args.next + 1]) : 100;
    // Every (|n| sorted, side threshold) the bound leaves open at s, most open first.
    std::map<std::tuple<int, int, int, double>, std::tuple<std::int64_t, int, int>> open;
    for (const auto& nm : p::appendix2_normals()) {
      std::array<int, 3> a{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
      std::sort(a.begin(), a.end());
      const std::int64_t reach = tt::reach_units({a[0], a[1], a[2]}, s, tt::window_pixels);
      const int e = t.alpha_error(nm);
      const std::int64_t top = tt::wrap_threshold_units(nm, e, 1, args.o), bottom = tt::wrap_threshold_units(nm, e, -1, args.o);
      const auto th = thresholds(nm, t, args.o);
      if (reach + tt::truncation_units(nm, 1, args.o) >= top) open.emplace(std::tuple{a[0], a[1], a[2], th.top}, std::tuple{reach - top, nm.iX, nm.iY});
      if (reach + tt::truncation_units(nm, -1, args.o) >= bottom) open.emplace(std::tuple{a[0], a[1], a[2], th.bottom}, std::tuple{reach - bottom, nm.iX, nm.iY});
    }
    std::vector<std::pair<std::int64_t, std::tuple<int, int, int, double>>> order;
    for (const auto& [k, v] : open) order.push_back({std::get<0>(v), k});
    std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    // Screen every open class on the corner family, then search the `limit` highest in full.
    struct screened {
      double margin;
      std::array<int, 3> w;
      double threshold;
      std::int64_t gap;
    };
    std::vector<screened> all;
    for (const auto& [gap, k] : order) {
      const auto [w0, w1, w2, th] = k;
      const relaxation r{{double(w0), double(w1), double(w2)}, double(s)};
      all.push_back({corner_family(r).e.lower - th, {w0, w1, w2}, th, gap});
    }
    std::sort(all.begin(), all.end(), [](const screened& x, const screened& y) { return x.margin > y.margin; });
    const auto above = std::count_if(all.begin(), all.end(), [](const screened& x) { return x.margin > 0; });
    std::printf("s = %d (%s): %zu classes (|n| sorted, side threshold) the bound leaves open; %td above their threshold on the "
                "corner family; full search of the first %d\n",
                s, args.option_name(), all.size(), above, std::min<int>(limit, static_cast<int>(all.size())));
    int done = 0;
    for (const auto& c : all) {
      if (done++ == limit) break;
      const relaxation r{{double(c.w[0]), double(c.w[1]), double(c.w[2])}, double(s)};
      const found f = search(r, 4, 150, 1);
      std::printf("|n| = (%d, %d, %d), bound over by %lld units, corner family margin %+.3f:\n", c.w[0], c.w[1], c.w[2],
                  static_cast<long long>(c.gap), c.margin);
      print_found(f, c.threshold);
      std::fflush(stdout);
    }
    return 0;
  }
  if (argc > args.next + 2 && std::strcmp(argv[args.next], "families") == 0) {
    const auto nm = p::paper::pack_normal_from(std::atoi(argv[args.next + 1]), std::atoi(argv[args.next + 2]));
    const double step = argc > args.next + 3 ? std::atof(argv[args.next + 3]) : 128;
    const relaxation r{{double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))}, double(s)};
    const auto th = thresholds(nm, t, args.o);
    std::printf("s = %d (%s), n = (%d, %d, %d), top threshold %.3f, bottom %.3f\n", s, args.option_name(), nm.iX, nm.iY, nm.iZ, th.top,
                th.bottom);
    families(r, step, std::min(th.top, th.bottom));
    return 0;
  }
  if (argc < args.next + 2) {
    std::fprintf(stderr, "usage: proofs_triangle_dual S [truncate_to_8] (IX IY [STARTS EVALS] | survey [LIMIT] | families IX IY [STEP])\n");
    return 2;
  }
  const int iX = std::atoi(argv[args.next]), iY = std::atoi(argv[args.next + 1]);
  const int starts = argc > args.next + 2 ? std::atoi(argv[args.next + 2]) : 8, evals = argc > args.next + 3 ? std::atoi(argv[args.next + 3]) : 400;
  const auto nm = p::paper::pack_normal_from(iX, iY);
  const relaxation r{{double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))}, double(s)};
  const auto th = thresholds(nm, t, args.o);
  const found f = search(r, starts, evals, 1);
  std::printf("s = %d (%s), n = (%d, %d, %d): top side\n", s, args.option_name(), nm.iX, nm.iY, nm.iZ);
  print_found(f, th.top);
  std::printf("bottom side: threshold %.3f margin %+.3f\n", th.bottom, f.e.lower - th.bottom);
  return 0;
}
