// Section 3.5: the two-pass method's error and its wrap limit s, and the error of its three-pass
// alternative.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/claims_two_pass_text.hpp"
#include "proofs/domains.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::claims {

namespace two_pass_text {
std::string describe_light(const ivec3& l) {
  return "l = (" + std::to_string(l[0]) + ", " + std::to_string(l[1]) + ", " + std::to_string(l[2]) + ") colour 0x" +
         [&] {
           char b[16];
           std::snprintf(b, sizeof b, "%02x%02x%02x", 128 + l[2], 128 + l[1], 128 + l[0]);
           return std::string(b);
         }();
}

// Domain option tolight = attenuated_T (|T| <= 1, §3.5's per-vertex attenuation): the lights are the
// ball Σ l² <= s² instead of its shell. Every argument of these claims uses only |l| <= s (the error
// terms r_c, the value bounds of two_pass::wrap_search, the triangle bound), so their bounds hold on
// the ball, and every extreme and witness found is a unit-T light, a member of the ball: the outcome
// is the same. tests/proofs/reduction_test.cpp checks it against brute force over the ball at s = 40.
outcome for_domain(outcome o, const sweep_config& cfg) {
  if (cfg.domain.light == domain_options::tolight::attenuated)
    o.note += " (tolight = attenuated_T: the same on the ball of lights, by the bounds' use of |l| <= s only)";
  return o;
}
}  // namespace two_pass_text

namespace {
using two_pass_text::describe_light, two_pass_text::paper_s;

std::string describe_pair(const paper::packed_normal& p, const ivec3& l, const gs::model_options& o,
                          two_pass::na_term na = two_pass::na_term::thirds_in_alpha) {
  const auto r = two_pass::pixel(p, two_pass::vertex_light(l), o, na);
  return "n = (" + std::to_string(p.iX) + ", " + std::to_string(p.iY) + ", " + std::to_string(p.iZ) + ") alpha " +
         hexdec(p.alpha) + ", " + describe_light(l) + " => value " + std::to_string(r.value) + ", DPB dot " +
         hexdec(r.dot) + ", floor(n·l/128) = " + std::to_string(two_pass::exact_dot(p, l));
}

}  // namespace

outcome two_pass_error_bound(const gs::model_options& o, const sweep_config& cfg) {
  // Domain: every Appendix 2 normal × every packed light of s = 122 (too large to enumerate:
  // ~51 000 × ~280 000). Reduction, with q_c, e as in two_pass::wrap_search:
  //   value = Σ q_c + e, and with r_c = n_c·l_c/128 − q_c, floor(n·l/128) = Σ q_c + floor(Σ r_c),
  //   so error = value − floor(n·l/128) = e − floor(Σ r_c)   (when nothing wraps: s_max >= 125).
  // r_c ∈ [0, 1) for n_c >= 0 and (−1, 0] for n_c < 0; n_z = iZ >= 5 > 0 (appendix2.packing), so
  // Σ r_c ∈ (−2, 3) and error ∈ [e − 2, e + 2] ⊂ [−3, 3] (|e| <= 1, two-pass.na-rounding).
  // +3 needs e = +1 and n_x, n_y < 0; −3 needs e = −1 and n_x, n_y >= 0. A witness for each makes
  // [−3, 3] tight; the search scans exactly those normals against every light and stops at the
  // first witness. Were one missing, the full domain is scanned for the true extreme.
  const auto& normals = appendix2_normals();
  const two_pass::light_grid g(paper_s);
  const two_pass::table t(o);
  const std::uint64_t size = normals.size() * g.lights.size();
  const auto r = two_pass::error_extremes(normals, g, t, cfg);
  const auto& err = r.err;
  const std::uint64_t nl = g.lights.size();
  outcome out;
  out.result = verdict::bound;
  out.domain_size = size;
  out.figures = {fig("s", paper_s),
                 fig("lights", static_cast<std::int64_t>(nl)),
                 fig("normals", static_cast<std::int64_t>(normals.size())),
                 fig("err_min", err.min),
                 fig("err_max", err.max),
                 fig("full_scan", r.full_scan ? 1 : 0)};
  out.witnesses = {"err_min: " + describe_pair(normals[err.arg_min / nl], g.lights[err.arg_min % nl], o),
                   "err_max: " + describe_pair(normals[err.arg_max / nl], g.lights[err.arg_max % nl], o)};
  out.note =
      "per-pixel result − floor(n·l/128) over normals × packed lights (s = 122): the floors of the "
      "split products and the n'_a rounding add up to ±3";
  return two_pass_text::for_domain(std::move(out), cfg);
}

