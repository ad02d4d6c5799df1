// The planar methods' cells (argument in cells.hpp): each piece of a cell is sphere ∩ half-spaces, and
// its farthest point from the decoded direction is found in closed form by farthest().
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "normal_encoding/cell_pieces.hpp"
#include "normal_encoding/spherical.hpp"
#include "normal_encoding/spherical_lut.hpp"
#include "normal_encoding/stereographic.hpp"

namespace gsdot3::normal_encoding::cell_pieces {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double pi = std::numbers::pi;
const vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};

void box(std::vector<halfspace>& h, vec3 axis, double lo, double hi) {
  if (lo > -1) h.push_back({axis, lo});
  if (hi < 1) h.push_back({-1.0 * axis, -hi});
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

// The unorm squares of x and y codes (i, j) for every j the filter keeps: cell(j, x0, x1, y0, y1).
template <typename Cell>
void for_each_unorm_square(int bits, std::uint32_t i, const code_filter& f, Cell&& cell) {
  double x0, x1;
  unorm_interval(i, bits, x0, x1);
  for (std::uint32_t j = 0; j <= unorm_max(bits); ++j) {
    if (f.skipped(i, j)) continue;
    double y0, y1;
    unorm_interval(j, bits, y0, y1);
    cell(j, x0, x1, y0, y1);
  }
}

// The z codes k (unorm at `bits`) whose interval meets ±[zlo, zhi], the z range of a column whose
// x² + y² lies in [r2min, r2max] (codes strictly inside (−zlo, zlo) cannot): piece(k, z0, z1).
template <typename Piece>
void for_each_z_code(int bits, double r2min, double r2max, Piece&& piece) {
  const double zlo = std::sqrt(std::max(0.0, 1 - r2max)), zhi = std::sqrt(std::max(0.0, 1 - r2min));
  auto zcode = [&](double z) { return unorm_encode(z * 0.5 + 0.5, bits); };
  const std::uint32_t gap0 = zcode(-zlo), gap1 = zcode(zlo);
  for (std::uint32_t k = zcode(-zhi); k <= zcode(zhi); ++k) {
    if (k > gap0 && k < gap1) continue;
    double z0, z1;
    unorm_interval(k, bits, z0, z1);
    piece(k, z0, z1);
  }
}

// A box x ∈ [x0, x1], y ∈ [y0, y1], z ∈ [z0, z1] (only its sides inside the unit cube).
std::vector<halfspace> box3(double x0, double x1, double y0, double y1, double z0, double z1) {
  std::vector<halfspace> h;
  box(h, ex, x0, x1);
  box(h, ey, y0, y1);
  box(h, ez, z0, z1);
  return h;
}

void xyz_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a) {
  for_each_unorm_square(bits, i, f, [&](std::uint32_t j, double x0, double x1, double y0, double y1) {
    const double r2min = min_sq(x0, x1) + min_sq(y0, y1), r2max = max_sq(x0, x1) + max_sq(y0, y1);
    if (r2min > 1) return;
    for_each_z_code(bits, r2min, r2max, [&](std::uint32_t k, double z0, double z1) {
      evaluate_piece(m, bits, {{i, j, k}}, box3(x0, x1, y0, y1, z0, z1), a);
    });
  });
}

// #1 (xy), #2 (xy_sign: one piece per sign of z) and #8 (view_space: the front hemisphere).
void xy_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a) {
  for_each_unorm_square(bits, i, f, [&](std::uint32_t j, double x0, double x1, double y0, double y1) {
    if (min_sq(x0, x1) + min_sq(y0, y1) > 1) return;
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
  });
}

void spherical_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a) {
  // enc.x = (φ/kPI + 1)/2: φ ∈ kPI·[2(i − 1/2)/M − 1, 2(i + 1/2)/M − 1] ∩ [−π, π]; a wedge.
  double p0, p1;
  unorm_interval(i, bits, p0, p1);
  p0 = std::max(-pi, p0 * spherical::kPI);
  p1 = std::min(pi, p1 * spherical::kPI);
  for (std::uint32_t j = 0; j <= unorm_max(bits); ++j) {
    if (f.skipped(i, j)) continue;
    double z0, z1;
    unorm_interval(j, bits, z0, z1);
    std::vector<halfspace> h{{{-std::sin(p0), std::cos(p0), 0}, 0}, {{std::sin(p1), -std::cos(p1), 0}, 0}};
    box(h, ez, z0, z1);
    evaluate_piece(m, bits, {{i, j, 0}}, std::move(h), a);
  }
}

