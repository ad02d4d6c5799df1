// two_pass_triangle/two_pass_triangle.hpp — section 3.5's interpolated light vectors on whole triangles, as the
// GS model sets them up (gs::gouraud_triangle), and the bound on how far a pixel's light can leave
// the vertex lights' sphere.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gs_arith/options.hpp"
#include "gs_arith/texture_function.hpp"
#include "proofs/domains.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::two_pass::triangle {

// The GS's largest drawing area (SCISSOR / FRAME up to 2048 × 2048): vertices in 12.4 window
// coordinates 0 .. 2047·16 (the pixel centres the triangle can cover are 0 .. 2047).
inline constexpr int window_pixels = 2048;
// XYOFFSET as the pipeline sets it (pipeline/prepare.hpp xy_offset_pixels): window pixel 0 is
// primitive coordinate 2048.0, the middle of the GS's 4096² space.
inline constexpr int xy_offset_pixels = 2048;

// One case of the domain: the packed normal (iX, iY), three vertex lights of L_s, the triangle's
// vertices in 12.4 window coordinates, and one pixel it covers.
struct triangle_case {
  int s, iX, iY;
  std::array<ivec3, 3> light;
  std::array<int, 6> xy16;  // x0, y0, x1, y1, x2, y2
  int px, py;
};

// The wrapping cases of certificates.csv (two_pass_triangle/certificates.hpp; README.md says how
// each kind wraps and how to re-derive it). tests/proofs replays each through the pipeline's
// rasteriser (the pixel is covered) and gs::pixel_pipeline.
std::span<const triangle_case> certificates();  // certificates.csv (two_pass_triangle/certificates.hpp)

// The vertex colour of a packed light: 128 + l per channel, vertex alpha 0x80.
gs::rgba8 light_colour(const ivec3& l) noexcept;

// The pixel's light colour: the plane of gs::gouraud_triangle with the reference pixel the
// pipeline uses (pipeline/band_renderer.hpp attributes(): the top-left pixel of the triangle's
// bounding box, ceil of the least x and y), read at the pixel under the set-up in force
// (gs::gouraud_colour: gouraud_at for plane_steps, gouraud_exact_at for per_pixel). Whether the
// pixel is covered is the rasteriser's business: the tests replay every certificate through it.
gs::fragment_colour pixel_light(const triangle_case& c,
                                gs::gouraud_setup setup = gs::gouraud_setup::plane_steps) noexcept;

