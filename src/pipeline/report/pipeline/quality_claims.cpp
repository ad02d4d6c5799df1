// pipeline/quality_claims.cpp — the paper's comparative quality sentences on renders (quality_claims.hpp).
#include "pipeline/quality_claims.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>

#include "pipeline/default_scene.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/pixel_walk.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/render.hpp"

namespace gsdot3::pipeline {

namespace {

// Whether the triangle's vertex tolight vectors (T·fade, what section 2 splits into TL_pos / TL_neg)
// have a component of each sign: there max(·, 0) per vertex differs from max(·, 0) per pixel.
bool sign_changes(const prepared_scene& ps, std::size_t light, const prepared_triangle& t) {
  for (int c = 0; c < 3; ++c) {
    bool pos = false, neg = false;
    for (std::uint32_t v : t.vertex) {
      const light_vertex& l = ps.lights[light][v];
      const float x = l.T[c] * l.fade;
      pos = pos || x > 0;
      neg = neg || x < 0;
    }
    if (pos && neg) return true;
  }
  return false;
}

// SplitMix64 (Steele, Lea, Flood 2014): the same stream on every platform, unlike <random>'s
// distributions; uniform doubles from the top 53 bits.
struct splitmix {
  std::uint64_t x;
  std::uint64_t next() {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1p-53; }
  int between(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
};

glm::vec3 on_sphere(splitmix& r, double radius, double min_y, double max_y) {
  const double y = r.uniform(min_y, max_y), phi = r.uniform(0, 2 * std::numbers::pi), c = std::sqrt(1 - y * y);
  return {static_cast<float>(radius * c * std::sin(phi)), static_cast<float>(radius * y),
          static_cast<float>(radius * c * std::cos(phi))};
}

const method_errors* find(const quality_scene& s, method m, map_read map) {
  const auto it = std::find_if(s.methods.begin(), s.methods.end(),
                               [&](const method_errors& e) { return e.m == m && e.map == map; });
  return it == s.methods.end() ? nullptr : &*it;
}
const method_errors& of(const quality_scene& s, method m, map_read map) {
  if (const method_errors* e = find(s, m, map)) return *e;
  throw std::logic_error("quality rows: scene '" + s.name + "' has no " + label(m, map) + " render");
}

struct claim_def {
  const char* id;
  const char* paper;
  method better, other;
  bool dot_product_metrics;  // the unnormalised-product metrics apply (both methods skip normalisation)
  bool speed;                // the sentence claims speed too
  map_read better_map = map_read::own_map, other_map = map_read::own_map;
  bool edges = false;  // the sentence names edge highlighting (the edge_highlighting metric applies)
};
const claim_def claims[] = {
    {"quality.two-pass-vs-2002",
     "seed 000 §3: the proposed signed multiplication \"improves the speed and quality compared to [Breugelmanns02]\"; "
     "two-pass does it \"in two passes without the per vertex clamping problem\" (§2, figure 1)",
     method::two_pass, method::baseline, true, true},
    {"quality.four-pass-vs-2002", "seed 000 §3: the same sentence for the four-pass method (per-pixel normalised)",
     method::four_pass, method::baseline, false, true},
    {"quality.four-pass-vs-two-pass",
     "seed 000 §3.6, figure 7: renormalising per pixel removes two-pass's intensity loss across a triangle and its "
     "edge highlighting",
     method::four_pass, method::two_pass, false, false, map_read::own_map, map_read::own_map, true},
    {"quality.three-pass-vs-two-pass",
     "seed 000 §3.5: \"to completely avoid the precision loss [of n'_a = (n_a + 1)/3], one could also do a three-pass "
     "solution by adding the terms as a separate additive pass, but it is probably not worth it\"",
     method::three_pass, method::two_pass, true, false},
    {"quality.three-maps-vs-palettised",
     "seed 000 §3.6: \"A quantized 8 bit normal map can be used with three palettes or alternatively three 8 bit "
     "normal maps, which will give the same quality as using a standard 24 bit normal map\" (both four-pass against "
     "the float reference of the unquantised normals)",
     method::four_pass, method::four_pass, false, false, map_read::three_maps, map_read::palettised},
};

}  // namespace

std::vector<std::string> quality_claim_ids() {
  std::vector<std::string> ids;
  for (const claim_def& c : claims) ids.emplace_back(c.id);
  return ids;
}

std::string label(method m, map_read map) {
  switch (map) {
    case map_read::own_map: return std::string(name(m));
    case map_read::palettised: return std::string(name(m)) + ", 8-bit map vs unquantised";
    case map_read::three_maps: return std::string(name(m)) + ", three 8-bit maps vs unquantised";
  }
  throw std::logic_error("unknown map_read");
}

method_errors measure_errors(method m, const frame& f, const reference_frame& ref, const prepared_scene& ps,
                             map_read map) {
  method_errors e{m, map};
  e.pixel_ops = f.pixel_ops;
  double sr = 0, su = 0, sdr = 0, srr = 0, sdd = 0, ss = 0;
  for (std::size_t l = 0; l < ref.unnormalised.size(); ++l)
    for (std::size_t i = 0; i < ref.unnormalised[l].size(); ++i) {
      const double u = ref.unnormalised[l][i];
      if (std::isnan(u)) continue;
      const double d = dot_value(f.dot[l][i]), r = ref.renormalised[l][i];
      ++e.samples;
      sr += (d - r) * (d - r);
      su += (d - u) * (d - u);
      sdr += d * u;
      srr += u * u;
      sdd += d * d;
      const auto t = f.visible_triangle[i];
      if (t >= 0 && sign_changes(ps, l, ps.triangles[static_cast<std::size_t>(t)])) {
        ++e.sign_change_samples;
        ss += (d - u) * (d - u);
      }
    }
  if (e.samples == 0) return e;
  const double n = static_cast<double>(e.samples);
  e.vs_renormalised = std::sqrt(sr / n);
  e.vs_unnormalised = std::sqrt(su / n);
  e.gain = srr > 0 ? sdr / srr : 0;
  // Σ(d − g·u)² = Σd² − 2gΣdu + g²Σu², which at g = Σdu/Σu² is Σd² − (Σdu)²/Σu².
  e.after_gain = std::sqrt(std::max(0.0, sdd - e.gain * sdr) / n);
  e.sign_change = e.sign_change_samples > 0 ? std::sqrt(ss / static_cast<double>(e.sign_change_samples)) : 0;
  // Edge highlighting: the mean error near the edges against the mean error inside, over the lights.
  double edge = 0, inside = 0;
  for_each_covered_pixel(ps, f.visible_triangle, [&](const pixel_sample& p) {
    const double least = std::min({p.lambda.x, p.lambda.y, p.lambda.z});
    if (least >= 0.1 && least <= 0.25) return;
    for (std::size_t l = 0; l < ref.renormalised.size(); ++l) {
      const double r = ref.renormalised[l][p.index];
      if (std::isnan(r)) continue;
      const double err = dot_value(f.dot[l][p.index]) - r;
      if (least < 0.1)
        edge += err, ++e.edge_samples;
      else
        inside += err, ++e.inside_samples;
    }
  });
  if (e.edge_samples > 0 && e.inside_samples > 0)
    e.edge_highlighting =
        std::fabs(edge / static_cast<double>(e.edge_samples) - inside / static_cast<double>(e.inside_samples));
  return e;
}

quality_scene measure_quality(const std::string& name, const scene& s, const render_options& o) {
  const prepared_scene ps = prepare(s, 0.0f, o.specular);
  quality_scene q{name, {}};
  std::vector<frame> frames;
  for (method m : gs_methods) frames.push_back(render(s, ps, m, o));
  const reference_frame ref = render_reference(s, ps, frames.front().visible_triangle, o.bilinear, o.specular_power);
  for (std::size_t k = 0; k < frames.size(); ++k)
    q.methods.push_back(measure_errors(gs_methods[k], frames[k], ref, ps));
  // Section 3.6: four-pass's 8-bit palettised frame and its three 8-bit component maps' frame, both
  // against the reference of the normals the palette was quantised from.
  scene wide = s;
  wide.normals = with_index_bits(s.normals, 24);
  const reference_frame unquantised =
      render_reference(wide, ps, frames.front().visible_triangle, o.bilinear, o.specular_power);
  const auto four = static_cast<std::size_t>(
      std::find(std::begin(gs_methods), std::end(gs_methods), method::four_pass) - std::begin(gs_methods));
  q.methods.push_back(measure_errors(method::four_pass, frames.at(four), unquantised, ps, map_read::palettised));
  q.methods.push_back(
      measure_errors(method::four_pass, render(wide, ps, method::four_pass, o), unquantised, ps, map_read::three_maps));
  return q;
}

scene random_quality_scene(std::uint64_t seed, int width, int height) {
  splitmix r{seed};
  scene s = default_scene(128);
  s.model = head_mesh(r.between(6, 20), r.between(8, 24));
  s.width = width;
  s.height = height;
  s.lights.clear();
  const int lights = r.between(1, 3);
  for (int l = 0; l < lights; ++l) {
    const auto g = static_cast<std::uint8_t>(r.between(0x20, 0xB0));
    s.lights.push_back({on_sphere(r, r.uniform(1.6, 4.0), -0.6, 0.9), {0x10, g, static_cast<std::uint8_t>(0xC0 - g)}});
  }
  s.view.eye = on_sphere(r, r.uniform(3.0, 4.5), -0.3, 0.4);
  return s;
}

std::vector<quality_row> quality_rows(const std::vector<quality_scene>& scenes) {
  struct metric_def {
    const char* name;
    double method_errors::*field;
    bool dot_product, speed, edges;
  };
  const metric_def metrics[] = {{"rmse_vs_renormalised", &method_errors::vs_renormalised, false, false, false},
                                {"rmse_vs_unnormalised", &method_errors::vs_unnormalised, true, false, false},
                                {"rmse_after_gain", &method_errors::after_gain, true, false, false},
                                {"rmse_sign_change_triangles", &method_errors::sign_change, true, false, false},
                                {"edge_highlighting", &method_errors::edge_highlighting, false, false, true},
                                {"gs_pixel_ops", nullptr, false, true, false}};
  std::vector<quality_row> rows;
  for (const claim_def& c : claims)
    for (const metric_def& m : metrics) {
      if ((m.dot_product && !c.dot_product_metrics) || (m.speed && !c.speed) || (m.edges && !c.edges)) continue;
      if (scenes.empty() || !find(scenes.front(), c.better, c.better_map) ||
          !find(scenes.front(), c.other, c.other_map))
        continue;
      quality_row row{c.id, c.paper, m.name, label(c.better, c.better_map), label(c.other, c.other_map), {}, 0, {}};
      for (const quality_scene& s : scenes) {
        const method_errors &b = of(s, c.better, c.better_map), &o = of(s, c.other, c.other_map);
        const double vb = m.field ? b.*m.field : static_cast<double>(b.pixel_ops);
        const double vo = m.field ? o.*m.field : static_cast<double>(o.pixel_ops);
        row.per_scene.emplace_back(vb, vo);
        row.holds_on += vb < vo ? 1 : 0;
      }
      const std::size_t n = row.per_scene.size();
      const bool all_equal =
          std::all_of(row.per_scene.begin(), row.per_scene.end(), [](const auto& p) { return p.first == p.second; });
      row.verdict = row.holds_on == n   ? "holds"
                    : all_equal         ? "refuted (equal on every scene)"
                    : row.holds_on == 0 ? "refuted"
                                        : "mixed (" + std::to_string(row.holds_on) + " of " + std::to_string(n) + ")";
      rows.push_back(row);
    }
  return rows;
}

}  // namespace gsdot3::pipeline
