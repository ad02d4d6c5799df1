// two_pass_triangle/triangle_certify.hpp — a certified upper bound on the continuous relaxation of
// two-pass.max-s.interpolated's error bound (triangle_relaxation.hpp), over a rectangle of geometries
// at once, by a dual with sign constraints checked in exact integers.
//
// Folded coordinates (triangle_relaxation.hpp: σ_c = side·sign n_c, w_c = |n_c|), levels. The reference
// pixel r = (0, 0) is the least vertex x and the least vertex y; vertices X_k (k = 0, 1, 2), the pixel p
// a vertex (the family reduction below, leaving F1, F2, F3 (= F2 mirrored, x <-> y maps the
// relaxation onto itself), F4, A1, A2). The family reduction, in four steps:
//  1. Translation: a lattice case's least vertex coordinates lie in (r − 1, r]; moving the triangle
//     and p by less than one pixel so that they equal r keeps the barycentric coordinates and the
//     steps and does not shorten a or b (p's offsets from r). So r = (0, 0) is the least vertex x and
//     the least vertex y, and every vertex coordinate is below 2048.
//  2. Scaling: diag(λ, μ) about r with λ, μ >= 1 keeps P_c(p) (barycentric coordinates are affine
//     invariants), divides the x steps by λ and the y steps by μ, and multiplies a by λ and b by μ;
//     λ·a·min(1, t/λ) = min(λ·a, a·t) >= a·min(1, t) for t >= 0, so the objective never falls. So the
//     bounding box is [0, A]² (A = 2048; relaxation_classes.hpp's survey_box explains why 2047 suffices).
//  3. The pixel: for fixed vertices and lights the objective is linear in p (P_c(p) is, and so are
//     p_x·clamp(t_x) and p_y·clamp(t_y), t depending on the vertices and lights only), so its maximum
//     over the closed triangle is at a vertex.
//  4. Three vertices attain the box's four extremes, so one of them is a corner of it. One corner
//     vertex: the other two lie on the two edges the corner does not touch (F1: corner (A, A), F2:
//     (A, 0), F3: (0, A), the mirror image of F2, F4: (0, 0)); two corner vertices, opposite (A1, A2;
//     the third anywhere) or adjacent (a case of the others).
// The plane P(x) = Q + G·x through the vertex lights ℓ_k = Q + G·X_k, |ℓ_k| <= s;
// t_{c,ax} = −128·G_{c,ax} units per pixel. The objective (relaxation_value) is
//   Σ_c w_c·(P_c(p) + p_x·clamp(t_{c,x}, 0, 1)/128 + p_y·clamp(t_{c,y}, 0, 1)/128).
// A pattern π (bit 2c + ax set: (c, ax) charged) is the region t_{c,ax} >= 0 on charged axes, <= 0 on
// the others; the regions cover every point, and on π's region the objective is
//   f_π = w·P(p) + Σ_{charged} w_c·p_ax·min(1, t_{c,ax})/128,
// concave in the lights. Dual: for y_0, y_1, y_2 in R³ with Σ_k y_k = w, m_{c,ax} = Σ_k y_{k,c}·X_{k,ax}
// and κ_{c,ax} = w_c·p_ax − m_{c,ax} = Σ_{k ≠ p} y_{k,c}·(p_ax − X_{k,ax}),
//   Σ_k y_k·ℓ_k = w·Q + Σ_{c,ax} m_{c,ax}·G_{c,ax},  so  f_π = Σ_k y_k·ℓ_k + Σ_{c,ax} [κ_{c,ax}·G_{c,ax} + lag].
// Per axis (G = −t/128): charged, t >= 0, κ >= 0: (−κ·t + w_c·p_ax·min(1, t))/128 is m·t/128 on [0, 1]
// and falls beyond, so it is <= max(0, m)/128; uncharged, t <= 0, κ <= 0: −κ·t/128 <= 0. With
// Cauchy–Schwarz on each y_k·ℓ_k:
//   f_π <= s·Σ_k |y_k| + Σ_{charged} max(0, m_{c,ax})/128
// whenever κ >= 0 on the charged axes and κ <= 0 on the uncharged ones. This is the Lagrangian dual
// of max f_π over the balls and the sign constraints exactly (write min(1, t) = min over θ in [0, 1] of
// θ + (1 − θ)·t, multipliers λ, μ >= 0 for −t <= 0 and t <= 0: the functional's coefficient of G is
// m = w_c·p_ax·θ − 128λ on a charged axis, w_c·p_ax + 128μ on an uncharged one, and the least θ is
// max(0, m)/(w_c·p_ax)), and Slater holds for a nondegenerate triangle (small lights with strict
// signs), so at one geometry the least bound over y is the pattern's supremum. The θ-dual of
// tools/proofs_triangle relaxation is y_{k,c} = w_c·β_k(z_c) with z_c on [0, p] per charged axis and z_c = p on the
// uncharged ones; here z_c may go past p on uncharged axes (κ <= 0), which is what the θ-dual misses.
// y_p = w, y_k = 0 (k ≠ p) is feasible for every geometry (κ = 0): bound (ii) with every axis lagged.
// For a FIXED y the bound is s·Σ|y_k| plus Σ max(0, affine function of the vertex and pixel
// coordinates): convex in the geometry, so over a rectangle of a family's (u, v) (every coordinate of
// every vertex is 0, A, u or v) it is largest at the four corners; κ is affine in the geometry, so
// its signs hold on the rectangle iff they hold at the corners. Degenerate triangles (inside a
// rectangle) need nothing: at every nondegenerate one the bound holds, and there is no 1/det.
// A channel with w_c = 0 gets y_{·,c} = 0: κ = m = 0, so its per-axis terms vanish for every t, and
// the patterns that differ only on it are one (patterns() lists one of them).
//
// Rigour: y is found in doubles (any y gives a bound), then rounded to the grid y·2^dual_bits in
// integers with y_p = w − Σ_{k≠p} y_k exactly; vertex coordinates are integers in 2^-coord_bits pixel
// (the rectangles are dyadic). κ and m are then exact (__int128), each |y_k| is bounded by the
// ceiling of an integer square root, and the bound is compared with the threshold exactly:
//   128·2^(dual_bits+coord_bits)·(s·Σ|y_k| + max_corner Σ max(0, m)/128) < threshold128·2^(dual_bits+coord_bits),
// threshold128 = 128·relaxation_threshold = wrap_threshold_units − truncation_units − |n|_1 (an
// integer). No floating-point value enters the verdict.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace gsdot3::proofs::two_pass::triangle::certify {