// The error bound. Write P_c for the exact plane of channel c (8.7 units) through the three vertex
// values, r for the reference pixel and g_c for the exact gradient. gouraud_triangle truncates the
// start value P_c(r) and the two steps g_c toward zero, each by less than one unit, and gouraud_at
// adds a·dx + b·dy exactly at the pixel p = r + (a, b), so L_c(p) = P_c(p) + E_c with
//   E_c = (start − P_c(r)) − a·f_x − b·f_y,   f = g_c − steps: |f| < min(1, |g_c|), sign f = sign g_c,
// and 0 <= a, b <= W − 1 (W = window_pixels: a covered pixel centre is >= the least vertex
// coordinate, hence >= r, and every coordinate is <= W − 1). Fix the wrap side's signs σ_c
// (σ_c = sign n_c for the top wrap, −sign n_c for the bottom) and call channel c aligned on an axis if
// σ_c·g_c < 0 there (below, n·v stands for Σ |n_c|·σ_c·v_c: n·v for the top, −n·v for the
// bottom); only aligned axes raise σ_c·E_c, so (|f| < 1, |start error| < 1)
//   σ_c·E_c < W            for a channel aligned on at most one axis,
//   σ_c·E_c < 1 + a + b    for a channel aligned on both (<= 2W − 1).
// (i) If every channel with n_c != 0 is aligned on both axes, one point w of the closed triangle,
//   chosen from the geometry alone, gives σ_c·L_c(p) < σ_c·P_c(w) + W for every channel. With X the
//   vertex of least x, X = r + (ξ, b_X), −1 < ξ <= 0, and Y the vertex of least y, Y = r + (a_Y, η),
//   −1 < η <= 0: if some w = X + t·(Y − X), t in [0, 1], is <= p in both coordinates, then σ_c·P_c
//   falls along both axes, so σ_c·P_c(w) >= σ_c·P_c(p) + |f_x|·(p − w)_x + |f_y|·(p − w)_y and
//   σ_c·L_c(p) < σ_c·P_c(w) + 1 + |f_x|·(w − r)_x + |f_y|·(w − r)_y, where (w − r)_x <= t·a_Y and
//   (w − r)_y <= (1 − t)·b_X, so the lag is < max(a_Y, b_X, 0) + 1 <= W. If no such w exists (X and Y
//   are not <= p: b_X > b and a_Y > a; the segment meets x <= p_x for t <= t1 = (a − ξ)/(a_Y − ξ)
//   and y <= p_y for t >= t0 = (b_X − b)/(b_X − η) > t1), then a <= t1·a_Y and b <= (1 − t0)·b_X
//   < (1 − t1)·b_X, so a + b < max(a_Y, b_X) <= W − 1 and w = p serves. Hence n·L(p) < n·P(w) + m·W.
// (ii) Otherwise some channel with n_c != 0 is aligned on at most one axis, and
//   n·L(p) < n·P(p) + m·W + (W − 1)·(m − μ),   m = |n|_1, μ = the least nonzero |n_c|.
// In both cases the plane point (w or p) lies in the closed triangle, so P there is a convex
// combination of the vertex values, inside the ball |l| <= s around 128 per channel. The clamp to
// 0 .. 0x7FFF only moves each L_c towards [0, 32640], where every P_c lies (each bound above holds
// channel by channel). With gouraud_fraction = truncate_to_8 the multiply sees 128·floor(L_c/128),
// which is <= L_c and, L_c being a whole number of 8.7 units, >= L_c − 127: it only lowers σ_c·L_c
// where σ_c = +1 and raises it by at most 127 units where σ_c = −1, so the wrap side adds
// truncation_units = 127·Σ_{σ_c < 0} |n_c| (n_c < 0 at
// the top, n_c > 0 at the bottom). tests/proofs/triangle_test.cpp checks (i) and (ii) against the
// exact rational plane on every lattice triangle of a small window and on random full-size ones.
// With λ_c = M_c/128 − 128 for the light M_c the multiply sees (L_c, or 128·floor(L_c/128) under
// truncate_to_8) and the floors of the two passes (q_c = floor or ceil of n_c·λ_c/128,
// two_pass::wrap_search), value <= n·λ/128 + #{n_c < 0}·g + e and value >= n·λ/128 − #{n_c > 0}·g + e
// with g = 16383/16384: n_c·λ_c/128 = n_c·(M_c − 16384)/16384 and n_c·M_c is a whole number, so a
// floor or a ceiling moves it by at most 16383/16384; under truncate_to_8 n_c·M_c is a multiple of 128
// and g = 127/128 (floor_slack_units; tests/proofs checks both ends on the model's value). A zero
// component's products are 0 whatever its light (tests/proofs checks it on every Appendix 2 normal
// with one). So a normal cannot wrap at s when  (reach + T_top)/16384 + #{n_c < 0}·g + e < 128  and
// −(reach + T_bottom)/16384 − #{n_c > 0}·g + e > −129 (T = truncation_units of that side), with
// reach = |n|·s·128 + G, G = gain_units, by (i) and
// (ii) (evaluated exactly in integers: |n| is taken as the ceiling of the square root; (i) as ball_reach_units), or the
// tighter reach_units of (iii) below, which bound_safe_s uses where (ii) alone does not settle s.
// Under gouraud_setup::per_pixel the light is the exact plane at p truncated toward zero from vertex
// 0's value, so |E_c| < 1 unit on every channel whatever the gradients, with P(p) in the ball: no
// case split, n·L(p) − n·centre < R·|n| + m (ball_reach_units with W = 1; lag_window is the W of (ii)).
// Under per_pixel_floor L_c = floor(P_c(p)), so −1 < E_c <= 0: the same W = 1.
// The other set-ups of a source are bounded the same way, with their own W, the largest |E_c| (in units):
// - per_pixel_level: L_c = 128·floor((P_c(p) + 1/2)/128), so −127.5 < E_c <= 1/2: W = 128. L_c is a multiple of
//   128, so the multiply's floors have the truncate_to_8 slack (floor_slack_units 128) and truncate_to_8
//   changes nothing (truncation_units 0).
// - pcsx2_rows_4 / _8 (gs::gouraud_rows_units): p = left + k on its row, left = the row's first pixel
//   (ceil of the left edge: in the closed triangle, as p). With g the exact x gradient, n the vectors
//   after the first and m = k − n·lanes, L_c = trunc(P_c(left)) + trunc(g·m) + n·trunc(lanes·g) when
//   nothing saturates, and P_c(left) + g·k = P_c(p): E_c = −(three truncations, one of them n times),
//   |E_c| < 2 + n <= 2 + floor((2047 + lanes − 1)/lanes): W = 514 (4 lanes), 258 (8 lanes). The clamp
//   at 0 after each step only lifts a negative running value, and (Lindley) never above P_c(p): still
//   within W. Saturation: |P_c(p) − P_c(left)| = |g|·k <= 2s·128 < 32767, so n = 0 never saturates, and
//   n >= 2 needs k >= lanes + 1, where |lanes·g| < 32767 too; at n = 1 (m = k − lanes < 0, opposite
//   sign to the step) a saturated step (and offset) gives, by cases, a value between trunc(P_c(left))
//   − 1 and P_c(p) + 1, exact in 16 bits (paddw wraps, but the true sum lies in range). Per channel
//   that is a point of the segment from P(left) to P(p), both in the ball, ±3 units, but a different
//   point per channel: the light is only in the cube |λ_c| <= R + 3 around the centre (saturation_units,
//   n·L(p) − n·centre < |n|_1·(R + 3)). tests/proofs/triangle_test.cpp checks both statements against
//   the model on random steep and shallow triangles.
constexpr int lag_window(const gs::model_options& o) noexcept {
  switch (o.setup) {
    case gs::gouraud_setup::per_pixel:
    case gs::gouraud_setup::per_pixel_floor: return 1;
    case gs::gouraud_setup::per_pixel_level: return 128;
    case gs::gouraud_setup::pcsx2_rows_4: return 2 + (window_pixels - 1 + 3) / 4;
    case gs::gouraud_setup::pcsx2_rows_8: return 2 + (window_pixels - 1 + 7) / 8;
    case gs::gouraud_setup::plane_steps: break;
  }
  return window_pixels;
}
constexpr bool saturates(const gs::model_options& o) noexcept {
  return o.setup == gs::gouraud_setup::pcsx2_rows_4 || o.setup == gs::gouraud_setup::pcsx2_rows_8;
}
constexpr std::int64_t saturation_units(const std::array<std::int64_t, 3>& n, int s) noexcept {
  return (n[0] + n[1] + n[2]) * (std::int64_t{128} * s + 3);
}
constexpr std::int64_t gain_units(std::int64_t l1, std::int64_t least, int window) noexcept {
  return l1 * window + std::int64_t{window - 1} * (l1 - least);
}
// 16384·(1 − g): by how much, in 1/16384 level, a floor or ceiling of one channel's product stays short
// of moving it a whole level: 1 (keep_fraction: n_c·M_c a whole number) or 128 (truncate_to_8: a
// multiple of 128).
constexpr std::int64_t floor_slack_units(const gs::model_options& o) noexcept {
  if (o.setup == gs::gouraud_setup::per_pixel_level) return 128;
  return o.gouraud == gs::gouraud_fraction::keep_fraction ? 1 : 128;
}
// What reach + truncation_units must stay below on a wrap side (side +1: the top, value >= 128;
// −1: the bottom, value <= −129): 16384·(128 − e) − 16384·g·#{n_c < 0} and 16384·(129 + e) −
// 16384·g·#{n_c > 0}, i.e. 16384·(128 − #{n_c < 0} − e) and 16384·(129 − #{n_c > 0} + e) plus
// floor_slack_units per channel counted.
constexpr std::int64_t wrap_threshold_units(const paper::packed_normal& p, int e, int side,
                                            const gs::model_options& o) noexcept {
  const int neg = (p.iX < 0) + (p.iY < 0) + (p.iZ < 0), pos = (p.iX > 0) + (p.iY > 0) + (p.iZ > 0);
  const int counted = side > 0 ? neg : pos;
  return std::int64_t{16384} * (side > 0 ? 128 - neg - e : 129 - pos + e) + floor_slack_units(o) * counted;
}
constexpr std::int64_t truncation_units(const paper::packed_normal& p, int side, const gs::model_options& o) noexcept {
  if (o.gouraud == gs::gouraud_fraction::keep_fraction || o.setup == gs::gouraud_setup::per_pixel_level) return 0;
  std::int64_t sum = 0;
  for (int n : {p.iX, p.iY, p.iZ})
    if (side * n < 0) sum += n < 0 ? -n : n;
  return 127 * sum;
}
// (iii) The curvature, for case (ii). Write D for the set of channels aligned on both axes. Each
// channel statement holds on its own (the argument of (i) is channel by channel, w is the same for
// all; tests/proofs/triangle_test.cpp checks them one by one): for c in D both σ_c·L_c < σ_c·P_c(p) + 2W − 1 (1 + a + b
// <= 2W − 1) and σ_c·L_c < σ_c·P_c(w) + W, with the same w for every channel of D (w comes from the geometry alone);
// for c not in D, σ_c·L_c < σ_c·P_c(p) + W. P(p) and P(w) both lie in the ball B of radius R = 128·s around the centre
// (16384 per channel). min(x, y) <= θx + (1 − θ)y for θ in [0, 1], so for every θ_c:
//   n·L(p) − n·centre < max over v, u in B of [Σ_{c∉D} |n_c|·σ_c·v_c + Σ_{c∈D} |n_c|·(θ_c·σ_c·v_c + (1 − θ_c)·σ_c·u_c)]
//   + K
//                     = R·(|α| + |β|) + K   (Cauchy–Schwarz, attained),
//   α_c = |n_c| (c ∉ D), θ_c·|n_c| (c ∈ D);  β_c = (1 − θ_c)·|n_c| (c ∈ D), 0 (c ∉ D);
//   K = Σ_{c∉D} |n_c|·W + Σ_{c∈D} |n_c|·(θ_c·(2W − 1) + (1 − θ_c)·W).
// θ = 1 gives (ii) back (with D the worst set), θ = 0 charges D's lag to the second point: a lag
// on both axes needs the plane to fall, so the light at w is that much further along n. The
// bound is taken over every D that leaves out a channel with n_c != 0, each with θ_c = k_c/16
// chosen by a grid in doubles and then evaluated exactly in integers (any θ gives a valid bound,
// so the choice needs no proof). Case (i) is R·|n| + |n|_1·W. tests/proofs/triangle_test.cpp
// checks the maximum over the two points against brute force over the integer points of a small
// ball.
// (iii) for one set D (bit c set: c in D) and ball radius R, n_c >= 0: the least bound over the θ grid,
// rounded up (an integer >= the maximum over v, u in B of the bracket above plus K).
std::int64_t two_point_units(const std::array<std::int64_t, 3>& n, unsigned in_d, std::int64_t radius, int window);
// Case (i)'s bound R·|n| + |n|_1·W, R·|n| rounded up exactly (the ceiling of sqrt(R²·|n|²)).
std::int64_t ball_reach_units(const std::array<std::int64_t, 3>& n, int s, int window);
// The bound on n·L(p) − n·centre (8.7 units, the Gouraud light's; truncation_units come on top), for a
// normal with components |n_c| and s: max of case (i) and (iii) over every D.
std::int64_t reach_units(const std::array<std::int64_t, 3>& n, int s, int window);
// Under the set-ups other than plane_steps, P(p) is a convex combination of the three vertex lights, so
// n·(P(p) − centre) <= 128·light_support: the largest Σ |n_c|·l_c over the light set (packed lights,
// or the ball's cells under tolight = attenuated_T; both are symmetric under negating a channel, so
// this serves both wrap sides). Tighter than the ball's R·|n| where no light points along n.
std::int64_t light_support(const std::array<std::int64_t, 3>& n, std::span<const ivec3> lights) noexcept;
// The cells of the ball |l| <= s (tolight = attenuated_T, domains.hpp attenuated_lights) on which
// light_support takes its largest value for every n >= 0: the first octant's cells with the largest z
// for their x, y ((s + 1)² cells instead of the ball's ~4.2·s³; checked against the whole ball).
std::vector<ivec3> ball_support_lights(int s);
// `lights`: the light set of s, used under the set-ups other than plane_steps (empty: the ball alone).
bool cannot_wrap(const paper::packed_normal& p, int e, int s, const gs::model_options& o,
                 std::span<const ivec3> lights = {}) noexcept;
