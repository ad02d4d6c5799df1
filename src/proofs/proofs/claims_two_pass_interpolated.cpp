// Section 3.5 on whole triangles: two-pass.max-s.interpolated, from the bound, the certified relaxation
// and the certificates of src/proofs/two_pass_triangle (README.md there states the argument).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/claims_two_pass_text.hpp"
#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/relaxation_classes.hpp"
#include "two_pass_triangle/triangle_brute_force.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"

namespace gsdot3::proofs::claims {

namespace {
// The certificates (two_pass::triangle::certificates()) are re-derived on every run: the pixel's
// light through gs::gouraud_triangle and the pixel through the two-pass passes; one that does not
// wrap under the options in force is counted (certificates_not_wrapping), not trusted.
using two_pass::triangle::triangle_case;
using two_pass_text::describe_light, two_pass_text::for_domain, two_pass_text::paper_s;

// Sorted values as "89..91, 98, 100" (runs of consecutive values joined).
std::string s_ranges(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  std::string out;
  for (std::size_t i = 0; i < v.size();) {
    std::size_t j = i;
    while (j + 1 < v.size() && v[j + 1] == v[j] + 1) ++j;
    out += (out.empty() ? "" : ", ") + std::to_string(v[i]) + (j > i ? ".." + std::to_string(v[j]) : "");
    i = j + 1;
  }
  return out;
}

std::string describe_certificate(const triangle_case& c, const gs::model_options& o) {
  const auto p = paper::pack_normal_from(c.iX, c.iY);
  const auto light = two_pass::triangle::pixel_light(c, o.setup);
  const auto r = two_pass::pixel(p, light, o);
  std::string v;
  for (std::size_t k = 0; k < 3; ++k) {
    char b[48];
    std::snprintf(b, sizeof b, "%s(0x%04x, 0x%04x)", k == 0 ? "" : ", ", c.xy16[2 * k], c.xy16[2 * k + 1]);
    v += b;
  }
  char buf[200];
  std::snprintf(buf, sizeof buf, "; pixel (%d, %d) => light 8.7 (0x%04x, 0x%04x, 0x%04x), value %d, DPB dot ", c.px,
                c.py, light.r.value(), light.g.value(), light.b.value(), r.value);
  return "s = " + std::to_string(c.s) + ": n = (" + std::to_string(p.iX) + ", " + std::to_string(p.iY) + ", " +
         std::to_string(p.iZ) + ") alpha " + hexdec(p.alpha) + "; vertices 12.4 " + v + " with " +
         describe_light(c.light[0]) + ", " + describe_light(c.light[1]) + ", " + describe_light(c.light[2]) + buf +
         hexdec(r.dot);
}

// --brute-force (two_pass::triangle::brute_force, two_pass_triangle/triangle_brute_force.hpp): the bound's
// per-channel statements at full size, for gouraud_setup=plane_steps (under per_pixel the statement
// is |L_c − P_c(p)| < 1, the truncation of the exact value itself). The light does not depend on the
// other model options (truncate_to_8 is applied after, in the multiply, and adds its 128 units to the
// bound; the cases use no domain option), so the outcome is option-free and the runner checks the
// cases once, with no variants.
outcome interpolated_brute_force(const gs::model_options&, const sweep_config& cfg) {
  namespace tt = two_pass::triangle;
  const auto r = tt::brute_force(cfg);
  const auto statements = tt::channel_statements();
  outcome out;
  out.option_free = true;
  out.domain_size = tt::brute_force_cases;
  out.figures = {fig("pixels", static_cast<std::int64_t>(r.pixels))};
  auto describe = [](std::uint64_t at, const std::string& what) {
    auto c = tt::brute_force_case(at >> tt::pixel_index_bits);
    c.px = static_cast<int>(at & 2047), c.py = static_cast<int>(at >> 11 & 2047);
    const std::string failures = tt::failures_at(c, tt::window_pixels);
    return what + ": case " + std::to_string(at >> tt::pixel_index_bits) + ", vertices 12.4 (" + hexdec(c.xy16[0], 16) +
           ", " + hexdec(c.xy16[1], 16) + "), (" + hexdec(c.xy16[2], 16) + ", " + hexdec(c.xy16[3], 16) + "), (" +
           hexdec(c.xy16[4], 16) + ", " + hexdec(c.xy16[5], 16) + ") with " + describe_light(c.light[0]) + ", " +
           describe_light(c.light[1]) + ", " + describe_light(c.light[2]) + ", pixel (" + std::to_string(c.px) + ", " +
           std::to_string(c.py) + ") => " + failures;
  };
  for (std::size_t k = 0; k < tt::statement_count; ++k) {
    const auto& acc = r.statement[k];
    const std::string name(statements[k].name);
    out.counterexamples += acc.violations.count;
    out.figures.push_back(fig(name + "_checked", static_cast<std::int64_t>(acc.checked)));
    out.figures.push_back(fig(name + "_violations", static_cast<std::int64_t>(acc.violations.count)));
    out.figures.push_back(fig(name + "_max_left_over_allowance_ppm", acc.ratio_ppm.empty() ? 0 : acc.ratio_ppm.max));
    for (auto at : acc.violations.first) out.witnesses.push_back(describe(at, "statement " + name));
  }
  out.counterexamples += r.w_outside.count;
  out.figures.push_back(fig("w_outside_triangle", static_cast<std::int64_t>(r.w_outside.count)));
  for (auto at : r.w_outside.first) out.witnesses.push_back(describe(at, "w outside the closed triangle"));
  out.result = out.counterexamples == 0 ? verdict::proven : verdict::refuted;
  out.note =
      "brute force of the bound's per-channel statements under gouraud_setup=plane_steps (A) sigma*L_c(p) < "
      "sigma*P_c(p) + W, (B) < sigma*P_c(p) + 1 + a + b, "
      "(C) < sigma*P_c(w) + W, and w in the closed triangle, for both wrap sides, against the exact rational plane, on "
      "lattice triangles of the full window x 4 lights of L_122 (every pixel centre in each closed triangle)";
  return out;
}

// What interpolated_under found, for its note.
struct findings {
  int proven_safe, bound_safe, certified, first_wrap;
  bool paper_wraps;
  std::vector<int> wrapping_s;
  double lowest_lag;
  int limit;  // the least s of a relaxation witness above the threshold (0: none)
  std::string limit_text;
  bool next_bracketed;
  two_pass::triangle::certify::next_s_survey next;
  std::size_t normals;
};

std::string settled(const findings& f) {
  return f.first_wrap > f.proven_safe + 1
             ? "s = " + s_ranges({f.proven_safe + 1, f.first_wrap - 1}) + " is bracketed, not settled"
             : std::string("the bound meets the lowest certificate");
}

// The note under a set-up other than plane_steps: how far a pixel's light is from the plane, the bound's s.
std::string set_up_note(const gs::model_options& o, const findings& f) {
  const std::string setup(gs::option_value(o, "gouraud_setup"));
  const std::string w = std::to_string(two_pass::triangle::lag_window(o));
  const std::string how =
      o.setup == gs::gouraud_setup::per_pixel ? "the exact plane at every pixel, its distance from vertex 0 truncated "
                                                "to whole 8.7 units: a pixel's light is within one unit per channel"
      : o.setup == gs::gouraud_setup::per_pixel_floor
          ? "the exact plane at every pixel, floored to whole 8.7 units: a pixel's light is within one unit per "
            "channel"
      : o.setup == gs::gouraud_setup::per_pixel_level
          ? "the exact plane plus 1/256 level floored to a whole level: within 128 units per channel"
          : "each row from the plane at its first pixel, truncated 16-bit lane offsets and vector steps: within " + w +
                " units per channel where no step saturates; where one does (a steep row's second vector) each "
                "channel "
                "takes a value between the row's first pixel's and its own, so the light is only in the cube of the "
                "vertex lights' ball";
  return "under gouraud_setup=" + setup + " (" + how +
         ") of a convex combination of the vertex lights; the bound "
         "(two_pass_triangle's lag_window = " +
         w + ") proves no s <= " + std::to_string(f.proven_safe) +
         " wraps; wraps are certified at s = " + s_ranges(f.wrapping_s) +
         " (the lowest, s = " + std::to_string(f.first_wrap) + "); " + settled(f) +
         ". The paper's s = " + std::to_string(paper_s) +
         (f.paper_wraps              ? " wraps"
          : f.proven_safe >= paper_s ? " is safe"
                                     : " is not settled") +
         " under this set-up";
}

// The note under plane_steps: the lag, the bound and its certified relaxation, the certificates, the searches.
std::string plane_steps_note(const findings& f) {
  char lag_text[16];
  std::snprintf(lag_text, sizeof lag_text, "%.1f", f.lowest_lag);
  const std::string certified_text =
      f.certified > f.bound_safe
          ? "; for the classes it leaves open (|n| sorted, wrap side) up to s = " + std::to_string(f.certified) +
                " the continuous relaxation of its per-channel statements (real vertices, real lights in the ball) is "
                "certified "
                "below the wrap threshold: a dual with the alignment signs as constraints over rectangles of the five "
                "geometry "
                "families, checked in exact integers (two_pass_triangle/triangle_certify.hpp; run by ctest "
                "proofs_certify_survey, "
                "not by "
                "prove: ~40 s under keep_fraction, ~60 s under truncate_to_8)"
          : std::string();
  return "on whole triangles the paper's s = " + std::to_string(paper_s) +
         (f.paper_wraps ? " wraps" : " is not shown to wrap") +
         ": a pixel ~2030 pixels from the plane's reference pixel "
         "misses the truncated fraction of each 8.7 step, up to 16 levels per channel and axis, and that pushes its "
         "light "
         "out of the vertex sphere along the normal. Wraps are certified at s = " +
         s_ranges(f.wrapping_s) +
         " (certificates, each a refutation at its s; the lowest s = " + std::to_string(f.first_wrap) +
         "). No s <= " + std::to_string(f.proven_safe) +
         " wraps: the error bound (one axis's lag, 16 levels, per channel; two axes' only on "
         "channels whose plane falls along both axes, and not on all channels at once, and then weighed against a "
         "second "
         "point of the vertex lights' ball that the falling plane passes) proves s <= " +
         std::to_string(f.bound_safe) + " for every normal" + certified_text + ". " + settled(f) +
         (f.next_bracketed ? " (at s = " + std::to_string(f.next.s) + " the relaxation certifies all but " +
                                 std::to_string(f.next.uncertified) + " of the " + std::to_string(f.next.classes) +
                                 " classes the bound leaves open, ctest proofs_certify_next_s: "
                                 "a wrap there needs one of their " +
                                 std::to_string(f.next.normals) + " normals, of the " + std::to_string(f.normals) + ")"
                           : std::string()) +
         ": the lowest certificate (s = " + std::to_string(f.first_wrap) + ") puts its pixel's light " + lag_text +
         " levels from the light of the vertex next to it" +
         (f.lowest_lag > 2047.0 / 128 ? " (more than one axis's 2047/128: its plane lags along both axes)"
                                      : " (one axis's lag)") +
         "; the searches (tools/proofs_triangle two-axis, corner and steep; the local search, steep's planners and "
         "the free-x search of commit 9f63566's bench/proofs_triangle_*) found no wrap below " +
         std::to_string(f.first_wrap) + "." + f.limit_text +
         (f.limit > 0 ? std::string(", so s = ") + std::to_string(f.limit) +
                            " and above can only be settled with the lattice (integer "
                            "lights, the whole-unit steps' lattice of gradients, 12.4 vertices; the floors' and the "
                            "truncation's integer slack are in the bound already)"
                      : std::string());
}

outcome interpolated_under(const gs::model_options& o, const sweep_config& cfg) {
  // Domain: every triangle the GS can draw in its 2048² window (vertices in 12.4), three vertex
  // lights of L_s (packed_lights), every pixel it covers, the light from gs::gouraud_triangle with
  // the pipeline's reference pixel (two_pass_triangle.hpp), against every Appendix 2 normal. Far too
  // large to enumerate; settled by:
  // (1) safe s: the error bound of two_pass::triangle::cannot_wrap (argument beside it): a pixel's
  //     light is a plane value of the triangle (a convex combination of the vertex lights) plus less
  //     than W = 2048 8.7 units per channel, or 2W − 1 on the channels whose plane falls along both
  //     axes, and not on all of them at once (then the lag is paid by a point of the edge between
  //     the least-x and least-y vertices); where they are not, the two-axis lag is charged to the
  //     curvature: it needs the plane to fall along both axes, so a second plane point, also in the
  //     vertex lights' ball, lies that much further along those channels ((iii) of the bound).
  //     Evaluated per normal for every s.
  // (2) wraps: certificates (above), re-verified here; each refutes "s avoids wrapping" at its s.
  //     Spans are the special case of a thin triangle; the old span bound (no wrap for s <= 123 on
  //     spans of <= 128 pixels) does not carry over, because the lag grows with the distance from
  //     the reference pixel (up to 2047/128 levels per axis), not with the span's 128 pixels.
  if (cfg.brute_force) return interpolated_brute_force(o, cfg);
  const auto& normals = appendix2_normals();
  const int bound_safe = two_pass::triangle::bound_safe_s(o, cfg.domain.light == domain_options::tolight::attenuated);
  // (1') plane_steps: from there, the relaxation of the bound's statements certified class by class
  // (two_pass_triangle/relaxation_classes.hpp; re-run by ctest proofs_certify_survey, too slow for prove).
  const int certified = two_pass::triangle::certify::certified_relaxation_s(o);
  const int proven_safe = std::max(bound_safe, certified);
  int first_wrap = 128;
  const triangle_case* lowest = nullptr;
  std::vector<int> wrapping_s;
  std::vector<std::string> witnesses;
  tally failed, wrapping;
  std::uint64_t index = 0;
  for (const auto& c : two_pass::triangle::certificates()) {
    const auto p = paper::pack_normal_from(c.iX, c.iY);
    bool ok = c.iX * c.iX + c.iY * c.iY <= 16358;
    for (const auto& l : c.light) ok = ok && is_packed_light(c.s, l);
    for (int v : c.xy16) ok = ok && v >= 0 && v <= (two_pass::triangle::window_pixels - 1) * 16;
    const auto r = two_pass::pixel(p, two_pass::triangle::pixel_light(c, o.setup), o);
    if (ok && r.dot != r.value) {
      if (c.s < first_wrap) first_wrap = c.s, lowest = &c;
      wrapping_s.push_back(c.s);
      wrapping.add(index);
      witnesses.push_back(describe_certificate(c, o));
    } else {
      failed.add(index);
    }
    ++index;
  }
  // the lowest wrapping certificate's lag: its pixel's light against the light of the vertex nearest
  // the pixel, in levels, the largest over the channels
  double lowest_lag = 0;
  if (lowest != nullptr) {
    const triangle_case& c = *lowest;
    auto dist2 = [&](std::size_t k) {
      const double dx = c.xy16[2 * k] / 16.0 - c.px, dy = c.xy16[2 * k + 1] / 16.0 - c.py;
      return dx * dx + dy * dy;
    };
    std::size_t near = 0;
    for (std::size_t k = 1; k < 3; ++k)
      if (dist2(k) < dist2(near)) near = k;
    const auto light = two_pass::triangle::pixel_light(c, o.setup);
    const int Lc[3] = {light.r.value(), light.g.value(), light.b.value()};
    for (std::size_t ch = 0; ch < 3; ++ch)
      lowest_lag = std::max(lowest_lag, std::abs(Lc[ch] / 128.0 - 128 - c.light[near][ch]));
  }
  const bool paper_wraps = std::find(wrapping_s.begin(), wrapping_s.end(), paper_s) != wrapping_s.end();
  // How far the bound's own statements can go: the least s of a relaxation witness (real geometry,
  // real lights in the ball) above the threshold under this option (triangle_relaxation.hpp). The
  // witnesses charge the plane_steps lag; the other set-ups have none.
  const bool per_pixel = o.setup != gs::gouraud_setup::plane_steps;
  int limit = 0;
  double limit_margin = 0;
  if (!per_pixel) {
    const two_pass::table t(o);
    for (const auto& w : two_pass::triangle::relaxation_witnesses()) {
      if (w.gouraud != o.gouraud) continue;
      const double m = two_pass::triangle::relaxation_margin(w, t, o);
      if (m > 0 && (limit == 0 || w.s < limit)) limit = w.s, limit_margin = m;
    }
  }
  std::string limit_text;
  if (limit > 0) {
    char margin[32];
    std::snprintf(margin, sizeof margin, "%.1f", limit_margin);
    limit_text = " The bound's statements themselves admit a wrap from s = " + std::to_string(limit) +
                 " (relaxation witness: real vertices and real lights in the ball, " + margin +
                 " levels·|n| over the threshold; two_pass_triangle's relaxation_witnesses)";
  }
  // What the relaxation leaves at the bracketed s (stored; ctest proofs_certify_next_s re-derives it).
  auto next = two_pass::triangle::certify::uncertified_next_s(o);
  const bool next_bracketed = next.s == proven_safe + 1 && next.s < first_wrap;
  if (!next_bracketed) next = {};
  outcome out;
  out.result = paper_wraps ? verdict::refuted : verdict::bound;
  out.domain_size =
      normals.size() * static_cast<std::uint64_t>(proven_safe + 1) + two_pass::triangle::certificates().size();
  out.counterexamples = wrapping.count;
  out.figures = {fig("s_max", proven_safe),
                 fig("s_max_upper", first_wrap - 1),
                 fig("first_wrapping_s", first_wrap),
                 fig("paper_s", paper_s),
                 fig("window_pixels", two_pass::triangle::window_pixels),
                 fig("certificates_not_wrapping", static_cast<std::int64_t>(failed.count)),
                 fig("normals", static_cast<std::int64_t>(normals.size())),
                 fig("bound_limit_s", limit),
                 fig("bound_s_max", bound_safe),
                 fig("relaxation_certified_s", certified),
                 fig("s_max_upper_classes", next.classes),
                 fig("s_max_upper_classes_uncertified", next.uncertified),
                 fig("s_max_upper_normals", next.normals)};
  out.witnesses = std::move(witnesses);
  const findings f{proven_safe, bound_safe, certified,  first_wrap,     paper_wraps, wrapping_s,
                   lowest_lag,  limit,      limit_text, next_bracketed, next,        normals.size()};
  out.note = per_pixel ? set_up_note(o, f) : plane_steps_note(f);
  return for_domain(std::move(out), cfg);
}

// The verdict per evidenced set-up (docs/evidence.md R9) × gouraud_fraction, the other options as
// given: one evaluation each, memoised (a pure function of the options and the domain), so the
// variants of gouraud_setup and gouraud_fraction reuse them.
outcome interpolated_memo(const gs::model_options& o, const sweep_config& cfg) {
  static std::mutex lock;
  static std::map<std::string, outcome> done;
  std::string key;
  for (const auto& row : gs::option_catalogue()) key += std::string(gs::option_value(o, row.name)) + ",";
  key += cfg.domain.light == domain_options::tolight::attenuated ? "attenuated" : "unit";
  if (cfg.brute_force) return interpolated_under(o, cfg);
  {
    const std::lock_guard<std::mutex> g(lock);
    if (const auto it = done.find(key); it != done.end()) return it->second;
  }
  outcome out = interpolated_under(o, cfg);
  const std::lock_guard<std::mutex> g(lock);
  return done.emplace(key, std::move(out)).first->second;
}

}  // namespace

outcome two_pass_max_s_interpolated(const gs::model_options& o, const sweep_config& cfg) {
  outcome out = interpolated_memo(o, cfg);
  // The table is the default run's: drawn when the options the table does not vary (and the domain)
  // are the defaults, so the other options' variant runs (whose tables no ledger prints) cost one
  // evaluation each.
  gs::model_options plain = o;
  plain.setup = gs::model_options{}.setup, plain.gouraud = gs::model_options{}.gouraud;
  if (cfg.brute_force || !(plain == gs::model_options{}) || cfg.domain.light != domain_options{}.light) return out;
  out.table = {
      "| gouraud_setup (sources) | gouraud_fraction | verdict | s_max (proven) | first wrapping s | paper's s = 122 |",
      "|---|---|---|---|---|---|"};
  const char* sources[] = {"0, the model's DDA",     "0", "1 (PCSX2 SSE4)", "1 (PCSX2 AVX2)", "1 (parallel-gs)",
                           "2 (DobieStation, Play!)"};
  for (const char* setup :
       {"per_pixel_floor", "per_pixel", "pcsx2_rows_4", "pcsx2_rows_8", "per_pixel_level", "plane_steps"})
    for (const char* fraction : {"keep_fraction", "truncate_to_8"}) {
      gs::model_options v = o;
      (void)gs::set_option(v, "gouraud_setup", setup);
      (void)gs::set_option(v, "gouraud_fraction", fraction);
      const outcome r = interpolated_memo(v, cfg);
      const std::int64_t first = r.integer("first_wrapping_s");
      const bool wraps = r.result == verdict::refuted;
      out.table.push_back("| `" + std::string(setup) + "` (" + sources[static_cast<int>(v.setup)] + ") | `" + fraction +
                          "` | " + (wraps ? "refuted" : "bound") + " | " + std::to_string(r.integer("s_max")) + " | " +
                          (first > 127 ? std::string("none certified") : std::to_string(first)) + " | " +
                          (wraps                           ? "wraps"
                           : r.integer("s_max") >= paper_s ? "safe"
                                                           : "not settled") +
                          " |");
    }
  return out;
}

}  // namespace gsdot3::proofs::claims
