// two_pass_triangle/relaxation_classes.hpp — the step from the error bound (i)–(iii) of two_pass_triangle.hpp to
// the s two-pass.max-s.interpolated proves under gouraud_setup = plane_steps: the classes (|n| sorted,
// wrap-side threshold) the bound's reach_units leaves open at s, each certified by triangle_certify's
// branch and bound on the continuous relaxation of the bound's own statements. A class that closes is
// safe at s and at every s' <= s (the ball of radius s' lies in that of s; the threshold does not
// depend on s), so every normal of every class is, and the normals the bound settles were safe anyway.
// The relaxation's lights are the whole ball |l| <= s, so it covers tolight = attenuated_T too.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gs_arith/options.hpp"
#include "proofs/paper_code.hpp"

namespace gsdot3::proofs::two_pass::triangle::certify {

struct open_class {
  std::int64_t gap;           // reach + truncation − wrap threshold, 8.7·n units (the bound's shortfall)
  std::array<int, 3> w;       // |n| sorted
  std::int64_t threshold128;  // 128·relaxation_threshold
  int iX, iY, side;           // one normal and side of the class (the one the bound misses by most)
};
// Every class whose reach_units leaves a side open at s, most open first.
std::vector<open_class> open_classes(int s, const gs::model_options& o);

// The branch and bound's settings for the ledger (and tools/proofs_triangle certify's defaults): the
// families' box side (pixels), the narrowest rectangle (1/16 pixel), the rectangles per class. A box of
// 2047 covers the claim's domain: its vertices lie in 0 .. 2047 pixels (12.4 window coordinates 0 ..
// 2047·16), so after the family reduction's translation (the least vertex coordinate onto r, by less
// than a pixel) every vertex coordinate and the pixel's offset from r lie in [0, max − min] ⊂ [0, 2047],
// and its scaling (λ, μ >= 1) stops at 2047. 2048 leaves one class open at s = 82 under truncate_to_8.
inline constexpr std::int64_t survey_box = 2047, survey_max_cells = 2000000;
inline constexpr int survey_min_cell_log2 = -4;
// Whether certify_class closes every open class at s with those settings (the classes certified on
// every core; the rest are skipped once one does not close).
bool relaxation_certified(int s, const gs::model_options& o);

// The s the claim takes as certified, per gouraud_fraction (plane_steps; 0 under per_pixel, whose bound
// needs no relaxation): 83 under keep_fraction, 82 under truncate_to_8 (`tools/proofs_triangle certify
// 83`: 2 183 classes, 38.1 s; `certify 82 --truncate-to-8`: 2 965 classes, 57.6 s, one core).
// Too slow for prove's budget, so prove takes these values and ctest proofs_certify_survey (label
// exhaustive) re-runs relaxation_certified at them (the open classes are the same under every value of
// tfx_rounding and blend_shift, which it checks too), and checks
// that s + 1 does not certify (the relaxation exceeds there: 84, and 83 under truncate_to_8).
int certified_relaxation_s(const gs::model_options& o) noexcept;

// The classes of open_classes(s, o) that certify_class, with the survey's settings, does not close
// (it stops each at its first rectangle whose attained value is above the threshold, or at
// survey_max_cells), in open_classes' order; every other class is safe at s.
std::vector<open_class> uncertified_classes(int s, const gs::model_options& o);
// The Appendix 2 normals with a wrap side in one of `classes` (|n| sorted and threshold128 as
// open_classes keys them) whose bound leaves that side open at s, in appendix2_normals' order.
std::vector<paper::packed_normal> normals_in(const std::vector<open_class>& classes, int s, const gs::model_options& o);

// At s_next = certified_relaxation_s + 1, where the relaxation itself exceeds (relaxation_witnesses):
// how many classes open_classes lists, how many of them stay uncertified and how many normals those
// hold, so that a wrap at s_next needs one of those normals (plane_steps; zeros under per_pixel).
// Measured by `tools/proofs_triangle certify 84` (155 of 3 851 classes stop, 557 normals, 140 s;
// `certify 83 --truncate-to-8`: 303 of 5 270, 1 042 normals, 131 s; one core) and re-derived by
// ctest proofs_certify_next_s under every tfx_rounding × blend_shift; prove takes the stored values.
struct next_s_survey {
  int s = 0;
  int classes = 0, uncertified = 0;
  std::int64_t normals = 0;
};
next_s_survey uncertified_next_s(const gs::model_options& o) noexcept;

}  // namespace gsdot3::proofs::two_pass::triangle::certify
