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

// Wrapping cases, with the tools/proofs_triangle command that finds each (tools/README.md; the
// programs cited at a commit were dropped from the tree, `git show COMMIT:PATH` has them).
// s = 100 and 122..125: found by `proofs_triangle search S` (its construction: a
// right triangle whose x step fractions are near 1 and point along the normal, the pixel next to its
// top-right vertex, ~2030 pixels from the plane's reference pixel), one per s it was run for
// (s = 100 twice: `search 100` and `search 100 --truncate-to-8`). s = 98, one per gouraud_fraction:
// found by the local search bench/proofs_triangle_anneal as it was at commit 2d5fcd4 (`98 1 300000` and
// `98 truncate_to_8 14 1000000`; its later two-axis start changes those runs), again one axis of
// lag (~2046 pixels).
// s = 91 (`proofs_triangle two-axis 91`, with and without --truncate-to-8) and s = 90
// (bench/proofs_triangle_anneal at commit f646b24, `90 3 300000` and `90 truncate_to_8 3 300000`,
// started from the s = 91 row; at 9f63566 `90 3 300000` ends at 127): the pixel lags along both
// axes, 15 levels per axis, on the two largest channels, the third keeping the plane level along the
// normal (case (ii) of the bound below).
// s = 89, one per gouraud_fraction: `proofs_triangle corner 89` and `corner 89 --truncate-to-8` (300
// candidates each): the corner model's lattice candidates (X, Y ~2046 pixels from Z on either axis,
// u = v + 16 levels on two channels), then the sub-pixel geometry that keeps both of their steps
// just below one unit per pixel and a steepest ascent: the pixel keeps 31.9 levels of lag (~2046
// units per axis) on those two channels; the third loses most of a level on one axis (X and Y
// differ by 15 there, which no geometry with both lag steps below 1 makes lossless). The same tool
// reaches 127 at s = 88 (`88`, 300 candidates) and 126 under truncate_to_8 (`88 --truncate-to-8`),
// where its lattice candidates' predicted value (the truncated light is a flat one) tops out at 127.
// s = 86, one per gouraud_fraction: `proofs_triangle steep 86 -79 -57 1 0 -20 -51 65 7 23
// 880 940` and `steep 86 --truncate-to-8 -79 -57 1 0 -22 -50 65 7 23 860 900 6`, its start
// values from bench/proofs_triangle_relaxation at commit 9f63566 (`57 79 83 86 300000 7`): X = (0, ~870), far above
// the pixel's row. The two lag channels fall along both axes with steps just below one unit per
// pixel (31.9 levels of lag, as at s = 89), and the third channel lags one axis too: its x step is
// just below one unit and its y step an integer K = 7 (a steep rise towards Z's row that truncation
// keeps), which lets P_c(pixel) on that channel sit ~50 levels from X's light; the third vertex Y,
// ~7·880/128 levels away on that channel, pays for it. Case (ii) of the bound charges that channel
// W over P_c(p) with nothing but the ball tying P(p) to the vertex lights, which is where the bound
// and these certificates still differ (the relaxation's best at s = 86 for n = (−79, −57, 83) is
// 16297 against the wrap threshold 16000 in n·level units; see the closing notes of issue 13).
// s = 85, one per gouraud_fraction: the same construction, `proofs_triangle steep 85 -89 -65 1 0 -17
// -59 59 4 26 750 775 6` (188 cases) and `steep 85 --truncate-to-8 -89 -65 1 0 -17 -59
// 59 4 26 750 775 6` (190 cases), its start values from bench/proofs_triangle_plan at commit 9f63566
// (`survey 85`: the
// exact optimum of the truncated-step model, 16188 against 16000 for n = (−89, −65, 65), top side,
// e = +1, with X = (0, ~761), K = 7, Z = p = (2047, 2047)). The earlier steep runs at s = 85 (best
// 127) took D1 = 9 from the relaxation; with the plan's lights that puts Y inside the ball (|l_Y| ~ 80),
// but a packed light sits on the shell: the plan's objective does not depend on xY, and moving Y =
// (xY, 0) until |l_Y| = s gives D1 = 4.
// s = 84, truncate_to_8 only: the same construction on the bottom side of an all-positive normal,
// where the multiply's floor of each channel's light level (folded: the ceiling, all three σ_c =
// −1) gives back up to a level per channel. bench/proofs_triangle_lattice at commit 9f63566 (`84
// truncate_to_8 60 67 -1 2 16000 40`: the construction's integer data in the limit of its windows,
// best F 16049 against 16000) and its first steep command with neighbouring normals, `proofs_triangle
// steep 84 --truncate-to-8 60 67 -1 2 -53 -62 -19 6 25 828 832 1 60 200 2 0 124.5` (7 cases):
// n = (61, 66, 91). The searches below, which found no wrap, are bench/ programs at commit 9f63566.
// Under keep_fraction no case of the construction reaches the threshold at s = 84 (search results,
// not a proof). bench/proofs_triangle_lattice finds F >= 16000 for none of the 65 weight classes of the
// top 300 rows of `bench/proofs_triangle_plan survey 84` (the best of the top nine classes 15999.59, n =
// (−87, −73, 59)), and its F counts a pixel on row 2047, which no triangle of the window covers
// (tests/proofs/triangle_test.cpp): on row 2046 the third channel gets K·|n_3|/128 levels·|n| less.
// bench/proofs_triangle_free_x frees every x step in (−1, 1) (Y's and Z's lights per channel, the
// lag planes no longer equal) and puts the pixel on row 2046: `84 IX IY SIDE THIRD 15990 40 1 1 2000`
// with THIRD = 0, 1, 2 for (IX, IY, SIDE) = (−73, −87, 1), (−69, −88, 1), (−63, −67, 1), (−63, −72,
// 1), (−64, −66, 1), (−64, −71, 1), (−71, −85, 1), (−65, −65, 1), (−65, −89, 1), (−67, −86, 1),
// (60, 67, −1), (61, 66, −1) (the |n| classes (59, 73, 87), (62, 69, 88), (63, 67, 89), (63, 72,
// 85), (64, 66, 89), (64, 71, 85), (65, 65, 89), (67, 67, 86), (60, 67, 91), (61, 66, 91), each at a
// sign pattern whose threshold is 16000) reaches F 15996.31 at best (n = (−63, −67, 89), third
// channel 2; 15996.51 with Z at each of the 256 positions of (2046, 2047]², `84 -67 -63 1 2 15996
// 40 1 1 10 1`), and the exact scorer 127 (n = (−73, −87, 59), with its neighbours and sign
// patterns); so do the same runs for one normal of each of the 55 (|n| class, third channel) pairs of
// the 249 rows of `bench/proofs_triangle_plan survey 84 400` with a positive margin (F_β >= 15990 for 16
// of them, a stage-2 F >= 15990 for 3). A wrap needs F > 16000: the floors give back less than the
// 2 (top) or 3 (bottom) that the threshold counts. Under truncate_to_8 at s = 83 the same runs (`83 truncate_to_8 IX IY
// SIDE THIRD 15900 40 1 1 2000` for (61, 66, −1), (60, 67, −1), (−67, −63, 1), (−63, −67, 1), (−89, −65, 1)) reach F
// 15944 at best (n = (60, 67, 91), bottom; exact value 127). s = 124, gouraud_setup=per_pixel with truncate_to_8 only
// (the dobiestation profile): the exact plane's light at the pixel lies in the unit box of an integer light m = (−27,
// −63, −105) just outside the packed shell, whose flat value is −129 for n = (24, 59, 111); the multiply's floor hands
// it m. `proofs_triangle boxes 124` (1 088 normals open by the bound; this is the third of the
// three rows it prints, the other two, for n = (23, 79, ·) and (23, 98, ·), wrap the same way; ~4 min
// on one core).
// s = 126: a flat triangle (three equal lights, the first witness of two-pass.max-s.vertex, n =
// (−127, −15, 5), l = (−125, −15, 0)): every set-up gives its pixels that light exactly, so it wraps
// under every option; it is the lowest wrap under gouraud_setup=per_pixel, where no pixel lags.
// pcsx2_rows_8 (8 lanes), s = 110 and 122: a steep first row's second vector (two_pass_triangle.hpp's
// argument above lag_window). Vertices at pixel centres: A = (1007, 1000), B = (1009, 1000), C = (1007,
// 1002) with lights A, B, A; the row at y = 1000 starts at A, 1007 = 7 mod 8, so the pixel (1008, 1000),
// whose exact light is (A + B)/2, is lane 0 of the next vector: on the channel whose lights differ by
// >= 74 levels (|8·g| and |7·g| above 32767 units) the saturated offset and step give A's value back
// (minus a unit), the other channels keep (A + B)/2, and that mix leaves the ball along n. Found by a
// scan over sampled Appendix 2 normals, the steep channel set and the 200 best packed lights A and B by
// that mix's n·light (a scratch search, not kept: the construction above is all it used).
// pcsx2_rows_4, s = 100 and 122: the same with 4 lanes, A = (1003, 1000) (3 mod 4) and B = (1004 + 1/16, 1000),
// so that P(1004, 1000) = A + (16/17)·(B − A) and the steep channel (lights >= 81 levels apart, |3·g| and
// |4·g| above 32767) keeps A's value.
// tests/proofs replays each through the pipeline's rasteriser (the pixel is covered) and
// gs::pixel_pipeline.
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
    case gs::gouraud_setup::per_pixel: return 1;
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
