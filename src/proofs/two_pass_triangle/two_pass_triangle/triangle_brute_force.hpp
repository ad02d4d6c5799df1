// two_pass_triangle/triangle_brute_force.hpp — `gsdot3 prove --claim two-pass.max-s.interpolated --brute-force`:
// the per-channel statements the bound of two_pass_triangle.hpp sums (its (i)–(iii)), checked
// directly at full size, every pixel, channel and wrap side, against the exact rational plane.
//
// Under test: gs::gouraud_triangle with pixel_light's reference pixel r, read by gs::gouraud_at
// (L_c, clamped as the GS clamps). Reference: the exact plane P_c through the three vertex values
// 128·(128 + l_c), as a rational with denominator |det| (det = twice the area in 1/256 pixel²) at
// p, and with denominator den at w = X + (num/den)·(Y − X) (point_w). For each channel c and each
// σ = ±1 (the two wrap sides' signs σ_c), "aligned on an axis" is σ·g_c < 0 for the exact gradient
// g_c along it, and the statements are
//   (A) aligned on at most one axis:  σ·L_c(p) < σ·P_c(p) + W,
//   (B) aligned on both:              σ·L_c(p) < σ·P_c(p) + 1 + a + b   (<= 2W − 1; p = r + (a, b)),
//   (C) aligned on both:              σ·L_c(p) < σ·P_c(w) + W,
// each as `left < allowance` over one positive denominator; plus, per pixel, that w lies in the
// closed triangle (three edge tests of w's exact coordinates), so that P_c(w), like P_c(p), is a
// convex combination of the vertex values. W = window_pixels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "proofs/sweep.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::two_pass::triangle {

// One channel at one pixel for one wrap side, exact.
struct channel_view {
  int sigma = 1;  // +1 or −1
  bool aligned_x = false, aligned_y = false;
  std::int64_t a = 0, b = 0;        // p − r
  std::int64_t L = 0;               // gouraud_at's channel at p, 8.7
  std::int64_t P_p = 0, den_p = 1;  // P_c(p) = P_p / den_p, den_p = |det|
  std::int64_t P_w = 0, den_w = 1;  // P_c(w) = P_w / den_w (w = p: P_p / den_p)
};
// A statement of the bound: where it applies, and its two sides over one positive denominator
// (it holds iff left < allowance). A later bound adds a row here.
struct channel_statement {
  std::string_view name, text;
  bool (*applies)(const channel_view&);
  std::array<std::int64_t, 2> (*sides)(const channel_view&, std::int64_t window);
};
inline constexpr std::size_t statement_count = 3;
std::span<const channel_statement, statement_count> channel_statements() noexcept;

// A statement's tally over the instances (pixel, channel, σ) where it applies: `checked` counts
// them, a pixel breaking it on any channel or side is one violation, ratio_ppm is the largest
// left / allowance in millionths (rounded down, in doubles; the check itself is exact).
struct statement_acc {
  tally violations;
  extremes ratio_ppm;
  std::uint64_t checked = 0;
  void merge(const statement_acc& later) {
    violations.merge(later.violations), ratio_ppm.merge(later.ratio_ppm);
    checked += later.checked;
  }
};
// Witnesses are case index × pixel: index·2^22 + py·2^11 + px (pixel coordinates below 2048).
inline constexpr int pixel_index_bits = 22;
constexpr std::uint64_t pixel_witness(std::uint64_t case_index, int px, int py) noexcept {
  return case_index << pixel_index_bits | static_cast<std::uint64_t>(py) << 11 | static_cast<std::uint64_t>(px);
}
struct brute_force_acc {
  std::array<statement_acc, statement_count> statement{};
  tally w_outside;  // pixels whose w is not in the closed triangle
  std::uint64_t pixels = 0;
  void merge(const brute_force_acc& later) {
    for (std::size_t k = 0; k < statement_count; ++k) statement[k].merge(later.statement[k]);
    w_outside.merge(later.w_outside);
    pixels += later.pixels;
  }
};

// Every pixel centre of c's closed triangle (a superset of the pixels the rasteriser covers; c.px,
// c.py unused), every statement, with allowances for a window of `window` pixels; witnesses get
// pixel_witness(index, ·, ·).
void check_case(const triangle_case& c, std::uint64_t index, int window, brute_force_acc& acc);
// What fails at the pixel (c.px, c.py), one line per statement, channel and side ("" if nothing).
std::string failures_at(const triangle_case& c, int window);

// The domain of --brute-force: triangles whose vertices lie on an 8 × 8 lattice spanning the
// window (step 256 pixels plus a 12.4 fraction that differs per point; every ordered triple, 2^18,
// degenerate ones cover nothing) × every ordered triple of 4 lights of L_122 (2^6): 2^24 cases of
// up to ~2·10^6 pixels each, in 65 536 chunks (`--shard K/N` takes whole chunks). The statements
// do not depend on the model options.
inline constexpr std::uint64_t brute_force_cases = std::uint64_t{1} << 24;
triangle_case brute_force_case(std::uint64_t index);  // s, iX, iY unused (0)
// The cases [first, first + count) of that domain (chunks of the slice; the whole domain by default).
brute_force_acc brute_force(const sweep_config& cfg, std::uint64_t first = 0, std::uint64_t count = brute_force_cases);

}  // namespace gsdot3::proofs::two_pass::triangle
