// proofs/two_pass_triangle.hpp — section 3.5's interpolated light vectors on whole triangles, as the
// GS model sets them up (gs::gouraud_triangle), and the bound on how far a pixel's light can leave
// the vertex lights' sphere.
#pragma once

#include <array>
#include <cstdint>
#include <span>

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

// Wrapping cases found by bench/proofs_triangle_search (its construction: a right triangle whose x
// step fractions are near 1 and point along the normal, the pixel next to its top-right vertex,
// ~2030 pixels from the plane's reference pixel), one per s it was run for (s = 100 twice: one
// for each gouraud_fraction). tests/proofs replays each through the pipeline's rasteriser (the pixel
// is covered) and gs::pixel_pipeline.
std::span<const triangle_case> certificates() noexcept;

// The vertex colour of a packed light: 128 + l per channel, vertex alpha 0x80.
gs::rgba8 light_colour(const ivec3& l) noexcept;

// The pixel's light colour: the plane of gs::gouraud_triangle with the reference pixel the
// pipeline uses (pipeline/band_renderer.hpp attributes(): the top-left pixel of the triangle's
// bounding box, ceil of the least x and y), read at the pixel by gs::gouraud_at. Whether the pixel
// is covered is the rasteriser's business: the tests replay every certificate through it.
gs::fragment_colour pixel_light(const triangle_case& c) noexcept;

// The error bound. Write P_c for the exact plane of channel c (8.7 units) through the three vertex
// values and (a, b) = pixel − reference pixel, a, b in 0 .. 2047 (the pixel and the reference are
// window pixels, the reference the least). gouraud_triangle truncates the start value at the
// reference and the two steps toward zero, each by less than one unit, and gouraud_at adds a·dx +
// b·dy exactly, so the pixel's channel is L_c = P_c(pixel) + E_c with |E_c| < 1 + a + b <= 4095.
// The clamp to 0 .. 0x7FFF only moves L_c towards P_c(pixel) ∈ [0, 32640] (a covered pixel lies in
// the closed triangle, so P(pixel) is a convex combination of the vertex values). With
// gouraud_fraction = truncate_to_8 the multiply sees 128·floor(L_c/128): |E_c| < 4095 + 128.
// With λ_c = L_c/128 − 128 and the floors of the two passes (q_c = floor or ceil of n_c·λ_c/128,
// two_pass::wrap_search), value <= n·λ/128 + #{n_c < 0} + e and value >= n·λ/128 − #{n_c >= 0} + e,
// and n·λ <= |n|·s + |n|_1·max|E_c|/128 since the convex combination has |·| <= s. So a normal
// cannot wrap at s when  (|n|·s·128 + |n|_1·E)/16384 + #{n_c < 0} + e < 128  and
// −(|n|·s·128 + |n|_1·E)/16384 − #{n_c >= 0} + e > −129, E = max|E_c| (evaluated exactly in
// integers: |n|·s <= sqrt(|n|²)·s is taken as the ceiling of the square root).
constexpr int max_error_units(const gs::model_options& o) noexcept {
  return o.gouraud == gs::gouraud_fraction::keep_fraction ? 4095 : 4095 + 128;
}
bool cannot_wrap(const paper::packed_normal& p, int e, int s, const gs::model_options& o) noexcept;
// The largest s such that no normal can wrap for any s' <= s by that bound (0 if none).
int bound_safe_s(const gs::model_options& o);

// --brute-force: the bound's one lemma, |L_c − P_c(pixel)| < 1 + a + b, checked directly at full
// size against the exact rational plane, on every triangle whose vertices lie on an 8 × 8 lattice
// spanning the window (step 256 pixels plus a 12.4 fraction that differs per point, every ordered
// triple, 2^18) × every ordered triple of 4 lights of L_122 (2^6), every pixel centre in the closed
// triangle (a superset of the covered pixels). 2^24 cases of ~10^5 pixels each: a run for a
// cluster, split with --shard (65 536 chunks).
struct brute_force_acc {
  tally violations;           // cases with a pixel breaking the lemma
  extremes ratio_ppm;         // max over pixels of |E_c| / (1 + a + b), in millionths
  extremes error_units;       // max |E_c| (8.7 units, rounded down)
  std::uint64_t pixels = 0;
  void merge(const brute_force_acc& later) {
    violations.merge(later.violations), ratio_ppm.merge(later.ratio_ppm), error_units.merge(later.error_units);
    pixels += later.pixels;
  }
};
inline constexpr std::uint64_t brute_force_cases = std::uint64_t{1} << 24;
triangle_case brute_force_case(std::uint64_t index);  // s, iX, iY unused (0)
brute_force_acc brute_force(const sweep_config& cfg);

}  // namespace gsdot3::proofs::two_pass::triangle
