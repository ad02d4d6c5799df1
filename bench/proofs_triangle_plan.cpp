// proofs_triangle_plan — which integer steps to aim at in a triangle certificate of
// two-pass.max-s.interpolated: the exact optimum of a continuous model of the truncated steps, per
// choice of steps. Not a benchmark, not a test and not a proof (it leaves the lattice, the 12.4
// vertices, the start value's truncation and the floors out); deterministic.
//
//   proofs_triangle_plan W0 W1 W2 S [GX_LO GX_HI GY_LO GY_HI] [TOP]
// W = (|n_c|), wrap-side signs folded in (σ_c = +1: larger is closer to the wrap). Geometry as in
// proofs_triangle_steep: r = (0, 0), X = (0, yX), Y = (xY, 0), Z = (xZ, yZ) real in [0, 2047], the
// pixel p = Z (the light plane is linear, so the extreme covered pixel sits at a vertex; X and Y are
// the case xZ = 0 or yZ = 0). Per channel c and axis the exact gradient is taken at an integer G
// (units per pixel; GX in GX_LO..GX_HI, default −1..0, GY in GY_LO..GY_HI, default −1..12) in the
// limit from above: the GS truncates it toward zero to m = G + 1 for G < 0 (a gain of one unit per
// pixel along that axis, the lag of the certificates) and to m = G for G >= 0 (no loss). So, with
// P_c the exact plane in levels,
//   l_V,c = P_c(r) + (G_x,c·V_x + G_y,c·V_y)/128 for V = X, Y, Z,   L_c(p) = P_c(r) + (m_x,c·x_p + m_y,c·y_p)/128,
// and for one geometry and one choice of G the best Σ W_c·L_c(p) is a linear function of P(r) over
// the intersection of three balls |l_V| <= S, maximised exactly: on one sphere (P = centre + S·Ŵ),
// on the circle of two, or at a point of all three (the KKT cases; the first feasible best wins).
// The geometry is searched from a 5⁴ grid, then by pattern search from the best three points.
// Prints the TOP (default 10) choices of G, best first, with Σ W_c·L_c(p) in W·level units (compare
// with 128·(128 − #gain − e) as in proofs_triangle_relaxation), the geometry and the three lights.
//
//   proofs_triangle_plan survey S [truncate_to_8] [TOP]
// Every Appendix 2 normal and wrap side, ranked by the margin of the steep family (one channel with
// G = (−1, K), K = 1..12, the other two (−1, −1): the construction of proofs_triangle_steep) over the
// wrap threshold 128·(128 − #neg − e) (top) or 128·(129 − #pos + e) (bottom), e the alpha error
// (two_pass::table::alpha_error; a wrap needs the floors to give back what the threshold leaves).
// truncate_to_8 only changes e's table; the model's truncation of the light is not in the plan.
// The printed yX range is the plan's ±12 pixels; the lattice puts yX on multiples of 128/(K + 1)
// (proofs_triangle_lattice, which also gives the best the lattice reaches: at s = 84 it lies 37 to
// 61 W·level units below the plan's optimum for the top normals).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string_view>
#include <vector>

#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"