void spherical_lut_pieces(const method& m, std::uint32_t i, acc& a) {
  // Pieces per atan2-LUT texel (i = texel x here, j = texel y) × z code: boxes.
  const double tx0 = 2.0 * i / spherical_lut::size - 1, tx1 = 2.0 * (i + 1) / spherical_lut::size - 1;
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(spherical_lut::size); ++j) {
    const double ty0 = 2.0 * j / spherical_lut::size - 1, ty1 = 2.0 * (j + 1) / spherical_lut::size - 1;
    const double r2min = min_sq(tx0, tx1) + min_sq(ty0, ty1), r2max = max_sq(tx0, tx1) + max_sq(ty0, ty1);
    if (r2min > 1) continue;
    const std::uint32_t ac = spherical_lut::lut().atan2_lookup[j * spherical_lut::size + i];
    for_each_z_code(8, r2min, r2max, [&](std::uint32_t k, double z0, double z1) {
      evaluate_piece(m, 8, {{ac, k, 0}}, box3(tx0, tx1, ty0, ty1, z0, z1), a);
    });
  }
}

void stereographic_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a) {
  // X = x/(1 + z) ∈ s·[2e − 1] for e's rounding interval; X >= c  <=>  x − c·z >= c (1 + z > 0).
  // A bounded cell (|X| <= Xm, |Y| <= Ym) also has z >= (1 − R²)/(1 + R²), R² = Xm² + Ym², which
  // excludes the pole that every plane x − c·z = c passes through.
  const std::uint32_t mx = unorm_max(bits);
  const double s = stereographic::scale;
  auto interval = [&](std::uint32_t q, double& lo, double& hi) {
    unorm_interval(q, bits, lo, hi);
    lo = q == 0 ? -inf : lo * s;
    hi = q == mx ? inf : hi * s;
  };
  double X0, X1;
  interval(i, X0, X1);
  for (std::uint32_t j = 0; j <= mx; ++j) {
    if (f.skipped(i, j)) continue;
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
}

void octahedral_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a) {
  // Within the octant (sx, sy, sz), s = σ·n with σ = (sx, sy, sz), and u = α_u·n / s with
  // α_u = (1, 0, 0) (sz = +1) or (1, 0, −sx) (sz = −1, folded: u = sx(|x| + |z|)/s); likewise v.
  // u >= u0  <=>  (α_u − u0·σ)·n >= 0.
  const bool snorm = m.id == method_id::octahedral_snorm;
  const std::uint32_t count = snorm ? (std::uint32_t{1} << bits) : unorm_max(bits) + 1;
  auto interval = [&](std::uint32_t q, double& lo, double& hi) {
    if (snorm) {
      const double sm = snorm_max(bits);
      const auto qs = static_cast<std::int32_t>(q) - (std::int32_t{1} << (bits - 1));
      if (qs < -snorm_max(bits)) {
        lo = 1;
        hi = -1;
        return;
      }  // −2^(b−1): never produced
      lo = (qs - 0.5) / sm;
      hi = (qs + 0.5) / sm;
    } else {
      unorm_interval(q, bits, lo, hi);
    }
  };
  double u0, u1;
  interval(i, u0, u1);
  if (u0 > u1) return;
  const method& dm = m.id == method_id::octahedral_precise ? method_of(method_id::octahedral) : m;
  for (std::uint32_t j = 0; j < count; ++j) {
    if (f.skipped(i, j)) continue;
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
          std::vector<halfspace> h{{sx * ex, 0},
                                   {sy * ey, 0},
                                   {sz * ez, 0},
                                   {alpha_u - u0 * sigma, 0},
                                   {u1 * sigma - alpha_u, 0},
                                   {alpha_v - v0 * sigma, 0},
                                   {v1 * sigma - alpha_v, 0}};
          evaluate_piece(dm, bits, {{i, j, 0}}, std::move(h), a);
        }
  }
}

}  // namespace

void planar_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a) {
  switch (m.id) {
    case method_id::xyz: return xyz_pieces(m, bits, i, f, a);
    case method_id::xy:
    case method_id::xy_sign:
    case method_id::view_space: return xy_pieces(m, bits, i, f, a);
    case method_id::spherical: return spherical_pieces(m, bits, i, f, a);
    case method_id::spherical_lut: return spherical_lut_pieces(m, i, a);
    case method_id::stereographic: return stereographic_pieces(m, bits, i, f, a);
    case method_id::octahedral:
    case method_id::octahedral_precise:
    case method_id::octahedral_snorm: return octahedral_pieces(m, bits, i, f, a);
    default: return;
  }
}

}  // namespace gsdot3::normal_encoding::cell_pieces
