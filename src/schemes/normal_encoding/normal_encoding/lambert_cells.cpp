// The Lambert family's cells (#4, #5, #6; argument in cells.hpp): a cell is L(square ∩ disk), and the
// angle over the images of the square's edges is maximised by branch and bound.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "normal_encoding/cell_pieces.hpp"

namespace gsdot3::normal_encoding::cell_pieces {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double pi = std::numbers::pi;

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
    if (v > found) {
      found = v;
      at = point(t);
    }
  };
  struct iv {
    double a, b, ga, gb;
    int depth;
  };
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

}  // namespace

void lambert_pieces(const method& m, int bits, std::uint32_t i, double tol, double global_lb, const code_filter& f,
                    acc& a) {
  const std::uint32_t mx = unorm_max(bits);
  const double ax0 = (i - 0.5) / mx - 0.5, ax1 = (i + 0.5) / mx - 0.5;
  for (std::uint32_t j = 0; j <= mx; ++j) {
    if (f.skipped(i, j)) continue;
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
    const edge_job edges[4] = {
        {ax0, true, ay0, ay1}, {ax1, true, ay0, ay1}, {ay0, false, ax0, ax1}, {ay1, false, ax0, ax1}};
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

}  // namespace gsdot3::normal_encoding::cell_pieces