namespace {
using vec = std::array<double, 3>;
constexpr double W = 2047;

double dot(const vec& a, const vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
vec add(const vec& a, const vec& b, double k = 1) { return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]}; }
vec cross(const vec& a, const vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// max w·x over |x − c_i| <= s (i = 0, 1, 2), or −1e18 if the intersection is empty.
double ball_max(const vec& w, const std::array<vec, 3>& c, double s, vec& at) {
  const double len = std::sqrt(dot(w, w));
  auto feasible = [&](const vec& x) {
    for (const vec& ci : c) {
      const vec d = add(x, ci, -1);
      if (dot(d, d) > s * s * (1 + 1e-12) + 1e-9) return false;
    }
    return true;
  };
  double best = -1e18;
  auto take = [&](const vec& x) {
    if (feasible(x) && dot(w, x) > best) best = dot(w, x), at = x;
  };
  for (const vec& ci : c) take(add(ci, w, s / len));
  if (best > -1e18) return best;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const vec u = add(c[static_cast<std::size_t>(j)], c[static_cast<std::size_t>(i)], -1);
      const double d2 = dot(u, u);
      if (d2 > 4 * s * s) return -1e18;
      if (d2 == 0) continue;
      const vec m = add(c[static_cast<std::size_t>(i)], u, 0.5);
      const double rho = std::sqrt(s * s - d2 / 4);
      const vec perp = add(w, u, -dot(w, u) / d2);
      const double pl = std::sqrt(dot(perp, perp));
      take(pl > 0 ? add(m, perp, rho / pl) : m);
    }
  if (best > -1e18) return best;
  // all three spheres: the circumcentre of the centres ± h along the plane's normal
  const vec a = add(c[1], c[0], -1), b = add(c[2], c[0], -1), nrm = cross(a, b);
  const double nn = dot(nrm, nrm);
  if (nn == 0) return -1e18;
  // circumcentre offset: (|a|²·(b × n) + |b|²·(n × a)) / (2·|n|²)
  const vec bn = cross(b, nrm), na = cross(nrm, a);
  const vec off = {(dot(a, a) * bn[0] + dot(b, b) * na[0]) / (2 * nn), (dot(a, a) * bn[1] + dot(b, b) * na[1]) / (2 * nn),
                   (dot(a, a) * bn[2] + dot(b, b) * na[2]) / (2 * nn)};
  const double h2 = s * s - dot(off, off);
  if (h2 < 0) return -1e18;
  const vec centre = add(c[0], off);
  for (double sg : {1.0, -1.0}) take(add(centre, nrm, sg * std::sqrt(h2 / nn)));
  return best;
}

struct choice {
  int gx[3], gy[3];
};
struct geometry {
  double yX, xY, xZ, yZ;
};
struct plan {
  double value = -1e18;
  choice g{};
  geometry at{};
  vec pr{};
};

double evaluate(const vec& w, const choice& g, const geometry& k, double s, vec& pr) {
  for (double v : {k.yX, k.xY, k.xZ, k.yZ})
    if (v < 0 || v > W) return -1e18;
  if (std::fabs(k.xY * (k.yZ - k.yX) + k.xZ * k.yX) < 1) return -1e18;  // degenerate
  const double V[3][2] = {{0, k.yX}, {k.xY, 0}, {k.xZ, k.yZ}};
  std::array<vec, 3> centres{};
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 3; ++c) centres[static_cast<std::size_t>(v)][static_cast<std::size_t>(c)] = -(g.gx[c] * V[v][0] + g.gy[c] * V[v][1]) / 128;
  double best = ball_max(w, centres, s, pr);
  if (best <= -1e18) return best;
  for (int c = 0; c < 3; ++c) {
    const int mx = g.gx[c] < 0 ? g.gx[c] + 1 : g.gx[c], my = g.gy[c] < 0 ? g.gy[c] + 1 : g.gy[c];
    best += w[static_cast<std::size_t>(c)] * (mx * k.xZ + my * k.yZ) / 128;
  }
  return best;
}

