// pipeline/report.cpp — statistics, images and the HTML/JSON report (see report.hpp).
#include "pipeline/report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "gs_cost/cost_json.hpp"
#include "pipeline/files.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/memory_picture.hpp"
#include "pipeline/memory_steps.hpp"
#include "pipeline/performance_claims.hpp"
#include "pipeline/pixel_walk.hpp"
#include "pipeline/quality_claims.hpp"
#include "pipeline/report_images.hpp"
#include "pipeline/report_page.hpp"
#include "pipeline/render.hpp"

namespace gsdot3::pipeline {

namespace {

// Step 5's pixels of a frame: how many, and the largest per-channel difference of their colour from
// the float Gouraud the reference composes there (compose_plain).
nlohmann::json step5_json(const frame& f, const std::vector<std::uint32_t>& reference) {
  std::size_t pixels = 0;
  int worst = 0;
  for (std::size_t i = 0; i < f.colour.size(); ++i) {
    if (f.plain_triangle[i] < 0) continue;
    ++pixels;
    for (int c = 0; c < 24; c += 8)
      worst = std::max(
          worst, std::abs(static_cast<int>((f.colour[i] >> c) & 0xFF) - static_cast<int>((reference[i] >> c) & 0xFF)));
  }
  return {{"pixels", pixels}, {"colour_max_abs_vs_float_gouraud", worst}};
}

using report_images::error_map;
using report_images::grey_image;
using report_images::heat_limit;
using report_images::montage;
using report_images::reference_bytes;
using report_images::rgb_image;

struct accumulator {
  error_stats s;
  double sum = 0, sum_abs = 0, sum_sq = 0;
  std::size_t near = 0;
  void add(double e) {
    ++s.samples;
    sum += e;
    sum_abs += std::fabs(e);
    sum_sq += e * e;
    s.max_abs = std::max(s.max_abs, std::fabs(e));
    if (std::fabs(e) <= 1.0) ++near;
    if (std::fabs(e) > 128.0) ++s.wraps;
  }
  error_stats done() {
    if (s.samples == 0) return s;
    const double n = static_cast<double>(s.samples);
    s.mean = sum / n;
    s.mean_abs = sum_abs / n;
    s.rmse = std::sqrt(sum_sq / n);
    s.psnr = s.rmse > 0 ? 20.0 * std::log10(255.0 / s.rmse) : INFINITY;
    s.within_1 = static_cast<double>(near) / n;
    return s;
  }
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json to_json(const error_stats& s) {
  return {{"samples", s.samples},   {"max_abs", s.max_abs},
          {"mean", s.mean},         {"mean_abs", s.mean_abs},
          {"rmse", s.rmse},         {"psnr_db", std::isfinite(s.psnr) ? nlohmann::json(s.psnr) : nlohmann::json("inf")},
          {"within_1", s.within_1}, {"wrap_errors", s.wraps}};
}

// Why a frame shows no pixel of the mesh, and what to try: a black frame with "RMSE 0" would say
// nothing of the methods.
std::string nothing_drawn(const scene& s, const prepared_scene& front) {
  const std::size_t n = s.model.triangles.size();
  return "the frame shows no pixel of the mesh: of its " + std::to_string(n) + " triangle(s) " +
         std::to_string(front.culled_back) + " face away from the camera (back faces are culled), " +
         std::to_string(front.dropped_outside) + " lie outside the view, " + std::to_string(front.triangles.size()) +
         " are drawn but cover no pixel centre; try another --view AZIMUTH,ELEVATION "
         "(e.g. --view 180,0), a larger --size, or check the file's winding (front faces are counter-clockwise)";
}

}  // namespace

error_stats compare(const std::vector<std::vector<std::uint8_t>>& dot, const std::vector<std::vector<float>>& ref,
                    const std::vector<bool>& counted) {
  accumulator a;
  for (std::size_t l = 0; l < ref.size(); ++l)
    for (std::size_t i = 0; i < ref[l].size() && (counted.empty() || counted[l]); ++i)
      if (!std::isnan(ref[l][i])) a.add(dot_value(dot[l][i]) - static_cast<double>(ref[l][i]));
  return a.done();
}

error_stats compare(const std::vector<std::vector<float>>& x, const std::vector<std::vector<float>>& ref,
                    bool clamp_reference_at_zero) {
  accumulator a;
  for (std::size_t l = 0; l < ref.size(); ++l)
    for (std::size_t i = 0; i < ref[l].size(); ++i)
      if (!std::isnan(ref[l][i])) {
        const double r =
            clamp_reference_at_zero ? std::max(0.0, static_cast<double>(ref[l][i])) : static_cast<double>(ref[l][i]);
        a.add(static_cast<double>(x[l][i]) - r);
      }
  return a.done();
}

std::string normalisation_warning(const error_stats& n, bool four_pass_brighter) {
  if (!(n.rmse > normalisation_warning_rmse)) return "";
  char figures[96];
  std::snprintf(figures, sizeof figures, "RMSE %.1f, max %.1f", n.rmse, n.max_abs);
  std::string text =
      std::string("the float reference's own normalisation error is large (") + figures +
      " /128): the vertices' tangent-space light vectors differ so much across each triangle that their "
      "interpolation, which every method here draws with (per vertex, as the paper's do), is far from the "
      "per-pixel vector, so the methods' errors against the renormalised reference are mostly this, not "
      "fixed-point error (compare them with the unnormalised reference)";
  if (four_pass_brighter)
    text.append(
        "; four-pass, brighter than the others here, interpolates sphere-map coordinates instead, which stay "
        "unit length");
  text.append(
      ". The usual cause is one smooth normal per corner across hard edges (a cube): give the file split "
      "normals, or, when it has none, a smaller --crease-angle (the edges sharper than it are split) or "
      "--normals flat");
  return text;
}

namespace {

// write_report's work, every file into `staged`.
report_summary write_staged(const scene& s, const report_request& r, staged_directory& staged) {
  namespace fs = std::filesystem;
  auto say = [&](const std::string& m) {
    if (r.progress) r.progress(m);
  };
  const fs::path& dir = staged.path();
  report_summary sum;
  sum.html = r.out_dir / "report.html";
  sum.json = r.out_dir / "report.json";
  const int w = s.width, h = s.height;

  say("preparing the scene (" + std::to_string(s.model.triangles.size()) + " triangles, " + std::to_string(w) + "x" +
      std::to_string(h) + ")");
  const prepared_scene front = prepare(s, 0.0f, r.options.specular);
  if (front.triangles.empty()) throw std::runtime_error(nothing_drawn(s, front));

  std::vector<frame> frames;
  for (method m : r.methods) {
    say(std::string("rendering ") + std::string(name(m)) + " through the GS model");
    const auto t0 = std::chrono::steady_clock::now();
    frames.push_back(render(s, front, m, r.options));
    sum.methods.push_back({m, seconds_since(t0), {}, {}, {}});
    if (r.cost) {
      say(std::string("pricing ") + std::string(name(m)) + " on the console's GS (its dump's packet stream, gs_cost)");
      sum.methods.back().ps2 = price_frame(s, front, m, r.options, *r.cost);
      if (!sum.methods.back().ps2.frame) say("  not priced: " + sum.methods.back().ps2.not_priced);
    }
  }
  say("rendering the float reference");
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<std::int32_t>& visible = frames.front().visible_triangle;
  if (std::none_of(visible.begin(), visible.end(), [](std::int32_t t) { return t >= 0; }))
    throw std::runtime_error(nothing_drawn(s, front));
  const reference_frame ref =
      render_reference(s, front, visible, r.options.bilinear, r.options.specular_power, frames.front().plain_triangle);
  sum.reference_seconds = seconds_since(t0);
  sum.normalisation = compare(ref.unnormalised, ref.renormalised);
  bool four_pass_brighter = false;  // four-pass's mean error above every other GS method's, and positive
  for (std::size_t k = 0; k < frames.size(); ++k) {
    // A method's figures count the lights it draws: section 3.8's Gouraud halves (--lod-fade) are
    // gouraud's dot products, which gouraud's own figures give.
    std::vector<bool> counted;
    for (const scene_light& l : s.lights) counted.push_back(light_method(sum.methods[k].m, l) == sum.methods[k].m);
    sum.methods[k].vs_renormalised = compare(frames[k].dot, ref.renormalised, counted);
    sum.methods[k].vs_unnormalised = compare(frames[k].dot, ref.unnormalised, counted);
  }
  for (const method_result& four : sum.methods)
    if (four.m == method::four_pass && four.vs_renormalised.mean > 0)
      four_pass_brighter = std::all_of(sum.methods.begin(), sum.methods.end(), [&](const method_result& o) {
        return o.m == method::four_pass || o.vs_renormalised.mean < four.vs_renormalised.mean;
      });
  sum.warning = normalisation_warning(sum.normalisation, four_pass_brighter);
  if (!sum.warning.empty()) say(sum.warning);

  say("writing images to " + r.out_dir.string());
  nlohmann::json j;
  j["scene"] = {{"description", r.scene_description},
                {"width", w},
                {"height", h},
                {"triangles", s.model.triangles.size()},
                {"drawn_triangles", front.triangles.size()},
                {"culled_back_facing", front.culled_back},
                {"dropped_outside_guard_band", front.dropped_outside},
                {"normal_map",
                 {{"width", s.normals.width},
                  {"height", s.normals.height},
                  {"palette", s.normals.palette.size()},
                  {"index_bits", s.normals.bits},
                  {"layers", layers(s.normals)}}},
                {"lights", s.lights.size()},
                {"step5_triangles", s.plain.triangles.size()},
                {"drawn_step5_triangles", front.plain.size()}};
  j["options"] = {{"s", r.options.s},
                  {"filter", r.options.bilinear ? "bilinear" : "nearest"},
                  {"specular", r.options.specular},
                  {"specular_power", r.options.specular_power},
                  {"path", r.options.path == raster_path::cached ? "cached" : "reference"},
                  {"threads", r.options.threads}};
  for (const auto& opt : gs::option_catalogue())
    j["options"]["model"][std::string(opt.name)] = std::string(gs::option_value(r.options.model, opt.name));
  if (!r.input_json.empty()) j["input"] = nlohmann::json::parse(r.input_json);
  j["units"] = "dot products in 1/128 (a DPB byte 0x80 + d stands for d/128)";
  j["reference"] = {{"seconds", sum.reference_seconds},
                    {"normalisation_error", to_json(sum.normalisation)},
                    {"warning", sum.warning}};
  if (r.cost)
    j["ps2"] = {{"clock_hz", gs::cost::gs_clock_hz},
                {"options", gs::cost::to_json(*r.cost)},
                {"model", "docs/cost.md: the GS cost model on the frame's dump stream (gsdot3 dump, gsdot3 cost)"}};
  write_png(dir / "reference-lit.png", rgb_image(w, h, ref.colour));
  for (std::size_t l = 0; l < s.lights.size(); ++l)
    write_png(dir / ("reference-dot-light" + std::to_string(l) + ".png"),
              grey_image(w, h, reference_bytes(ref.renormalised[l])));

  for (std::size_t k = 0; k < frames.size(); ++k) {
    method_result& mr = sum.methods[k];
    const std::string nm(name(mr.m));
    j["methods"][nm] = {{"frame_seconds", mr.seconds},
                        {"vs_renormalised", to_json(mr.vs_renormalised)},
                        {"vs_unnormalised", to_json(mr.vs_unnormalised)}};
    if (!front.plain.empty()) j["methods"][nm]["step5"] = step5_json(frames[k], ref.colour);
    if (r.cost)
      j["methods"][nm]["ps2"] =
          mr.ps2.frame ? gs::cost::frame_json(*mr.ps2.frame, false) : nlohmann::json{{"not_priced", mr.ps2.not_priced}};
    write_png(dir / (nm + "-lit.png"), rgb_image(w, h, frames[k].colour));
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const std::string dot = nm + "-dot-light" + std::to_string(l) + ".png",
                        err = nm + "-error-light" + std::to_string(l) + ".png";
      write_png(dir / dot, grey_image(w, h, frames[k].dot[l]));
      write_png(dir / err,
                error_map(
                    w, h, [&](std::size_t i) { return dot_value(frames[k].dot[l][i]); }, ref.renormalised[l]));
    }
  }

