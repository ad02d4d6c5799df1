// gsdot3 render / gsdot3 report — whole frames through the modeled GS, compared with the float
// dot product. `report` adds the HTML page; both write PNGs and report.json into --out. The options
// and their parsing: render_args.hpp.
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "render_args.hpp"
#include "pipeline/mesh_export.hpp"
#include "pipeline/report.hpp"

namespace gsdot3::cli {
namespace {

// "; PS2 5.444 ms (802723 GS cycles, 32.6 % of an NTSC field)" or why the frame was not priced.
std::string ps2_text(const pipeline::console_time& t) {
  if (!t.frame) return "; PS2 not priced: " + t.not_priced;
  const std::uint64_t c = t.frame->cycles.total();
  char buf[160];
  std::snprintf(buf, sizeof buf, "; PS2 %.3f ms (%llu GS cycles, %.1f %% of an NTSC field)", gs::cost::seconds(c) * 1e3,
                static_cast<unsigned long long>(c), 100.0 * gs::cost::seconds(c) * gs::cost::ntsc_hz);
  return buf;
}

void run(const render_args& a, bool html, context& ctx) {
  const scene_setup st = setup(a, pipeline::frame_use::render);
  const pipeline::scene_input& in = st.in;
  if (!a.export_mesh.empty()) {
    try {
      pipeline::export_mesh_glb(in.s.model, a.export_mesh);
    } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
    progress("wrote " + a.export_mesh + " (the mesh as drawn: centred and scaled to its unit bounding sphere)");
  }
  pipeline::report_request req;
  req.out_dir = a.out;
  req.methods = st.methods;
  req.schemes = st.schemes;
  req.write_html = html;
  req.options = st.options;
  const pipeline::scene& s = in.s;
  const std::string& description = in.description;
  req.input_json = pipeline::input_json(in.summary);
  req.input_html = pipeline::input_html(in.summary);
  req.scene_description = description;
  req.progress = progress;
  if (a.cost) req.cost = a.cost_model.resolve();
  pipeline::report_summary sum;
  try {
    sum = pipeline::write_report(s, req);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); } catch (const std::invalid_argument& e) {
    throw usage_error(e.what());  // a frame the options ask for that the model does not draw (render.hpp)
  }
  for (const auto& m : sum.methods)
    std::cerr << "gsdot3: " << pipeline::name(m.m) << ": max |e| " << m.vs_renormalised.max_abs << ", RMSE "
              << m.vs_renormalised.rmse << ", within ±1 " << 100.0 * m.vs_renormalised.within_1 << "%, wraps "
              << m.vs_renormalised.wraps << ", frame " << m.seconds * 1000.0 << " ms" << (a.cost ? ps2_text(m.ps2) : "")
              << "\n";
  for (const auto& m : sum.schemes)
    std::cerr << "gsdot3: " << m.m->name << ": max |e| " << m.vs_renormalised.max_abs << ", RMSE "
              << m.vs_renormalised.rmse << ", within ±1 " << 100.0 * m.vs_renormalised.within_1 << "%, frame "
              << m.seconds * 1000.0 << " ms\n";
  std::cout << (html ? sum.html : sum.json).string() << "\n";
  ctx.exit_code = 0;
}

}  // namespace

constexpr const char* export_mesh_help =
    "also write the mesh the renderer drew (centred and scaled to its unit bounding sphere, as drawn) as OUT.glb: "
    "NORMAL, TANGENT (w = handedness) and TEXCOORD_0, for Blender or any glTF viewer";

void add_cost_options(CLI::App* cmd, render_args& a) {
  cmd->add_flag("--cost", a.cost,
                "also price each GS method's frame on the console's GS (the stream gsdot3 dump writes, priced as "
                "gsdot3 cost prices it; docs/cost.md): report.json methods.M.ps2 and the page's bar chart");
  a.cost_model.add_to(cmd);
}

void add_render_command(CLI::App& app, context& ctx) {
  auto args = std::make_shared<render_args>();
  auto* render =
      app.add_subcommand("render", "Render the scene with each method through the GS model; PNGs + report.json");
  render->add_option("--out", args->out, "output directory (created if missing)")->capture_default_str();
  render->add_option("--export-mesh", args->export_mesh, export_mesh_help);
  add_options(render, *args);
  add_cost_options(render, *args);
  render->callback([args, &ctx] { run(*args, false, ctx); });

  auto rargs = std::make_shared<render_args>();
  auto* report = app.add_subcommand(
      "report",
      "Render and compare with the float dot product; writes the PNGs, report.json, report-pixels.js and their "
      "page report.html (open it in that folder) and prints its path");
  report->add_option("--out", rargs->out, "output directory (created if missing)")->capture_default_str();
  report->add_option("--export-mesh", rargs->export_mesh, export_mesh_help);
  add_options(report, *rargs);
  add_cost_options(report, *rargs);
  report->callback([rargs, &ctx] { run(*rargs, true, ctx); });
}

}  // namespace gsdot3::cli
