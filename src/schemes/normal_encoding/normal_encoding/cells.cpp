// The rounding-cell worst case (argument in cells.hpp).
#include "normal_encoding/cells.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "normal_encoding/spherical.hpp"
#include "normal_encoding/spherical_lut.hpp"
#include "normal_encoding/spheremap.hpp"
#include "normal_encoding/stereographic.hpp"

namespace gsdot3::normal_encoding {

namespace {
constexpr double feasible_eps = 1e-12;
constexpr double inf = std::numeric_limits<double>::infinity();
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

namespace {

// The running worst cell. Ties (equal angles, e.g. mirror-image cells) go to the least code in
// lexicographic order, and the first NaN cell is the least such code, so the result does not depend on
// how the codes are split between threads.
bool before(const code& a, const code& b) noexcept { return std::lexicographical_compare(a.c, a.c + 3, b.c, b.c + 3); }
struct acc {
  worst_case w;
  double sup_rad = -1, upper_rad = -1;
  vec3 d{};  // the decoded direction of the worst cell
  void add_nonfinite(code q, vec3 p) {
    if (w.nonfinite_cells++ == 0 || before(q, w.nonfinite_q)) {
      w.nonfinite_q = q;
      w.nonfinite_n = p;
    }
  }
  void add(code q, vec3 dn, double a, vec3 p, double upper) {
    if (a > sup_rad || (a == sup_rad && before(q, w.q))) {
      sup_rad = a;
      w.q = q;
      w.n = p;
      d = dn;
    }
    upper_rad = std::max(upper_rad, upper);
  }
  void merge(const acc& later) {
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
};

// The interval of a normal component c (stored as c·0.5 + 0.5, unorm) that rounds to q.
void unorm_interval(std::uint32_t q, int bits, double& lo, double& hi) {
  const double m = unorm_max(bits);
  lo = 2 * (q - 0.5) / m - 1;
  hi = 2 * (q + 0.5) / m - 1;
}
void box(std::vector<halfspace>& h, vec3 axis, double lo, double hi) {
  if (lo > -1) h.push_back({axis, lo});
  if (hi < 1) h.push_back({-1.0 * axis, -hi});
}
double min_sq(double lo, double hi) { return lo <= 0 && hi >= 0 ? 0 : std::min(lo * lo, hi * hi); }
double max_sq(double lo, double hi) { return std::max(lo * lo, hi * hi); }

// The dihedral reduction (cells.hpp): for methods that commute with x -> −x, y -> −y and x <-> y —
// their codes map to M − q (unorm; M odd, so no code is its own mirror) or −q (snorm) and their
// decodes to the mirrored vector — every cell is the mirror of one with i >= j >= the first code of
// positive u. The sup over those is the sup over all (test: reduction_matches_full_enumeration).
bool symmetric(method_id id) {
  switch (id) {
    case method_id::xyz: case method_id::xy: case method_id::xy_sign: case method_id::view_space:
    case method_id::spheremap: case method_id::cryengine3: case method_id::lambert: case method_id::stereographic:
    case method_id::octahedral: case method_id::octahedral_precise: case method_id::octahedral_snorm:
      return true;
    default:
      return false;
  }
}
thread_local bool reduce = false;
thread_local code_window window{};  // all codes by default
std::uint32_t first_positive(method_id id, int bits) {
  return id == method_id::octahedral_snorm ? (std::uint32_t{1} << (bits - 1)) : (unorm_max(bits) + 1) / 2;
}
bool skipped(const method& m, int bits, std::uint32_t i, std::uint32_t j) {
  if (i < window.i0 || i > window.i1 || j < window.j0 || j > window.j1) return true;
  if (!reduce) return false;
  const std::uint32_t c = first_positive(m.id, bits);
  return i < c || j < c || j > i;
}

// One piece: its code, its half-spaces.
void evaluate_piece(const method& m, int bits, code q, std::vector<halfspace> h, acc& a) {
  const vec3 dv = m.decode(q, bits);
  if (!finite(dv) || dot(dv, dv) == 0) {
    const auto f = farthest({0, 0, 1}, h);
    if (f.nonempty) {
      ++a.w.cells;
      a.add_nonfinite(q, f.p);
    }
    return;
  }
  const vec3 d = normalize(dv);
  const auto f = farthest(d, std::move(h));
  if (!f.nonempty) return;
  ++a.w.cells;
  const double ang = angle(d, f.p);
  a.add(q, d, ang, f.p, ang);
}

// Planar methods: the pieces with first code coordinate i.
void planar_pieces(const method& m, int bits, std::uint32_t i, acc& a) {
  const std::uint32_t mx = unorm_max(bits);
  const vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  switch (m.id) {
    case method_id::xyz: {
      double x0, x1;
      unorm_interval(i, bits, x0, x1);
      for (std::uint32_t j = 0; j <= mx; ++j) {
        if (skipped(m, bits, i, j)) continue;
        double y0, y1;
        unorm_interval(j, bits, y0, y1);
        const double r2min = min_sq(x0, x1) + min_sq(y0, y1), r2max = max_sq(x0, x1) + max_sq(y0, y1);
        if (r2min > 1) continue;
        const double zlo = std::sqrt(std::max(0.0, 1 - r2max)), zhi = std::sqrt(std::max(0.0, 1 - r2min));
        auto zcode = [&](double z) { return unorm_encode(z * 0.5 + 0.5, bits); };
        // z codes whose interval meets ±[zlo, zhi] (those strictly inside (−zlo, zlo) cannot).
        const std::uint32_t gap0 = zcode(-zlo), gap1 = zcode(zlo);
        for (std::uint32_t k = zcode(-zhi); k <= zcode(zhi); ++k) {
          if (k > gap0 && k < gap1) continue;
          {
            double z0, z1;
            unorm_interval(k, bits, z0, z1);
            std::vector<halfspace> h;
            box(h, ex, x0, x1);
            box(h, ey, y0, y1);
            box(h, ez, z0, z1);
            evaluate_piece(m, bits, {{i, j, k}}, std::move(h), a);
          }
        }
      }
      return;
    }
    case method_id::xy:
    case method_id::xy_sign:
    case method_id::view_space: {
      double x0, x1;
      unorm_interval(i, bits, x0, x1);
      for (std::uint32_t j = 0; j <= mx; ++j) {
        if (skipped(m, bits, i, j)) continue;
        double y0, y1;
        unorm_interval(j, bits, y0, y1);
        if (min_sq(x0, x1) + min_sq(y0, y1) > 1) continue;
        std::vector<halfspace> h;
        box(h, ex, x0, x1);
        box(h, ey, y0, y1);
        if (m.id == method_id::xy) {
          evaluate_piece(m, bits, {{i, j, 0}}, std::move(h), a);
        } else if (m.id == method_id::view_space) {
          h.push_back({ez, 0});
          evaluate_piece(m, bits, {{i, j, 0}}, std::move(h), a);
        } else {
          auto up = h, down = h;
          up.push_back({ez, 0});
          down.push_back({-1.0 * ez, 0});
          evaluate_piece(m, bits, {{i, j, 0}}, std::move(up), a);
          evaluate_piece(m, bits, {{i, j, 1}}, std::move(down), a);
        }
      }
      return;
    }
    case method_id::spherical: {
      // enc.x = (φ/kPI + 1)/2: φ ∈ kPI·[2(i − 1/2)/M − 1, 2(i + 1/2)/M − 1] ∩ [−π, π]; a wedge.
      double p0, p1;
      unorm_interval(i, bits, p0, p1);
      p0 = std::max(-pi, p0 * spherical::kPI);
      p1 = std::min(pi, p1 * spherical::kPI);
      for (std::uint32_t j = 0; j <= mx; ++j) {
        if (skipped(m, bits, i, j)) continue;
        double z0, z1;
        unorm_interval(j, bits, z0, z1);
        std::vector<halfspace> h{{{-std::sin(p0), std::cos(p0), 0}, 0}, {{std::sin(p1), -std::cos(p1), 0}, 0}};
        box(h, ez, z0, z1);
        evaluate_piece(m, bits, {{i, j, 0}}, std::move(h), a);
      }
      return;
    }
    case method_id::spherical_lut: {
      // Pieces per atan2-LUT texel (i = texel x here, j = texel y) × z code: boxes.
      const double tx0 = 2.0 * i / spherical_lut::size - 1, tx1 = 2.0 * (i + 1) / spherical_lut::size - 1;
      for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(spherical_lut::size); ++j) {
        const double ty0 = 2.0 * j / spherical_lut::size - 1, ty1 = 2.0 * (j + 1) / spherical_lut::size - 1;
        const double r2min = min_sq(tx0, tx1) + min_sq(ty0, ty1), r2max = max_sq(tx0, tx1) + max_sq(ty0, ty1);
        if (r2min > 1) continue;
        const std::uint32_t ac = spherical_lut::lut().atan2_lookup[j * spherical_lut::size + i];
        const double zlo = std::sqrt(std::max(0.0, 1 - r2max)), zhi = std::sqrt(std::max(0.0, 1 - r2min));
        auto zcode = [&](double z) { return unorm_encode(z * 0.5 + 0.5, 8); };
        const std::uint32_t gap0 = zcode(-zlo), gap1 = zcode(zlo);
        for (std::uint32_t k = zcode(-zhi); k <= zcode(zhi); ++k) {
          if (k > gap0 && k < gap1) continue;
          {
            double z0, z1;
            unorm_interval(k, 8, z0, z1);
            std::vector<halfspace> h;
            box(h, ex, tx0, tx1);
            box(h, ey, ty0, ty1);
            box(h, ez, z0, z1);
            evaluate_piece(m, 8, {{ac, k, 0}}, std::move(h), a);
          }
        }
      }
      return;
    }
    case method_id::stereographic: {
      // X = x/(1 + z) ∈ s·[2e − 1] for e's rounding interval; X >= c  <=>  x − c·z >= c (1 + z > 0).
      // A bounded cell (|X| <= Xm, |Y| <= Ym) also has z >= (1 − R²)/(1 + R²), R² = Xm² + Ym², which
      // excludes the pole that every plane x − c·z = c passes through.
      const double s = stereographic::scale;
      auto interval = [&](std::uint32_t q, double& lo, double& hi) {
        unorm_interval(q, bits, lo, hi);
        lo = q == 0 ? -inf : lo * s;
        hi = q == mx ? inf : hi * s;
      };
      double X0, X1;
      interval(i, X0, X1);
      for (std::uint32_t j = 0; j <= mx; ++j) {
        if (skipped(m, bits, i, j)) continue;
        double Y0, Y1;
        interval(j, Y0, Y1);
        std::vector<halfspace> h;
        if (std::isfinite(X0)) h.push_back({{1, 0, -X0}, X0});
        if (std::isfinite(X1)) h.push_back({{-1, 0, X1}, -X1});
        if (std::isfinite(Y0)) h.push_back({{0, 1, -Y0}, Y0});
        if (std::isfinite(Y1)) h.push_back({{0, -1, Y1}, -Y1});
        if (std::isfinite(X0) && std::isfinite(X1) && std::isfinite(Y0) && std::isfinite(Y1)) {
          const double r2 = max_sq(X0, X1) + max_sq(Y0, Y1);
          h.push_back({ez, (1 - r2) / (1 + r2)});
        }
        evaluate_piece(m, bits, {{i, j, 0}}, std::move(h), a);
      }
      return;
    }
    case method_id::octahedral:
    case method_id::octahedral_precise:
    case method_id::octahedral_snorm: {
      // Within the octant (sx, sy, sz), s = σ·n with σ = (sx, sy, sz), and u = α_u·n / s with
      // α_u = (1, 0, 0) (sz = +1) or (1, 0, −sx) (sz = −1, folded: u = sx(|x| + |z|)/s); likewise v.
      // u >= u0  <=>  (α_u − u0·σ)·n >= 0.
      const bool snorm = m.id == method_id::octahedral_snorm;
      const std::uint32_t count = snorm ? (std::uint32_t{1} << bits) : mx + 1;
      auto interval = [&](std::uint32_t q, double& lo, double& hi) {
        if (snorm) {
          const double sm = snorm_max(bits);
          const auto qs = static_cast<std::int32_t>(q) - (std::int32_t{1} << (bits - 1));
          if (qs < -snorm_max(bits)) { lo = 1; hi = -1; return; }  // −2^(b−1): never produced
          lo = (qs - 0.5) / sm;
          hi = (qs + 0.5) / sm;
        } else {
          unorm_interval(q, bits, lo, hi);
        }
      };
      double u0, u1;
      interval(i, u0, u1);
      if (u0 > u1) return;
      for (std::uint32_t j = 0; j < count; ++j) {
        if (skipped(m, bits, i, j)) continue;
        double v0, v1;
        interval(j, v0, v1);
        if (v0 > v1) continue;
        for (int sz = -1; sz <= 1; sz += 2)
          for (int sy = -1; sy <= 1; sy += 2)
            for (int sx = -1; sx <= 1; sx += 2) {
              if ((sx > 0 ? u1 < 0 : u0 > 0) || (sy > 0 ? v1 < 0 : v0 > 0)) continue;  // u has the sign of x
              const vec3 sigma{double(sx), double(sy), double(sz)};
              const vec3 alpha_u = sz > 0 ? vec3{1, 0, 0} : vec3{1, 0, -double(sx)};
              const vec3 alpha_v = sz > 0 ? vec3{0, 1, 0} : vec3{0, 1, -double(sy)};
              std::vector<halfspace> h{{sx * ex, 0}, {sy * ey, 0}, {sz * ez, 0},
                                       {alpha_u - u0 * sigma, 0}, {u1 * sigma - alpha_u, 0},
                                       {alpha_v - v0 * sigma, 0}, {v1 * sigma - alpha_v, 0}};
              const method& dm = m.id == method_id::octahedral_precise ? method_of(method_id::octahedral) : m;
              evaluate_piece(dm, bits, {{i, j, 0}}, std::move(h), a);
            }
      }
      return;
    }
    default:
      return;
  }
}

// Lambert family: branch and bound on the images of the square's edges (cells.hpp).
vec3 lambert_L(double ax, double ay) {
  const double r2 = ax * ax + ay * ay, g = std::sqrt(std::max(0.0, 1 - 4 * r2));
  return {4 * ax * g, 4 * ay * g, 1 - 8 * r2};
}

struct edge_job {
  double c;   // the fixed coordinate
  bool on_x;  // the edge is x = c (t runs over y) or y = c
  double t0, t1;
};

// Largest angle from d over L(edge ∩ disk), to within tol; `best` is the running global lower bound
// (pruning), returns {value found, certified upper bound over this edge}.
std::pair<double, double> edge_sup(vec3 d, const edge_job& e, double tol, double best, vec3& at) {
  const double w2 = 0.25 - e.c * e.c;
  if (w2 < 0) return {-1, -1};
  const double w = std::sqrt(w2), t0 = std::max(e.t0, -w), t1 = std::min(e.t1, w);
  if (t0 > t1) return {-1, -1};
  const vec3 south{0, 0, -1};
  const double to_south = angle(d, south);
  auto point = [&](double t) { return e.on_x ? lambert_L(e.c, t) : lambert_L(t, e.c); };
  auto g = [&](double t) { return angle(d, point(t)); };
  double found = -1, upper = -1;
  auto note = [&](double t, double v) {
    if (v > found) { found = v; at = point(t); }
  };
  struct iv { double a, b, ga, gb; int depth; };
  std::vector<iv> stack;
  constexpr int pieces = 8;
  double prev_t = t0, prev_g = g(t0);
  note(t0, prev_g);
  for (int k = 1; k <= pieces; ++k) {
    const double t = t0 + (t1 - t0) * k / pieces, gt = g(t);
    note(t, gt);
    stack.push_back({prev_t, t, prev_g, gt, 0});
    prev_t = t;
    prev_g = gt;
  }
  while (!stack.empty()) {
    const iv s = stack.back();
    stack.pop_back();
    const double h = s.b - s.a;
    const double r2max = e.c * e.c + std::max(s.a * s.a, s.b * s.b);
    const double r2min = e.c * e.c + (s.a <= 0 && s.b >= 0 ? 0 : std::min(s.a * s.a, s.b * s.b));
    const double k = 1 - 4 * r2max > 0 ? 4 / std::sqrt(1 - 4 * r2max) : inf;
    const double lip = (s.ga + s.gb) / 2 + k * h / 2;
    const double cap = to_south + (pi - 2 * std::asin(std::min(1.0, 2 * std::sqrt(r2min))));
    const double ub = std::min(lip, cap);
    const double target = std::max(best, found);
    if (ub <= target + tol || s.depth > 80 || h == 0) {
      upper = std::max(upper, std::max(ub, std::max(s.ga, s.gb)));
      continue;
    }
    const double mid = s.a + h / 2, gm = g(mid);
    note(mid, gm);
    stack.push_back({s.a, mid, s.ga, gm, s.depth + 1});
    stack.push_back({mid, s.b, gm, s.gb, s.depth + 1});
  }
  // Pruned intervals were bounded by best + tol when best came from another cell: the upper bound
  // reported for this edge is then at most max(best, found) + tol.
  return {found, upper};
}

void lambert_pieces(const method& m, int bits, std::uint32_t i, double tol, double global_lb, acc& a) {
  const std::uint32_t mx = unorm_max(bits);
  const double ax0 = (i - 0.5) / mx - 0.5, ax1 = (i + 0.5) / mx - 0.5;
  for (std::uint32_t j = 0; j <= mx; ++j) {
    if (skipped(m, bits, i, j)) continue;
    const double ay0 = (j - 0.5) / mx - 0.5, ay1 = (j + 0.5) / mx - 0.5;
    const double r2min = min_sq(ax0, ax1) + min_sq(ay0, ay1), r2max = max_sq(ax0, ax1) + max_sq(ay0, ay1);
    if (r2min >= 0.25) continue;  // the square misses the open disk: no unit n encodes to it
    const code q{{i, j, 0}};
    ++a.w.cells;
    const vec3 dv = m.decode(q, bits);
    if (!finite(dv) || dot(dv, dv) == 0) {
      // A point of the square inside the disk: the square's point nearest the centre, moved 1% of
      // the way to the square's centre when that stays inside.
      const double cx = std::clamp(0.0, ax0, ax1), cy = std::clamp(0.0, ay0, ay1);
      const double px = cx + 0.01 * ((ax0 + ax1) / 2 - cx), py = cy + 0.01 * ((ay0 + ay1) / 2 - cy);
      a.add_nonfinite(q, px * px + py * py < 0.25 ? lambert_L(px, py) : lambert_L(cx, cy));
      continue;
    }
    const vec3 d = normalize(dv);
    const edge_job edges[4] = {{ax0, true, ay0, ay1}, {ax1, true, ay0, ay1}, {ay0, false, ax0, ax1}, {ay1, false, ax0, ax1}};
    for (const auto& e : edges) {
      vec3 at{};
      const auto [found, ub] = edge_sup(d, e, tol, std::max(global_lb, a.sup_rad), at);
      if (found >= 0) a.add(q, d, found, at, ub);
    }
    if (r2max >= 0.25) {  // the square meets the circle: the south pole is in the cell's closure
      const vec3 s{0, 0, -1};
      a.add(q, d, angle(d, s), s, angle(d, s));
    }
  }
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
      consider(vec3{2 * X, 2 * Y, 1 - r2} );
    }
  }
  return best;
}

}  // namespace