  // Seed 000's comparative sentences on this scene (quality_claims.hpp; gsdot3 quality adds random scenes).
  auto rendered = [&](method m) { return std::find(r.methods.begin(), r.methods.end(), m) != r.methods.end(); };
  if (rendered(method::two_pass) && rendered(method::four_pass) && rendered(method::baseline)) {
    quality_scene q{"this scene", {}};
    for (std::size_t k = 0; k < frames.size(); ++k)
      q.methods.push_back(measure_errors(sum.methods[k].m, frames[k], ref, front));
    for (const quality_row& row : quality_rows({q}))
      j["quality_claims"].push_back({{"claim", row.claim},
                                     {"paper", row.paper},
                                     {"metric", row.metric},
                                     {"better", row.better},
                                     {"other", row.other},
                                     {"value_better", row.per_scene.front().first},
                                     {"value_other", row.per_scene.front().second},
                                     {"verdict", row.verdict}});
  }

  // Seed 000's performance sentences priced on this scene (performance_claims.hpp), with --cost.
  if (r.cost && rendered(method::two_pass) && rendered(method::four_pass) && rendered(method::baseline))
    for (const performance_row& row : performance_rows(s, r.options, *r.cost, r.progress))
      j["performance_claims"].push_back({{"claim", row.claim},
                                         {"paper", row.paper},
                                         {"statement", row.statement},
                                         {"figures", row.figures},
                                         {"verdict", row.verdict}});

