// gsdot3 normal-encoding — seed 002's table: per encoding, the worst case over the whole sphere
// (rounding cells, src/schemes/normal_encoding/cells.hpp) and the seed's PSNR on the embedded scene's
// view-space normals with the 2009 (unnormalised input) and 2010 (normalised) encoders, beside the
// seed's and the 2010 revision's published PSNRs. Progress on stderr.
#include <cstdio>
#include <map>
#include <string>

#include "commands.hpp"
#include "normal_encoding/cells.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scheme_normal_encoding.hpp"

namespace gsdot3::cli {

namespace {
struct args {
  int bits = 8;
  unsigned window = 0;
  bool no_worst_case = false;
};

// Published PSNRs (dB) on the seed's own scene: 2009 (seed 002) and the 2010 revision
// (../shared/spec/other-schemes.md).
const std::map<std::string, std::pair<double, double>> published = {
    {"xyz", {52.661, 51.081}},       {"xy", {15.054, 18.692}},         {"spherical", {40.244, 42.042}},
    {"spherical-lut", {36.503, 0}},  {"spheremap", {44.781, 48.071}},  {"cryengine3", {40.355, 0}},
    {"lambert", {43.054, 48.071}},   {"stereographic", {44.207, 44.147}}, {"view-space", {0, 38.730}}};

std::string dash_or(double v, const char* fmt) {
  if (v == 0) return "-";
  char b[32];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

void run(const args& a, context& ctx) {
  try {
    normal_encoding::check_bits(a.bits);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--bits: ") + e.what());
  }
  if (a.bits > 12 && a.window == 0 && !a.no_worst_case)
    throw usage_error("--bits " + std::to_string(a.bits) + ": the whole-sphere enumeration needs 4^bits cells; give --window R or --no-worst-case");
  std::fprintf(stderr, "gsdot3 normal-encoding: rendering the embedded scene's geometry\n");
  const pipeline::scene s = pipeline::default_scene();
  const pipeline::prepared_scene ps = pipeline::prepare(s);
  const pipeline::frame g = pipeline::render(s, ps, pipeline::method::two_pass, {});
  const auto rows = pipeline::normal_encoding_psnr(s, ps, g.visible_triangle, a.bits);
  std::printf("seed 002 at 2x%d (xyz 3x%d); PSNR dB on |n1 - n2| over %zu view-space pixels of the embedded scene\n", a.bits, a.bits,
              rows.empty() ? std::size_t{0} : rows.front().pixels);
  std::printf("%-20s %12s %12s %10s %10s %10s %10s\n", "method", "worst_deg", "(upper)", "psnr_2009", "psnr_2010", "seed_2009", "rev_2010");
  for (const auto& r : rows) {
    std::string worst = "-", upper = "-";
    // With a window, octahedral's window value is no bound for precise: left out.
    if (!a.no_worst_case && !(a.window > 0 && r.method == "octahedral-precise")) {
      std::fprintf(stderr, "gsdot3 normal-encoding: rounding cells of %s\n", r.method.c_str());
      const auto& m = normal_encoding::method_named(r.method);
      const auto& cm = m.id == normal_encoding::method_id::octahedral_precise ? normal_encoding::method_of(normal_encoding::method_id::octahedral) : m;
      normal_encoding::code_window win{};
      if (a.window > 0) {
        // Around the 2×10 worst cell, scaled to `bits`: only those (2R + 1)² codes (a lower bound).
        const auto w10 = normal_encoding::cell_worst_case(cm, 10, 2);
        const bool snorm = cm.id == normal_encoding::method_id::octahedral_snorm;
        auto scaled = [&](std::uint32_t q) {
          if (snorm) return static_cast<std::uint32_t>((static_cast<double>(q) - 512) * normal_encoding::snorm_max(a.bits) / 511.0 + (1u << (a.bits - 1)) + 0.5);
          return static_cast<std::uint32_t>(q * static_cast<double>(normal_encoding::unorm_max(a.bits)) / 1023.0 + 0.5);
        };
        const std::uint32_t ci = scaled(w10.q.c[0]), cj = scaled(w10.q.c[1]);
        win = {ci > a.window ? ci - a.window : 0, ci + a.window, cj > a.window ? cj - a.window : 0, cj + a.window};
      }
      const auto w = normal_encoding::cell_worst_case(cm, a.bits, 2, normal_encoding::default_tolerance_rad, a.window == 0, win);
      worst = dash_or(w.sup_deg, "%.6f") + (w.nonfinite_cells > 0 ? "+NaN" : "");
      upper = dash_or(w.upper_deg, "%.6f");
    }
    const auto it = published.find(r.method);
    const auto pub = it == published.end() ? std::pair<double, double>{0, 0} : it->second;
    std::printf("%-20s %12s %12s %10.3f %10.3f %10s %10s\n", r.method.c_str(), worst.c_str(), upper.c_str(), r.psnr_2009, r.psnr_2010,
                dash_or(pub.first, "%.3f").c_str(), dash_or(pub.second, "%.3f").c_str());
  }
  if (a.window > 0) std::printf("worst_deg here: sup over the %u x %u codes around the scaled 2x10 worst cell only: a LOWER bound\n", 2 * a.window + 1, 2 * a.window + 1);
  std::printf("worst_deg: sup over the whole sphere of the angle (#8: its front hemisphere), +NaN: some cells decode to NaN;\n"
              "octahedral-precise: octahedral's sup bounds it. Mean length of the 2009 inputs: %.6f\n",
              rows.empty() ? 0.0 : rows.front().mean_input_length);
  ctx.exit_code = 0;
}
}  // namespace

void add_normal_encoding_command(CLI::App& app, context& ctx) {
  auto a = std::make_shared<args>();
  auto* cmd = app.add_subcommand("normal-encoding", "seed 002: each normal encoding's worst case over the sphere and its PSNR on the scene");
  cmd->add_option("--bits", a->bits, "bits per channel, 4 to 16 (the worst case at 12+ takes minutes)")->capture_default_str();
  cmd->add_flag("--no-worst-case", a->no_worst_case, "only the PSNR table");
  cmd->add_option("--window", a->window,
                  "enumerate only the (2R+1)^2 codes around the 2x10 worst cell scaled to --bits (a lower bound; for 16 bits)");
  cmd->callback([a, &ctx] { run(*a, ctx); });
}

}  // namespace gsdot3::cli