outcome three_pass_error_bound(const gs::model_options& o, const sweep_config& cfg) {
  // The three-pass alternative adds 128 + Max(−n_c, 0) − Max(n_c, 0) to each channel in a third pass
  // instead of n'_a = (n_a + 1)/3 to all three. The same reduction as two_pass_error_bound, with
  // e = what pass 3 adds − n_a: the sweep over every Appendix 2 normal below shows e = 0 (the terms
  // palette entries are bytes 0..255 and Cs + Cd adds them exactly), so error = −floor(Σ r_c) ∈ [−2, 2];
  // +2 needs n_x, n_y < 0, −2 needs n_x, n_y >= 0, and error_extremes searches those for witnesses.
  const auto& normals = appendix2_normals();
  const two_pass::light_grid g(paper_s);
  const two_pass::table t(o, two_pass::na_term::additive_pass), thirds(o);
  std::int64_t e_nonzero = 0, two_pass_e_nonzero = 0;
  for (const auto& p : normals) e_nonzero += t.alpha_error(p) != 0, two_pass_e_nonzero += thirds.alpha_error(p) != 0;
  const auto r = two_pass::error_extremes(normals, g, t, cfg);
  const std::uint64_t nl = g.lights.size();
  outcome out;
  out.result = verdict::bound;
  out.domain_size = normals.size() * nl;
  out.figures = {fig("s", paper_s),
                 fig("normals", static_cast<std::int64_t>(normals.size())),
                 fig("normals_na_not_exact", e_nonzero),
                 fig("two_pass_normals_na_not_exact", two_pass_e_nonzero),
                 fig("err_min", r.err.min),
                 fig("err_max", r.err.max),
                 fig("full_scan", r.full_scan ? 1 : 0)};
  const auto na = two_pass::na_term::additive_pass;
  out.witnesses = {"err_min: " + describe_pair(normals[r.err.arg_min / nl], g.lights[r.err.arg_min % nl], o, na),
                   "err_max: " + describe_pair(normals[r.err.arg_max / nl], g.lights[r.err.arg_max % nl], o, na)};
  out.note = "the additive pass adds n_a exactly for " +
             std::string(e_nonzero == 0 ? "every normal" : "all but " + std::to_string(e_nonzero) + " normals") +
             " (two-pass's n'_a misses it by one for " + std::to_string(two_pass_e_nonzero) +
             "), so the per-pixel error against floor(n·l/128) narrows from two-pass's ±3 to [" +
             std::to_string(r.err.min) + ", " + std::to_string(r.err.max) +
             "]: what is left is the floors of the split products, which the third pass cannot remove";
  return two_pass_text::for_domain(std::move(out), cfg);
}

namespace {
// value >= 128 or <= −129 means the signed byte the DPB holds is not the dot product: a wrap.
constexpr int wrap_hi = 128, wrap_lo = -129;
}  // namespace

outcome two_pass_max_s_vertex(const gs::model_options& o, const sweep_config& cfg) {
  // Argument for s <= 125 (no search needed): |l| <= s (Σ l_c² <= s², packed_lights), |n| <= 128,
  // at most two negative components (iZ >= 5), |e| <= 1, so by the bounds of two_pass::wrap_search
  //   value <= (128·s + 2·127)/128 + 1 < s + 3   and   value >= (−128·s − 3·127)/128 − 1 > −s − 4,
  // i.e. −s − 3 <= value <= s + 2: inside [−128, 127] for every s <= 125. Above that, the pruned
  // search decides each s up to 127 (s = 128 would overflow the (char) cast for T = (1, 0, 0)).
  const auto& normals = appendix2_normals();
  const two_pass::table t(o);
  int s_max = 125;
  std::uint64_t domain = 0;
  std::vector<std::string> witnesses;
  std::int64_t wrapping = 0, evaluated = 0;
  for (int s = 126; s <= 127; ++s) {
    const two_pass::light_grid g(s);
    domain += normals.size() * g.lights.size();
    const auto r = two_pass::wrap_search(normals, g, t, wrap_hi, wrap_lo, cfg);
    evaluated += static_cast<std::int64_t>(r.evaluated);
    if (r.hits.count > 0) {
      wrapping = static_cast<std::int64_t>(r.hits.count);
      const std::uint64_t nl = g.lights.size();
      for (auto i : r.hits.first)
        witnesses.push_back("s = " + std::to_string(s) + ": " + describe_pair(normals[i / nl], g.lights[i % nl], o));
      break;
    }
    s_max = s;
  }
  outcome out;
  out.result = verdict::bound;
  out.domain_size = domain;
  out.figures = {fig("s_max", s_max), fig("paper_s", paper_s), fig("margin", s_max - paper_s),
                 fig("wrapping_pairs_at_s_max_plus_1", wrapping), fig("pairs_evaluated", evaluated)};
  out.witnesses = std::move(witnesses);
  out.counterexamples = static_cast<std::uint64_t>(wrapping);
  out.note = "no Appendix 2 normal and no vertex-packed light wraps for s <= " + std::to_string(s_max) +
             " (s <= 125 by the bound, larger s by the pruned exhaustive search); the paper's 122 is safe";
  return two_pass_text::for_domain(std::move(out), cfg);
}

}  // namespace gsdot3::proofs::claims
