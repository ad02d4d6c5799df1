// proofs/two_pass.hpp — section 3.5's two-pass method on one pixel, through the model, plus the
// per-channel fast path and the pruned wrap search the s_max claims use; and section 3.5's three-pass
// alternative, which differs only in how n_a enters the sum (na_term).
#pragma once

#include <cstdint>
#include <vector>

#include "gs_arith/options.hpp"
#include "gs_arith/texture_function.hpp"
#include "proofs/domains.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::two_pass {

// How n_a = Σ_c (128 + Max(−n_c, 0) − Max(n_c, 0)) enters the sum: the two-pass method stores
// n'_a = (n_a + 1)/3 in the negative palette's alpha and adds it to each channel (post pass 2.4a);
// the three-pass alternative ("adding the terms as a separate additive pass") adds each channel's
// term from a third palette in a third pass (methods::three_pass_pass3), so nothing is divided by 3.
enum class na_term { thirds_in_alpha, additive_pass };

// The palettes of one normal-map texel (Appendix 2): positive side (alpha unused), negative side
// with alpha n'_a, and the three-pass terms (128 + Max(−n_c, 0) − Max(n_c, 0) per channel).
struct palette_pair {
  gs::rgba8 pos, neg, terms;
};
palette_pair palettes(const paper::packed_normal& p) noexcept;

// One pixel: pass 1, pass 2, the post filter r+g+b+3a (thirds_in_alpha), or pass 1, pass 2, pass 3
// and the post filter r+g+b (additive_pass). `value` is the same sum at value level (pass-2 blend
// outputs before COLCLAMP, + 3·As, or + what pass 3 adds, − 384): the dot product the method computes
// when nothing wraps. `dot` is what the DPB holds after the post filter, read as a signed dot product
// (the byte minus 128, mod 256). The pixel wraps iff dot != value.
struct pixel_result {
  int value;
  int dot;
};
pixel_result pixel(const paper::packed_normal& p, gs::fragment_colour light, const gs::model_options& o,
                   na_term m = na_term::thirds_in_alpha) noexcept;

// The light colour of a packed tolight vector l (section 3.5): 128 + l per channel, flat.
gs::fragment_colour vertex_light(const ivec3& l) noexcept;

// Fast path for vertex (flat) lights: the per-channel pass-1 + pass-2 values, the pass-2 alpha and
// what pass 3 adds, tabulated through the model once. Every pass treats the channels independently
// (MODULATE and the blends are per channel), so value = Σ channel(n_c, l_c) + 3·alpha(n'_a) − 384, or
// Σ channel(n_c, l_c) + Σ term(n_c) − 384 with the additive pass; tests check it against pixel() bit
// for bit.
class table {
 public:
  explicit table(const gs::model_options& o, na_term m = na_term::thirds_in_alpha);
  int channel(int n, int l) const noexcept { return channel_[static_cast<std::size_t>((n + 127) * 256 + (l + 128))]; }
  int alpha(int a) const noexcept { return alpha_[static_cast<std::size_t>(a)]; }
  // channel(n, ·) as an array indexed by l in [−128, 127].
  const std::int16_t* row(int n) const noexcept { return &channel_[static_cast<std::size_t>((n + 127) * 256 + 128)]; }
  // What pass 3 adds to a channel whose normal component is n (the terms texel 128 − n).
  int term(int n) const noexcept { return term_[static_cast<std::size_t>(n + 127)]; }
  int value(const paper::packed_normal& p, const ivec3& l) const noexcept {
    return channel(p.iX, l[0]) + channel(p.iY, l[1]) + channel(p.iZ, l[2]) + na(p) - 384;
  }
  // What the pixel adds for n_a, less n_a: 3·n'_a − n_a (the alpha after pass 2), or the three terms
  // pass 3 adds less n_a.
  int alpha_error(const paper::packed_normal& p) const noexcept { return na(p) - (384 + p.delta); }
  na_term method() const noexcept { return m_; }

