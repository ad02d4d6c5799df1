// pipeline/report.hpp — comparing the GS renders with the float reference, in numbers (JSON, HTML
// tables) and in pictures (PNG frames, dot-product buffers, error heat maps, a figure-7 montage).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/console_time.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline {

// Error of a method's dot products against a float reference over covered pixels and lights, in
// 1/128 units: e = dot_value(byte) − reference. PSNR uses the 8-bit peak 255. A wrap error is a
// pixel with |e| > 128: only a modulo-256 wrap of the sum can put the value that far away.
struct error_stats {
  std::size_t samples = 0;
  double max_abs = 0, mean = 0, mean_abs = 0, rmse = 0, psnr = 0, within_1 = 0;
  std::size_t wraps = 0;
};
// `counted`: the lights whose samples count (empty: every light); the report counts those a method
// draws itself (lod.hpp's light_method), leaving --lod-fade's Gouraud halves to gouraud's figures.
error_stats compare(const std::vector<std::vector<std::uint8_t>>& dot, const std::vector<std::vector<float>>& reference,
                    const std::vector<bool>& counted = {});
// The same statistics for float values x (a scheme's dot products, or the reference itself) minus the
// reference; `clamp_reference_at_zero` compares with max(reference, 0) instead.
error_stats compare(const std::vector<std::vector<float>>& x, const std::vector<std::vector<float>>& reference,
                    bool clamp_reference_at_zero = false);

struct report_request {
  std::filesystem::path out_dir = "gsdot3-out";
  std::vector<method> methods{std::begin(gs_methods), std::end(gs_methods)};
  std::vector<const scheme_method*> schemes;  // the other seeds' methods (scheme_method.hpp)
  render_options options{};
  std::string scene_description = "embedded procedural scene";
  bool write_html = true;                            // false: `render` (images + JSON only)
  std::function<void(const std::string&)> progress;  // one line of stderr progress
  std::string input_json, input_html;                // input_report.hpp; empty: no "input" entry
  std::optional<gs::cost::cost_options> cost;        // price each GS method's frame (console_time.hpp)
};

struct method_result {
  method m;
  double seconds = 0;
  error_stats vs_renormalised, vs_unnormalised;
  console_time ps2;  // when report_request::cost
};

struct scheme_result {
  const scheme_method* m = nullptr;
  double seconds = 0;
  error_stats vs_renormalised, vs_unnormalised;  // against max(reference, 0) when m->non_negative
};

struct report_summary {
  std::vector<method_result> methods;
  std::vector<scheme_result> schemes;
  double reference_seconds = 0;
  error_stats normalisation;  // unnormalised − renormalised reference
  // Why the frames disagree with the renormalised reference for a reason other than fixed-point
  // arithmetic (normalisation_warning), or empty.
  std::string warning;
  std::filesystem::path html, json;
};

// The RMSE (1/128 units) of the float reference's own normalisation error above which the report
// says that interpolating per-vertex vectors, not the methods' arithmetic, dominates their error:
// the largest RMSE of a GS method against the unnormalised reference on the embedded scene is
// about 2, so above 4 most of a method's error against the renormalised one is normalisation.
inline constexpr double normalisation_warning_rmse = 4.0;
// `four_pass_brighter`: four-pass was drawn and its mean error is positive and above every other
// method's (box.uc with smooth normals); the warning then says why.
std::string normalisation_warning(const error_stats& normalisation, bool four_pass_brighter);

// Renders, compares and writes everything into a staged folder that becomes out_dir only when all
// is written (staged_directory: nothing half written; a previous out_dir is replaced whole, so it holds
// exactly this run's files). Throws std::runtime_error (one line, naming out_dir, never the staged
// folder) when the directory cannot be written or the frame shows no pixel of the mesh (with what to try).
report_summary write_report(const scene& s, const report_request& r);

}  // namespace gsdot3::pipeline