plan optimise(const vec& w, const choice& g, double s) {
  std::vector<std::pair<double, geometry>> grid;
  const double pts[5] = {0, 512, 1024, 1536, W};
  vec pr{};
  for (double a : pts)
    for (double b : pts)
      for (double c : pts)
        for (double d : pts) {
          const geometry k{a, b, c, d};
          grid.push_back({evaluate(w, g, k, s, pr), k});
        }
  std::partial_sort(grid.begin(), grid.begin() + 3, grid.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  plan best;
  for (int start = 0; start < 3; ++start) {
    if (grid[static_cast<std::size_t>(start)].first <= -1e18) break;
    geometry k = grid[static_cast<std::size_t>(start)].second;
    double cur = grid[static_cast<std::size_t>(start)].first;
    for (double step = 256; step >= 0.25;) {
      bool moved = false;
      for (int p = 0; p < 4; ++p)
        for (double sg : {1.0, -1.0}) {
          geometry q = k;
          double* f[4] = {&q.yX, &q.xY, &q.xZ, &q.yZ};
          *f[p] = std::clamp(*f[p] + sg * step, 0.0, W);
          const double v = evaluate(w, g, q, s, pr);
          if (v > cur + 1e-9) cur = v, k = q, moved = true;
        }
      if (!moved) step /= 2;
    }
    if (cur > best.value) {
      best.value = cur, best.g = g, best.at = k;
      evaluate(w, g, k, s, best.pr);
    }
  }
  return best;
}
void print_plan(const plan& p) {
  std::printf("%.2f  G = (%d,%d) (%d,%d) (%d,%d)  X = (0, %.2f) Y = (%.2f, 0) Z = p = (%.2f, %.2f)\n", p.value, p.g.gx[0], p.g.gy[0],
              p.g.gx[1], p.g.gy[1], p.g.gx[2], p.g.gy[2], p.at.yX, p.at.xY, p.at.xZ, p.at.yZ);
  const double V[3][2] = {{0, p.at.yX}, {p.at.xY, 0}, {p.at.xZ, p.at.yZ}};
  for (int v = 0; v < 3; ++v) {
    vec l{};
    for (int c = 0; c < 3; ++c) l[static_cast<std::size_t>(c)] = p.pr[static_cast<std::size_t>(c)] + (p.g.gx[c] * V[v][0] + p.g.gy[c] * V[v][1]) / 128;
    std::printf("      light %c = (%.2f, %.2f, %.2f) |l| = %.2f\n", "XYZ"[v], l[0], l[1], l[2], std::sqrt(dot(l, l)));
  }
}

// The proofs_triangle_steep command that searches the lattice around a steep-family plan. Y is not
// pinned by the objective (the plan leaves it inside the ball), but a packed light lies on the
// shell: Y = (xY, 0) moves to where |l_Y| = S (the root of the quadratic in xY nearest the plan's
// xY), which sets D1; D2 and yX as in the plan, X's light unfolded by the wrap-side signs.
void print_steep_command(const plan& p, double s, const gs::model_options& o, const std::array<int, 3>& n, int side) {
  int third = 0;
  for (int c = 0; c < 3; ++c)
    if (p.g.gy[c] > 0) third = c;
  // l_Y(xY) = P(r) + G_x·xY/128: |l_Y|² = s² is a quadratic in t = xY/128
  double qa = 0, qb = 0, qc = -s * s;
  for (std::size_t c = 0; c < 3; ++c) qa += p.g.gx[c] * p.g.gx[c], qb += 2 * p.pr[c] * p.g.gx[c], qc += p.pr[c] * p.pr[c];
  double xY = p.at.xY;
  const double disc = qb * qb - 4 * qa * qc;
  if (qa > 0 && disc >= 0) {
    double bestd = 1e18;
    for (double sg : {1.0, -1.0}) {
      const double x = 128 * (-qb + sg * std::sqrt(disc)) / (2 * qa);
      if (x >= 0 && x <= W && std::fabs(x - p.at.xY) < bestd) bestd = std::fabs(x - p.at.xY), xY = x;
    }
  }
  const int d1 = static_cast<int>(std::lround((xY - p.at.yX) / 128)), d2 = static_cast<int>(std::lround((p.at.xZ + p.at.yZ - p.at.yX) / 128));
  const int yx = static_cast<int>(std::lround(p.at.yX));
  int lx[3];
  for (std::size_t c = 0; c < 3; ++c) lx[c] = (n[c] >= 0 ? 1 : -1) * side * static_cast<int>(std::lround(p.pr[c] + p.g.gy[c] * p.at.yX / 128));
  std::printf("      steep: proofs_triangle_steep %g%s %d %d %d %d %d %d %d %d %d %d %d 6\n", s,
              o.gouraud == gs::gouraud_fraction::truncate_to_8 ? " truncate_to_8" : "", n[0], n[1], side, third, lx[0], lx[1], lx[2], d1,
              d2, std::max(0, yx - 12), std::min(2047, yx + 12));
}

int survey(int argc, char** argv) {
  namespace p2 = gsdot3::proofs::two_pass;
  const double s = argc > 2 ? std::atof(argv[2]) : 0;
  int next = 3;
  gs::model_options o{};
  if (argc > next && std::string_view(argv[next]) == "truncate_to_8") o.gouraud = gs::gouraud_fraction::truncate_to_8, ++next;
  const int top = argc > next ? std::atoi(argv[next]) : 20;
  if (s <= 0 || top < 1) {
    std::fprintf(stderr, "usage: proofs_triangle_plan survey S [truncate_to_8] [TOP]\n");
    return 2;
  }
  const p2::table t(o);
  std::map<std::array<int, 3>, plan> memo;  // by |n_c|
  struct row {
    double margin;
    int iX, iY, iZ, side, e;
    plan p;
  };
  std::vector<row> rows;
  for (const auto& nm : gsdot3::proofs::appendix2_normals()) {
    const std::array<int, 3> w{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
    auto it = memo.find(w);
    if (it == memo.end()) {
      plan best;
      for (int third = 0; third < 3; ++third)
        for (int K = 1; K <= 12; ++K) {
          choice g{{-1, -1, -1}, {-1, -1, -1}};
          g.gy[third] = K;
          const plan q = optimise({double(w[0]), double(w[1]), double(w[2])}, g, s);
          if (q.value > best.value) best = q;
        }
      it = memo.emplace(w, best).first;
    }
    const int e = t.alpha_error(nm), neg = (nm.iX < 0) + (nm.iY < 0) + (nm.iZ < 0);
    rows.push_back({it->second.value - 128.0 * (128 - neg - e), nm.iX, nm.iY, nm.iZ, 1, e, it->second});
    rows.push_back({it->second.value - 128.0 * (129 - (3 - neg) + e), nm.iX, nm.iY, nm.iZ, -1, e, it->second});
  }
  std::sort(rows.begin(), rows.end(), [](const row& a, const row& b) { return a.margin > b.margin; });
  std::printf("s = %g: %zu normals, %zu |n| classes\n", s, gsdot3::proofs::appendix2_normals().size(), memo.size());
  for (int i = 0; i < top && i < static_cast<int>(rows.size()); ++i) {
    const row& r = rows[static_cast<std::size_t>(i)];
    std::printf("margin %+.2f  n = (%d, %d, %d) side %+d e %+d  ", r.margin, r.iX, r.iY, r.iZ, r.side, r.e);
    print_plan(r.p);
    print_steep_command(r.p, s, o, {r.iX, r.iY, r.iZ}, r.side);
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string_view(argv[1]) == "survey") return survey(argc, argv);
  if (argc < 5) {
    std::fprintf(stderr, "usage: proofs_triangle_plan W0 W1 W2 S [GX_LO GX_HI GY_LO GY_HI] [TOP]\n");
    return 2;
  }
  const vec w = {std::atof(argv[1]), std::atof(argv[2]), std::atof(argv[3])};
  const double s = std::atof(argv[4]);
  int gx_lo = -1, gx_hi = 0, gy_lo = -1, gy_hi = 12, top = 10;
  if (argc >= 9) gx_lo = std::atoi(argv[5]), gx_hi = std::atoi(argv[6]), gy_lo = std::atoi(argv[7]), gy_hi = std::atoi(argv[8]);
  if (argc >= 10) top = std::atoi(argv[9]);
  if (gx_lo > gx_hi || gy_lo > gy_hi || top < 1 || s <= 0) {
    std::fprintf(stderr, "proofs_triangle_plan: GX_LO <= GX_HI, GY_LO <= GY_HI, TOP >= 1, S > 0\n");
    return 2;
  }
  std::vector<plan> plans;
  choice g{};
  const int nx = gx_hi - gx_lo + 1, ny = gy_hi - gy_lo + 1, per = nx * ny;
  for (int code = 0; code < per * per * per; ++code) {
    int r = code;
    for (int c = 0; c < 3; ++c, r /= per) g.gx[c] = gx_lo + (r % per) % nx, g.gy[c] = gy_lo + (r % per) / nx;
    plans.push_back(optimise(w, g, s));
  }
  std::sort(plans.begin(), plans.end(), [](const plan& a, const plan& b) { return a.value > b.value; });
  for (int i = 0; i < top && i < static_cast<int>(plans.size()); ++i) print_plan(plans[static_cast<std::size_t>(i)]);
  return 0;
}
