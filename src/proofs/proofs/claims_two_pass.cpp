// Section 3.5: the two-pass method's error and its wrap limit s.
#include <algorithm>
#include <cstdio>
#include <string>

#include "gs_arith/gouraud.hpp"
#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/domains.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::claims {

namespace {
constexpr int paper_s = 122;

std::string describe_light(const ivec3& l) {
  return "l = (" + std::to_string(l[0]) + ", " + std::to_string(l[1]) + ", " + std::to_string(l[2]) + ") colour 0x" +
         [&] {
           char b[16];
           std::snprintf(b, sizeof b, "%02x%02x%02x", 128 + l[2], 128 + l[1], 128 + l[0]);
           return std::string(b);
         }();
}
std::string describe_pair(const paper::packed_normal& p, const ivec3& l, const gs::model_options& o) {
  const auto r = two_pass::pixel(p, two_pass::vertex_light(l), o);
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
  out.figures = {fig("s", paper_s), fig("lights", static_cast<std::int64_t>(nl)),
                 fig("normals", static_cast<std::int64_t>(normals.size())), fig("err_min", err.min),
                 fig("err_max", err.max), fig("full_scan", r.full_scan ? 1 : 0)};
  out.witnesses = {"err_min: " + describe_pair(normals[err.arg_min / nl], g.lights[err.arg_min % nl], o),
                   "err_max: " + describe_pair(normals[err.arg_max / nl], g.lights[err.arg_max % nl], o)};
  out.note = "per-pixel result − floor(n·l/128) over normals × packed lights (s = 122): the floors of the "
             "split products and the n'_a rounding add up to ±3";
  return out;
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
  return out;
}

}  // namespace gsdot3::proofs::claims

namespace gsdot3::proofs::claims {

namespace {
// Wrapping pixels found by bench/proofs_span_search (a search over spans between nearby vertex
// lights of the cap around each candidate normal). They are certificates: each run re-derives the
// span through the model's Gouraud unit and the pixel through the two-pass passes, and a
// certificate that no longer wraps is reported, not trusted.
struct span_certificate {
  int s, iX, iY;
  ivec3 l0, l1;
  int pixels, k;
};
constexpr span_certificate certificates[] = {
    {125, -123, -26, {-121, -24, 20}, {-120, -26, 23}, 65, 35},
};
constexpr int span_max_pixels = 128;

}  // namespace

outcome two_pass_max_s_interpolated(const gs::model_options& o, const sweep_config& cfg) {
  // Domain: every span (scanline or edge) of n <= 128 pixels between two vertex lights of L_s
  // (packed_lights), every pixel k in 0..n, light colour from gs::gouraud_span / gouraud_at (8.7,
  // steps truncated toward zero), against every Appendix 2 normal. Far too large to enumerate
  // (|L_s|² · Σ (n + 1)); reduction:
  // (1) s <= 123 never wraps. Pixel k's 8.7 channel is 128·l0 + k·trunc(128·Δ/n): it lags the exact
  //     segment point p = l0 + (k/n)·Δ by less than k/128 <= 1 per component, and |p| <= s. The
  //     bounds of two_pass::wrap_search hold for 8.7 lights too (q_c = floor / ceil of n_c·l_c/128),
  //     so value < n·l/128 + 2 + e <= s + |n|_1/128 + 3 < s + 4.74 and value > −s − 1.74 − 4:
  //     −s − 5 <= value <= s + 4, inside [−128, 127] for s <= 123.
  // (2) Wraps at larger s are shown by certificates (above), re-verified here through the model; the
  //     vertex wraps of two-pass.max-s.vertex (s = 126) are pixels k = 0 of every span.
  //     With gouraud_fraction = truncate_to_8 the channel is further truncated to an integer (lag < 2
  //     per component): −s − 7 <= value <= s + 6, safe for s <= 121.
  // s between the proven bound and the first certified wrap is left undecided: reported as the gap.
  (void)cfg;
  const auto& normals = appendix2_normals();
  const int proven_safe = o.gouraud == gs::gouraud_fraction::keep_fraction ? 123 : 121;
  int first_wrap = 126;  // two-pass.max-s.vertex: vertex pixels wrap at s = 126
  std::vector<std::string> witnesses;
  tally failed;
  std::uint64_t index = 0;
  for (const auto& c : certificates) {
    const auto p = paper::pack_normal_from(c.iX, c.iY);
    const bool normal_ok = c.iX * c.iX + c.iY * c.iY <= 16358;
    const bool lights_ok = is_packed_light(c.s, c.l0) && is_packed_light(c.s, c.l1) && c.pixels >= 1 &&
                           c.pixels <= span_max_pixels && c.k >= 0 && c.k <= c.pixels;
    auto colour = [](const ivec3& l) {
      return gs::rgba8{methods::byte(128 + l[0]), methods::byte(128 + l[1]), methods::byte(128 + l[2]), methods::byte(0x80)};
    };
    const auto light = gs::gouraud_at(gs::gouraud_span(colour(c.l0), colour(c.l1), c.pixels), c.k);
    const auto r = two_pass::pixel(p, light, o);
    const bool wraps = r.dot != r.value;
    if (normal_ok && lights_ok && wraps) {
      first_wrap = std::min(first_wrap, c.s);
      char buf[160];
      std::snprintf(buf, sizeof buf, " => light 8.7 (0x%04x, 0x%04x, 0x%04x), value %d, DPB dot ", light.r.value(),
                    light.g.value(), light.b.value(), r.value);
      witnesses.push_back("s = " + std::to_string(c.s) + ": n = (" + std::to_string(p.iX) + ", " + std::to_string(p.iY) +
                          ", " + std::to_string(p.iZ) + "), span of " + std::to_string(c.pixels) + " pixels from " +
                          describe_light(c.l0) + " to " + describe_light(c.l1) + ", pixel " + std::to_string(c.k) + buf +
                          hexdec(r.dot));
    } else {
      failed.add(index);
    }
    ++index;
  }
  outcome out;
  out.result = verdict::bound;
  // Per normal at s = 122: |L_122|² spans of each length n, n + 1 pixels each.
  const std::uint64_t l122 = packed_lights(paper_s).size();
  out.domain_size = l122 * l122 * static_cast<std::uint64_t>((span_max_pixels + 1) * (span_max_pixels + 2) / 2 - 1);
  out.counterexamples = failed.count;
  out.figures = {fig("s_max", proven_safe), fig("s_max_upper", first_wrap - 1), fig("first_wrapping_s", first_wrap),
                 fig("paper_s", paper_s), fig("margin", proven_safe - paper_s), fig("span_max_pixels", span_max_pixels),
                 fig("certificates_failed", static_cast<std::int64_t>(failed.count)),
                 fig("normals", static_cast<std::int64_t>(normals.size()))};
  out.witnesses = std::move(witnesses);
  out.note = "Gouraud-interpolated lights never wrap for s <= " + std::to_string(proven_safe) +
             " (argument); a pixel wraps at s = " + std::to_string(first_wrap) + " (certificate); " +
             (first_wrap - 1 == proven_safe + 1 ? "s = " + std::to_string(proven_safe + 1)
                                                : "s = " + std::to_string(proven_safe + 1) + ".." + std::to_string(first_wrap - 1)) +
             " is undecided. The truncated Gouraud steps let a pixel's light stick out of the vertex sphere, so the "
             "safe s is below the vertex one; the paper's 122 is still safe";
  return out;
}

}  // namespace gsdot3::proofs::claims
