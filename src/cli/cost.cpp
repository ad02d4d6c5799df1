// gsdot3 cost — what a GS dump costs on the console: every frame and every pass (a run of primitives
// with the same drawing registers, gs_cost/model.hpp) priced by the GS cost model (src/gs_cost,
// docs/cost.md) in GS cycles, time at 147.456 MHz, share of the frame, where the cycles go (pixels,
// page breaks, texture misses, uploads, CLUT loads, set-up) and frames per second in NTSC and PAL.
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.hpp"
#include "cost_args.hpp"
#include "gs_cost/cost_json.hpp"
#include "gs_cost/model.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/performance_claims.hpp"

namespace gsdot3::cli {
namespace {

namespace cost = gs::cost;

struct args {
  std::string file;
  bool json = false, claims = false, markdown = false;
  std::size_t passes = 40;
  cost_args model;
  cost::cost_options o{};  // model.resolve()
};

std::string fixed_str(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string pct(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? "0.0 %" : fixed_str(100.0 * static_cast<double>(part) / static_cast<double>(whole), 1) + " %";
}

void print_breakdown(const cost::breakdown& b) {
  const std::uint64_t t = b.total();
  std::cout << "  pixels " << b.pixels << " (" << pct(b.pixels, t) << "), page breaks " << b.page_breaks << " ("
            << pct(b.page_breaks, t) << "), texture misses " << b.texture_misses << " (" << pct(b.texture_misses, t)
            << "), uploads " << b.uploads << " (" << pct(b.uploads, t) << "), CLUT loads " << b.clut_loads << " ("
            << pct(b.clut_loads, t) << "), set-up " << b.setup << " (" << pct(b.setup, t) << ")\n";
}

void print_text(const args& a, const std::vector<cost::frame_cost>& frames) {
  std::cout << "file " << a.file << "\nmodel: GS at 147.456 MHz, walk " << cost::name(a.o.walk) << ", page break "
            << a.o.page_break_cycles << " cycles, texture miss " << a.o.texture_miss_cycles << " cycles per "
            << cost::name(a.o.texture_miss_unit) << " (docs/cost.md)\nframes " << frames.size() << "\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto& fr = frames[f];
    const std::uint64_t c = fr.cycles.total();
    std::cout << "frame " << f + 1 << ": " << c << " cycles, " << fixed_str(cost::seconds(c) * 1e3, 3) << " ms; NTSC "
              << fixed_str(100.0 * cost::seconds(c) * cost::ntsc_hz, 1) << " % of a field, "
              << fixed_str(cost::fps_locked(c, cost::ntsc_hz), 2) << " fps; PAL "
              << fixed_str(100.0 * cost::seconds(c) * cost::pal_hz, 1) << " %, "
              << fixed_str(cost::fps_locked(c, cost::pal_hz), 2) << " fps; unlocked "
              << fixed_str(cost::fps_unlocked(c), 1) << " fps\n";
    std::cout << "  primitives " << fr.counts.primitives << " (" << fr.counts.triangles << " triangles, "
              << fr.counts.sprites << " sprites), pixels " << fr.counts.pixels << ", page breaks "
              << fr.counts.page_breaks << ", texture misses " << fr.counts.texture_misses << ", transfers "
              << fr.counts.transfers << " (" << fr.counts.upload_bytes << " bytes), CLUT loads " << fr.counts.clut_loads
              << "\n";
    std::cout << "  fill-rate share " << pct(fr.cycles.pixels, c) << " (pixel cycles of all cycles)\n";
    print_breakdown(fr.cycles);
    std::cout << "  passes " << fr.passes.size() << "\n";
    for (std::size_t i = 0; i < fr.passes.size() && i < a.passes; ++i) {
      const auto& p = fr.passes[i];
      const std::uint64_t pc = p.cycles.total();
      std::cout << "  pass " << i + 1 << " at byte " << p.first_offset << ": " << cost::mode_text(p) << "; "
                << p.counts.primitives << " primitives, " << p.counts.pixels << " pixels; " << pc << " cycles ("
                << fixed_str(cost::seconds(pc) * 1e6, 1) << " us, " << pct(pc, c) << " of the frame): pixels "
                << p.cycles.pixels << ", page breaks " << p.cycles.page_breaks << ", texture misses "
                << p.cycles.texture_misses << ", uploads " << p.cycles.uploads << ", CLUT " << p.cycles.clut_loads
                << ", set-up " << p.cycles.setup << "\n";
    }
    if (fr.passes.size() > a.passes)
      std::cout << "  (" << fr.passes.size() - a.passes << " more passes; --passes N lists more, --json all)\n";
  }
}

void print_json(const args& a, const std::vector<cost::frame_cost>& frames) {
  nlohmann::json j;
  j["file"] = a.file;
  j["clock_hz"] = cost::gs_clock_hz;
  j["options"] = cost::to_json(a.o);
  j["frames"] = nlohmann::json::array();
  for (const auto& fr : frames) j["frames"].push_back(cost::frame_json(fr, true));
  std::cout << j.dump(1) << "\n";
}

// The seed's performance sentences on the embedded scene (pipeline/performance_claims.hpp).
void print_claims(const args& a) {
  const pipeline::scene s = pipeline::default_scene();
  const auto rows =
      pipeline::performance_rows(s, {}, a.o, [](const std::string& m) { std::cerr << "gsdot3: " << m << "\n"; });
  const std::string scene = "the embedded scene (512x448, " + std::to_string(s.lights.size()) + " point lights)";
  if (a.markdown) {
    std::cout << pipeline::performance_markdown(rows, scene);
    return;
  }
  if (a.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& r : rows)
      j.push_back({{"claim", r.claim},
                   {"paper", r.paper},
                   {"statement", r.statement},
                   {"figures", r.figures},
                   {"verdict", r.verdict}});
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << "seed 000's performance sentences on " << scene << ", GS cost model defaults (docs/cost.md)\n";
  for (const auto& r : rows)
    std::cout << r.claim << " (" << r.paper << "): " << r.verdict << "\n  " << r.statement << "\n  " << r.figures
              << "\n";
}

void run(args a) {
  a.o = a.model.resolve();
  if (!a.claims && a.file.empty()) throw usage_error("give a dump FILE or --claims");
  if (a.claims && !a.file.empty()) throw usage_error("give a dump FILE or --claims, not both");
  if (a.markdown && !a.claims) throw usage_error("--markdown goes with --claims");
  if (a.claims) {
    print_claims(a);
    return;
  }
  gs::dump::gs_dump d;
  try {
    d = gs::dump::load_dump(a.file);
  } catch (const gs::dump::dump_error& e) { throw usage_error(e.what()); }
  std::vector<cost::frame_cost> frames;
  try {
    frames = cost::price_dump(d, a.o);
  } catch (const gs::dump::dump_error& e) { throw usage_error(a.file + ": " + e.what()); }
  if (a.json)
    print_json(a, frames);
  else
    print_text(a, frames);
}

}  // namespace

void add_cost_command(CLI::App& app, context& ctx) {
  (void)ctx;
  auto a = std::make_shared<args>();
  auto* cmd = app.add_subcommand("cost",
                                 "Price a PCSX2 GS dump on the console's GS: cycles, time at 147.456 MHz and "
                                 "NTSC / PAL frame rate per frame and per pass, and where the cycles go "
                                 "(docs/cost.md)");
  cmd->add_option("FILE", a->file, "The dump (.gs, .gs.xz, .gs.zst)");
  cmd->add_flag("--claims", a->claims,
                "Instead of a dump: seed 000's performance sentences priced on the embedded scene (two-pass vs "
                "four-pass vs 2002, the free DPB clear, per light, real time, specular); docs/performance-claims.md");
  cmd->add_flag("--markdown", a->markdown, "With --claims: the rows as docs/performance-claims.md");
  cmd->add_flag("--json", a->json, "Every frame and every pass as JSON on stdout");
  cmd->add_option("--passes", a->passes, "Passes listed per frame in the text output")->capture_default_str();
  a->model.add_to(cmd);
  cmd->callback([a] { run(*a); });
}

}  // namespace gsdot3::cli