inline constexpr int coord_bits = 20;  // vertex coordinates in 2^-20 pixel
inline constexpr int dual_bits = 24;   // y in 2^-24
inline constexpr std::int64_t coord_one = std::int64_t{1} << coord_bits;

// One class: the folded weights w = |n| (any order), s, and 128·relaxation_threshold.
struct problem {
  std::array<int, 3> w;
  int s;
  std::int64_t threshold128;
};

// The vertices of one geometry, 2^-coord_bits pixel, r = (0, 0).
using vertices = std::array<std::array<std::int64_t, 2>, 3>;
// A rectangle of geometries given by its corner geometries (4; or 1 for a single geometry), and
// which vertex is the pixel.
struct corners {
  std::vector<vertices> at;
  int p = 0;
};

// The five families of the reduction with box A (pixels): F1 (0, u), (v, 0), (A, A); F2 (0, u),
// (A, 0), (v, A); F4 (0, 0), (A, u), (v, A); A1 (0, 0), (A, A), (u, v); A2 (0, A), (A, 0), (u, v).
inline constexpr int family_count = 5;
inline constexpr const char* family_names[family_count] = {"F1", "F2", "F4", "A1", "A2"};
vertices family_member(int family, std::int64_t u, std::int64_t v, std::int64_t box);
// The rectangle [u0, u1] × [v0, v1] (2^-coord_bits pixel) of a family, p = vertex p.
corners family_cell(int family, int p, std::int64_t u0, std::int64_t u1, std::int64_t v0, std::int64_t v1,
                    std::int64_t box);

// y_{k,c}, doubles (the search) and on the integer grid (the certificate).
using dual_real = std::array<std::array<double, 3>, 3>;
using dual_grid = std::array<std::array<std::int64_t, 3>, 3>;

// The search: a y for pattern π that makes the bound small over every corner (a log-barrier Newton
// method on a smoothed bound, in doubles; any y it returns is only a candidate). warm: a y feasible
// for a superset of the corners (the parent rectangle's), or null.
dual_real search_dual(const problem& pr, const corners& g, unsigned pattern, const dual_real* warm);

// y rounded to the grid, with Σ_k y_k = w exactly and y_{·,c} = 0 where w_c = 0.
dual_grid to_grid(const problem& pr, const dual_real& y, int p);

// The exact check of one y on the corners: feasible (the sign conditions at every corner), the
// bound scaled by 128·2^(dual_bits+coord_bits) (valid only if feasible) and whether it is below the
// threshold; `levels` is that bound in levels·|n| (long double, for reports only).
struct check {
  bool feasible = false, below = false;
  long double levels = 0;
};
check check_dual(const problem& pr, const corners& g, unsigned pattern, const dual_grid& y);

// The patterns that need a certificate: those charged only on channels with w_c > 0.
std::vector<unsigned> patterns(const problem& pr);

// An attained value of the relaxation at geometry v (pixels) with p = vertex p: the lights
// s·y_k/|y_k| of a dual y, through relaxation_value (a lower bound on the supremum).
double attained(const problem& pr, const std::array<std::array<double, 2>, 3>& v, int p, const dual_real& y);

// The branch and bound of one class over every family, p and pattern: a rectangle closes when
// check_dual of y_p = w (no search), or else of the searched y (warm-started from the parent's), is
// feasible and below; otherwise it splits in four, down to
// min_cell (2^-coord_bits pixel), below which it stays open (with the attained value at its centre).
// It stops at the first open rectangle whose attained value exceeds the threshold (the relaxation
// admits a wrap there: no dual can close it) and after max_cells rectangles (counted open).
struct open_cell {
  int family, p;
  unsigned pattern;
  std::int64_t u0, u1, v0, v1;
  long double bound;
  double attained;
  dual_real y;  // the rectangle's dual: its lights s·y_k/|y_k| attain `attained` at the centre
};
struct outcome {
  std::int64_t cells = 0, closed = 0;  // rectangles examined, closed
  std::vector<open_cell> open;         // what could not be closed (at most max_open kept)
  std::int64_t open_count = 0;
  long double worst_closed = -1e30L;  // the largest certified bound among the closed rectangles
  double best_attained = -1e30;       // over the open rectangles' centres
  bool exceeds = false;               // stopped at an open rectangle whose attained value is above the threshold
  open_cell witness{};                // that rectangle (the relaxation admits a wrap at its centre)
};
// One closed rectangle and the grid dual that closed it: what a stored certificate would hold.
struct closed_cell {
  int family, p;
  unsigned pattern;
  std::int64_t u0, u1, v0, v1;
  dual_grid y;
};
outcome certify_class(const problem& pr, std::int64_t box, std::int64_t min_cell, std::int64_t max_cells,
                      std::size_t max_open = 8, std::vector<closed_cell>* record = nullptr);

}  // namespace gsdot3::proofs::two_pass::triangle::certify