// The largest s such that no normal can wrap for any s' <= s by that bound (0 if none); `attenuated`:
// the lights of tolight = attenuated_T.
int bound_safe_s(const gs::model_options& o, bool attenuated = false);

// The reference pixel r of pixel_light: the ceiling of the least vertex x and of the least y.
std::array<int, 2> reference_pixel(const std::array<int, 6>& xy16) noexcept;

// The point w of (i), built from the geometry alone (the same w for every channel; --brute-force
// checks (A)–(C) with it at full size, two_pass_triangle/triangle_brute_force.hpp). lag_edge: the edge from
// X, the first vertex of least x, to Y, the first vertex of least y, as offsets from r in 1/16
// pixel: X = 16·r + (ξ, b_X), Y = 16·r + (a_Y, η), −16 < ξ, η <= 0.
struct lag_edge {
  std::size_t X = 0, Y = 0;
  int rx = 0, ry = 0;
  std::int64_t xi = 0, bX = 0, aY = 0, eta = 0;
};
lag_edge lag_edge_of(const std::array<int, 6>& xy16) noexcept;
// w = X + (num/den)·(Y − X) with t = num/den the least of 0, 1, t1 = (16a − ξ)/(a_Y − ξ) and
// t0 = (b_X − 16b)/(b_X − η) in [0, 1] for which w <= p = r + (a, b) in both coordinates; num < 0
// when no point of the edge is <= p, and then w = p (and 16·(a + b) < max(a_Y, b_X)).
// 0 < den <= 2^15 + 16.
struct plane_point {
  std::int64_t num = -1, den = 1;
  bool at_pixel() const noexcept { return num < 0; }
};
plane_point point_w(const lag_edge& e, int px, int py) noexcept;

}  // namespace gsdot3::proofs::two_pass::triangle
