// two_pass_triangle/triangle_relaxation.hpp — how far the error bound of two-pass.max-s.interpolated can go:
// the continuous relaxation of its per-channel statements, and the witnesses that it admits a wrap.
//
// The statements (two_pass_triangle.hpp): at a covered pixel p = r + (a, b), channel c with wrap-side
// sign σ_c has σ_c·L_c(p) < σ_c·P_c(p) + 1 + a·min(1, t_x) + b·min(1, t_y) units on the axes where it is
// aligned (t = −σ_c·(the exact step in units per pixel) > 0) and nothing more on the others; P lies
// in the vertex lights' ball. Relaxed: real vertices, real lights in the ball |l| <= s (levels), any
// real p in the triangle, the lag a·clamp(t, 0, 1) taken in full. A relaxation witness is a point of
// that relaxation where Σ_c |n_c|·σ_c·(L_c − 16384) plus the bound's own slack exceeds the wrap
// threshold: then no argument that uses only those statements and the ball can prove its normal
// safe at s, and the open range can only be closed with the lattice (integer lights, 12.4 vertices,
// the truncation itself, the floors). `tools/proofs_triangle relaxation` searches the geometry for them
// and `tools/proofs_triangle certify` meets them where its branch and bound stops (triangle_certify.hpp
// argues the reduction of the geometry to five families with the bounding box [0, 2048]² and p at a vertex).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "gs_arith/options.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::two_pass::triangle {

// Lights and directions are σ-folded: component c is σ_c times the light's component, σ_c = side·sign n_c
// (side +1: the top, −1: the bottom), so "larger" is towards the wrap on every channel.
struct relaxation_point {
  std::array<std::array<double, 2>, 3> vertex;  // pixels, relative to the reference pixel r = (0, 0)
  std::array<double, 2> pixel;                  // p, in the closed triangle
  std::array<std::array<double, 3>, 3> light;   // levels, σ-folded; scaled onto the ball |l| <= s where outside
};

// Σ_c w_c·(P_c(p) + p_x·clamp(t_x,c, 0, 1)/128 + p_y·clamp(t_y,c, 0, 1)/128) in levels·|n| (w = |n|,
// σ-folded), with the lights scaled onto the ball of radius s where they leave it.
double relaxation_value(const relaxation_point& x, const std::array<double, 3>& w, double s) noexcept;

struct relaxation_witness {
  int s, iX, iY;  // the normal (paper::pack_normal_from)
  int side;       // +1: the top (value >= 128), −1: the bottom (value <= −129)
  gs::gouraud_fraction gouraud;
  relaxation_point at;
};
// The table; each row was printed by a tools/proofs_triangle subcommand (command beside it).
std::span<const relaxation_witness> relaxation_witnesses() noexcept;

// The witness's value above its side's threshold, levels·|n|: relaxation_value + the start error
// (|n|_1/128: < 1 unit per channel) + truncation_units of the side (truncate_to_8), minus
// 128·(128 − #neg − e) at the top, 128·(129 − #{n_c > 0} + e) at the bottom (cannot_wrap's
// comparisons, e = t.alpha_error). Positive: the bound's statements admit a wrap.
double relaxation_margin(const relaxation_witness& w, const two_pass::table& t, const gs::model_options& o);
// What relaxation_value must exceed on that side for the bound's statements to admit a wrap:
// wrap_threshold_units minus the start error and truncation_units, in levels·|n|.
double relaxation_threshold(const paper::packed_normal& p, int e, int side, const gs::model_options& o) noexcept;
// The same, ×128 (8.7·n units): an integer, what the certified bound (triangle_certify) compares with.
std::int64_t relaxation_threshold_units(const paper::packed_normal& p, int e, int side,
                                        const gs::model_options& o) noexcept;

}  // namespace gsdot3::proofs::two_pass::triangle