  // The other seeds' methods on the same geometry (scheme_method.hpp).
  page_inputs page{&s, &front, r.options, r.methods, &frames, &ref, {}, {}, heat_limit, true};
  for (const scheme_method* sm : r.schemes) {
    say(std::string("rendering ") + std::string(sm->name) + " (seed " + std::string(sm->seed) + ")");
    const auto ts = std::chrono::steady_clock::now();
    const scheme_frame sf = sm->render(s, front, visible, r.options);
    scheme_result sr{sm, seconds_since(ts), {}, {}};
    sr.vs_renormalised = compare(sf.dot, ref.renormalised, sm->non_negative);
    sr.vs_unnormalised = compare(sf.dot, ref.unnormalised, sm->non_negative);
    const std::string nm(sm->name);
    j["methods"][nm] = {{"frame_seconds", sr.seconds},
                        {"seed", std::string(sm->seed)},
                        {"summary", std::string(sm->summary)},
                        {"compared_with", sm->non_negative ? "max(reference, 0)" : "reference"},
                        {"vs_renormalised", to_json(sr.vs_renormalised)},
                        {"vs_unnormalised", to_json(sr.vs_unnormalised)}};
    std::vector<std::uint32_t> lit = sf.colour;  // with step 5's geometry, which no scheme changes
    compose_plain(s, front, frames.front().plain_triangle, r.options.bilinear, lit);
    write_png(dir / (nm + "-lit.png"), rgb_image(w, h, lit));
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const std::string dot = nm + "-dot-light" + std::to_string(l) + ".png",
                        err = nm + "-error-light" + std::to_string(l) + ".png";
      std::vector<float> against = ref.renormalised[l];
      if (sm->non_negative)
        for (float& v : against) v = std::isnan(v) ? v : std::max(v, 0.0f);
      write_png(dir / dot, grey_image(w, h, reference_bytes(sf.dot[l])));
      write_png(dir / err, error_map(
                               w, h, [&](std::size_t i) { return static_cast<double>(sf.dot[l][i]); }, against));
    }
    sum.schemes.push_back(sr);
    page.schemes.push_back({nm, std::string(sm->seed), sf.dot, sm->non_negative});
  }