worst_case cell_worst_case(const method& m, int bits, unsigned threads, double tolerance_rad, bool use_symmetry, code_window win) {
  check_bits(m, bits);
  const std::uint32_t first = m.id == method_id::spherical_lut ? spherical_lut::size
                              : m.id == method_id::octahedral_snorm ? (std::uint32_t{1} << bits)
                                                                     : unorm_max(bits) + 1;
  auto run = [&](double global_lb, double tol) {
    const unsigned t = std::max(1U, threads);
    std::vector<acc> parts(t);
    std::vector<std::jthread> pool;
    for (unsigned w = 0; w < t; ++w)
      pool.emplace_back([&, w] {
        reduce = use_symmetry && symmetric(m.id);
        window = win;
        for (std::uint32_t i = win.i0 / t * t + w; i < first && i <= win.i1; i += t) {
          if (i < win.i0) continue;
          if (lambert_family(m.id)) lambert_pieces(m, bits, i, tol, global_lb, parts[w]);
          else planar_pieces(m, bits, i, parts[w]);
        }
      });
    pool.clear();
    acc all;
    for (const auto& p : parts) all.merge(p);
    return all;
  };
  acc all = run(0, lambert_family(m.id) ? 1e-4 : tolerance_rad);
  if (lambert_family(m.id)) all = run(all.sup_rad, tolerance_rad);  // second pass: prune against the first's best
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