 private:
  int na(const paper::packed_normal& p) const noexcept {
    return m_ == na_term::thirds_in_alpha ? 3 * alpha(p.alpha) : term(p.iX) + term(p.iY) + term(p.iZ);
  }
  na_term m_;
  std::vector<std::int16_t> channel_;  // n in [−127, 128] × l in [−128, 127]
  std::vector<std::int16_t> alpha_;    // 0..255
  std::vector<std::int16_t> term_;     // n in [−127, 128]
};

// The packed lights of one s, indexed by (x, y) cell for the cap enumeration below.
struct light_grid {
  int s;
  std::vector<ivec3> lights;         // sorted by (x, y, z)
  std::vector<std::uint32_t> start;  // cell (x + s)·(2s + 1) + (y + s) -> first index; one past the end last
  explicit light_grid(int s);
  std::uint32_t cell_begin(int x, int y) const noexcept { return start[cell(x, y)]; }
  std::uint32_t cell_end(int x, int y) const noexcept { return start[cell(x, y) + 1]; }

 private:
  std::size_t cell(int x, int y) const noexcept { return static_cast<std::size_t>((x + s) * (2 * s + 1) + (y + s)); }
};

// Pairs (normal i, light j), index i·|lights| + j, whose value is >= hi or <= lo.
struct wrap_hits {
  tally hits;
  std::uint64_t evaluated = 0;  // pairs actually evaluated (the rest were pruned)
  void merge(const wrap_hits& later) {
    hits.merge(later.hits);
    evaluated += later.evaluated;
  }
};

// Pruned search. Argument (with q_c = channel(n_c, l_c) − n_c and e = 3·n'_a − n_a, so that
// value = Σ q_c + e): the model floors every product, so q_c = floor(n_c·l_c / 128) for n_c >= 0 and
// q_c = −floor(−n_c·l_c / 128) = ceil(n_c·l_c / 128) for n_c < 0; since n_c·l_c is an integer,
//   (n·l − 127·#{n_c >= 0}) / 128 + e  <=  value  <=  (n·l + 127·#{n_c < 0}) / 128 + e.
// So value >= hi needs n·l >= 128·(hi − e) − 127·#{n_c < 0}, and value <= lo needs
// n·l <= 128·(lo − e) + 127·#{n_c >= 0}. For |l| <= s those lights lie in a spherical cap around ±n,
// whose bounding box of (x, y) cells is enumerated; every light in it is evaluated exactly. The
// tests compare this against brute force (wrap_search_brute) on smaller instances.
wrap_hits wrap_search(const std::vector<paper::packed_normal>& normals, const light_grid& grid, const table& t, int hi,
                      int lo, const sweep_config& cfg);
wrap_hits wrap_search_brute(const std::vector<paper::packed_normal>& normals, const light_grid& grid, const table& t,
                            int hi, int lo, const sweep_config& cfg);

// The extremes of value − exact_dot over normals × grid lights. Reduction (argument in
// claims_two_pass.cpp, two_pass_error_bound): without wraps the error is e − floor(Σ r_c) with
// e = t.alpha_error(p) and floor(Σ r_c) ∈ [−2, 2] (n_z > 0), so it lies in [e_min − 2, e_max + 2]
// (e over the normals); the top only for e = e_max with n_x, n_y < 0, the bottom only for e = e_min
// with n_x, n_y >= 0 (two-pass: e ∈ [−1, 1], so ±3; three-pass: e = 0, so ±2). So those normals are
// scanned against every light, stopping at the first pair (in normal-major order) that reaches an
// end; if either end is not reached, the whole domain is scanned. Either way the result is the exact
// extremes (for wrap-free instances) and does not depend on the thread count.
struct error_result {
  extremes err;                 // indices i·|lights| + j
  std::uint64_t evaluated = 0;  // pairs evaluated
  bool full_scan = false;
};
error_result error_extremes(const std::vector<paper::packed_normal>& normals, const light_grid& grid, const table& t,
                            const sweep_config& cfg);

// floor(n·l / 128): the exact integer dot product of the packed normal and light.
constexpr int exact_dot(const paper::packed_normal& p, const ivec3& l) noexcept {
  return (p.iX * l[0] + p.iY * l[1] + p.iZ * l[2]) >> 7;
}

}  // namespace gsdot3::proofs::two_pass
