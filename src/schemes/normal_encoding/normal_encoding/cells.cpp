// The rounding-cell worst case (argument in cells.hpp): farthest(), the dihedral reduction, the threads
// that split the first code coordinate, and the witness inside the worst cell. The cells themselves are
// cut into pieces by planar_cells.cpp and lambert_cells.cpp (cell_pieces.hpp).
#include "normal_encoding/cells.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "normal_encoding/cell_pieces.hpp"
#include "normal_encoding/spherical_lut.hpp"
#include "normal_encoding/stereographic.hpp"

namespace gsdot3::normal_encoding {

namespace {
constexpr double feasible_eps = 1e-12;
constexpr double pi = std::numbers::pi;

bool feasible(vec3 p, const std::vector<halfspace>& h) {
  for (const auto& c : h)
    if (dot(c.a, p) < c.b - feasible_eps) return false;
  return true;
}
}  // namespace

farthest_point farthest(vec3 d, std::vector<halfspace> h) {
  for (auto& c : h) {
    const double l = length(c.a);
    c.a = (1 / l) * c.a;
    c.b /= l;
  }
  farthest_point best;
  auto consider = [&](vec3 p) {
    if (!feasible(p, h)) return;
    best.nonempty = true;
    const double v = dot(d, p);
    if (v < best.min_dot) {
      best.min_dot = v;
      best.p = p;
    }
  };
  consider(-1.0 * d);
  for (const auto& c : h) {  // the minimum of d·n on each face circle
    if (std::fabs(c.b) > 1) continue;
    const vec3 centre = c.b * c.a;
    const double r = std::sqrt(1 - c.b * c.b);
    vec3 w = d - dot(d, c.a) * c.a;
    if (length(w) < 1e-15) w = std::fabs(c.a.x) < 0.9 ? cross(c.a, vec3{1, 0, 0}) : cross(c.a, vec3{0, 1, 0});
    consider(centre - (r / length(w)) * w);
  }
  for (std::size_t k = 0; k < h.size(); ++k)  // the vertices: sphere ∩ two planes
    for (std::size_t l = k + 1; l < h.size(); ++l) {
      const double g = dot(h[k].a, h[l].a), det = 1 - g * g;
      if (det < 1e-14) continue;
      const double al = (h[k].b - g * h[l].b) / det, be = (h[l].b - g * h[k].b) / det;
      const vec3 p0 = al * h[k].a + be * h[l].a;
      const double t2 = (1 - dot(p0, p0)) / det;
      if (t2 < 0) continue;
      const vec3 e = std::sqrt(t2) * cross(h[k].a, h[l].a);
      consider(p0 + e);
      consider(p0 - e);
    }
  return best;
}

void cell_pieces::acc::merge(const acc& later) {
  w.cells += later.w.cells;
  if (later.w.nonfinite_cells > 0 && (w.nonfinite_cells == 0 || before(later.w.nonfinite_q, w.nonfinite_q))) {
    w.nonfinite_q = later.w.nonfinite_q;
    w.nonfinite_n = later.w.nonfinite_n;
  }
  w.nonfinite_cells += later.w.nonfinite_cells;
  if (later.sup_rad > sup_rad || (later.sup_rad == sup_rad && before(later.w.q, w.q))) {
    sup_rad = later.sup_rad;
    w.q = later.w.q;
    w.n = later.w.n;
    d = later.d;
  }
  upper_rad = std::max(upper_rad, later.upper_rad);
}

namespace {

using cell_pieces::acc;

// The dihedral reduction (cells.hpp): for methods that commute with x -> −x, y -> −y and x <-> y —
// their codes map to M − q (unorm; M odd, so no code is its own mirror) or −q (snorm) and their
// decodes to the mirrored vector — every cell is the mirror of one with i >= j >= the first code of
// positive u. The sup over those is the sup over all (test: reduction_matches_full_enumeration).
bool symmetric(method_id id) {
  switch (id) {
    case method_id::xyz:
    case method_id::xy:
    case method_id::xy_sign:
    case method_id::view_space:
    case method_id::spheremap:
    case method_id::cryengine3:
    case method_id::lambert:
    case method_id::stereographic:
    case method_id::octahedral:
    case method_id::octahedral_precise:
    case method_id::octahedral_snorm: return true;
    default: return false;
  }
}
std::uint32_t first_positive(method_id id, int bits) {
  return id == method_id::octahedral_snorm ? (std::uint32_t{1} << (bits - 1)) : (unorm_max(bits) + 1) / 2;
}

bool lambert_family(method_id id) {
  return id == method_id::spheremap || id == method_id::cryengine3 || id == method_id::lambert;
}

// A unit n that really encodes to q, near the closure point p (the supremum is approached, not
// always attained: e.g. at a pole the encoder cannot take). Tries p, then p moved towards d, then
// deterministic perturbations of radius 2^-10 .. 2^-40 around p; keeps the largest true angle.
vec3 inside_witness(const method& m, int bits, code q, vec3 p, vec3 d) {
  vec3 best = p;
  double best_angle = -1;
  auto consider = [&](vec3 n) {
    n = normalize(n);
    if (!finite(n) || (m.front_hemisphere && n.z < 0) || !(m.encode(n, bits) == q)) return;
    const double a = angle(m.decode(q, bits), n);
    if (a > best_angle || (std::isnan(a) && best_angle < 0)) {
      best_angle = std::isnan(a) ? 0 : a;
      best = n;
    }
  };
  consider(p);
  for (int e = -40; e <= -4; e += 2) consider(p + std::ldexp(1.0, e) * (d - p));
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53 * 2 - 1;
  };
  for (int e = -10; e >= -40; e -= 2)
    for (int k = 0; k < 64; ++k) consider(p + std::ldexp(1.0, e) * vec3{uniform(), uniform(), uniform()});
  if (m.id == method_id::stereographic) {
    // Cells clamped at the square's border reach the pole along a strip: walk out along it, the
    // inverse projection of (X, Y) being (2X, 2Y, 1 − X² − Y²)/(1 + X² + Y²).
    const double mx = unorm_max(bits), s = stereographic::scale;
    for (double k = 10; k <= 1e8; k *= 10) {
      const double X = q.c[0] == 0 ? -k : q.c[0] == mx ? k : (2 * q.c[0] / mx - 1) * s;
      const double Y = q.c[1] == 0 ? -k : q.c[1] == mx ? k : (2 * q.c[1] / mx - 1) * s;
      const double r2 = X * X + Y * Y;
      consider(vec3{2 * X, 2 * Y, 1 - r2});
    }
  }
  return best;
}

}  // namespace