  // Figure 7: two-pass and four-pass, front and back.
  const bool have2 = std::find(r.methods.begin(), r.methods.end(), method::two_pass) != r.methods.end();
  const bool have4 = std::find(r.methods.begin(), r.methods.end(), method::four_pass) != r.methods.end();
  if (have2 && have4) {
    say("rendering the back views for the side-by-side");
    const prepared_scene back = prepare(s, 180.0f, r.options.specular);
    auto lit = [&](const prepared_scene& ps, method m) { return rgb_image(w, h, render(s, ps, m, r.options).colour); };
    write_png(dir / "side-by-side.png", montage(lit(front, method::two_pass), lit(front, method::four_pass),
                                                lit(back, method::two_pass), lit(back, method::four_pass)));
  }

  // GS local memory (gs_memory): the PSMCT32 DPB page read as the PSMT8 texture of the post filter,
  // and whether the memory path gives the frames above bit for bit.
  write_png(dir / "memory-psmct32-as-psmt8.png",
            page_overlay_image(gs::mem::psm::PSMCT32, gs::mem::psm::PSMT8, "channel", 4));
  write_png(dir / "memory-psmct32-as-psmz32.png",
            page_overlay_image(gs::mem::psm::PSMCT32, gs::mem::psm::PSMZ32, "pixel", 4));
  j["options"]["memory_path"] = r.options.memory_path;
  j["options"]["dpb_clear"] = std::string(name(r.options.dpb_clear));
  j["memory"]["pictures"] = {"memory-psmct32-as-psmt8.png", "memory-psmct32-as-psmz32.png"};
  for (const memory_step& st : memory_steps)
    j["memory"]["steps"].push_back(
        {{"step", st.step}, {"does", st.does}, {"memory_path", st.memory_path}, {"value_path", st.value_path}});
  // The memory path may refuse the frame (frame_limits.hpp: its buffers beyond the 4 MiB; step 5 with
  // streamed textures, gs_inputs.hpp's plain_needs_resident_texture): the report says why instead of
  // the pictures.
  try {
    // The first method's frame rendered again on the memory path with a trace: its DPB as the post
    // filter of light 0 reads it, displayed as PSMCT32 and read as PSMT8.
    render_options traced = r.options;
    traced.memory_path = true;
    std::vector<pass_record> trace;
    traced.trace = &trace;
    render(s, front, sum.methods.front().m, traced);
    const dpb_pictures dpb = post_filter_dpb_pictures(trace, w, h, traced.dpb_clear == dpb_clear_mode::z_trick);
    write_png(dir / "memory-dpb-psmct32.png", dpb.display);
    write_png(dir / "memory-dpb-as-psmt8.png", dpb.as_psmt8);
    j["memory"]["dpb_pictures"] = {{"method", std::string(name(sum.methods.front().m))},
                                   {"files", {"memory-dpb-psmct32.png", "memory-dpb-as-psmt8.png"}}};
    render_options other = r.options;
    other.memory_path = !r.options.memory_path;
    other.dpb_clear = dpb_clear_mode::explicit_clear;
    for (std::size_t k = 0; k < frames.size(); ++k) {
      const frame f = render(s, front, sum.methods[k].m, other);
      j["memory"]["memory_path_equals_value_level"][std::string(name(sum.methods[k].m))] =
          f.colour == frames[k].colour && f.dot == frames[k].dot;
    }
  } catch (const std::invalid_argument& e) {
    j["memory"]["not_drawn"] = e.what();
    say(std::string("memory path not drawn: ") + e.what());
  }
  write_file_atomically(dir / "report.json", j.dump(2) + "\n");
  if (r.write_html) {
    say("writing the page and the inspector's per-pixel data");
    page.report_json = j.dump(2);
    write_report_page(dir, page);
  }
  staged.commit();
  return sum;
}

}  // namespace

report_summary write_report(const scene& s, const report_request& r) {
  staged_directory staged(r.out_dir, "report.json");  // nothing reaches out_dir unless the whole report is written
  try {
    return write_staged(s, r, staged);
  } catch (const std::runtime_error& e) { throw std::runtime_error(staged.as_target(e.what())); }
}

}  // namespace gsdot3::pipeline