worst_case cell_worst_case(const method& m, int bits, unsigned threads, double tolerance_rad, bool use_symmetry,
                           code_window win) {
  check_bits(m, bits);
  const std::uint32_t first = m.id == method_id::spherical_lut      ? spherical_lut::size
                              : m.id == method_id::octahedral_snorm ? (std::uint32_t{1} << bits)
                                                                    : unorm_max(bits) + 1;
  const cell_pieces::code_filter filter{use_symmetry && symmetric(m.id), win, first_positive(m.id, bits)};
  auto run = [&](double global_lb, double tol) {
    const unsigned t = std::max(1U, threads);
    std::vector<acc> parts(t);
    std::vector<std::jthread> pool;
    for (unsigned w = 0; w < t; ++w)
      pool.emplace_back([&, w] {
        for (std::uint32_t i = win.i0 / t * t + w; i < first && i <= win.i1; i += t) {
          if (i < win.i0) continue;
          if (lambert_family(m.id))
            cell_pieces::lambert_pieces(m, bits, i, tol, global_lb, filter, parts[w]);
          else
            cell_pieces::planar_pieces(m, bits, i, filter, parts[w]);
        }
      });
    pool.clear();
    acc all;
    for (const auto& p : parts) all.merge(p);
    return all;
  };
  acc all = run(0, lambert_family(m.id) ? 1e-4 : tolerance_rad);
  // second pass: prune against the first's best
  if (lambert_family(m.id)) all = run(all.sup_rad, tolerance_rad);
  worst_case w = all.w;
  w.reduced = use_symmetry && symmetric(m.id);
  w.witness = inside_witness(m, bits, w.q, w.n, all.d);
  if (w.nonfinite_cells > 0) w.nonfinite_n = inside_witness(m, bits, w.nonfinite_q, w.nonfinite_n, w.nonfinite_n);
  w.branch_and_bound = lambert_family(m.id);
  w.sup_deg = all.sup_rad * 180 / pi;
  w.upper_deg = (lambert_family(m.id) ? std::max(all.upper_rad, all.sup_rad + tolerance_rad) : all.sup_rad) * 180 / pi;
  return w;
}

}  // namespace gsdot3::normal_encoding
