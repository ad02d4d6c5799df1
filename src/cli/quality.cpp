// gsdot3 quality — the paper's comparative quality sentences (seed 000) as rows with verdicts: the
// embedded scene and N seeded random scenes through the GS model, each claim × metric
// (pipeline/quality_claims.hpp; docs/quality-claims.md). Progress on stderr.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "model_args.hpp"
#include "gs_arith/options.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/quality_claims.hpp"

namespace gsdot3::cli {

namespace {
struct args {
  unsigned scenes = 8;
  std::uint64_t seed = 1;
  int s = 122;
  model_args model;
  bool json = false;
};

nlohmann::json to_json(const pipeline::quality_scene& q) {
  nlohmann::json j;
  for (const auto& e : q.methods)
    j[pipeline::label(e.m, e.map)] = {{"rmse_vs_renormalised", e.vs_renormalised},
                                      {"rmse_vs_unnormalised", e.vs_unnormalised},
                                      {"rmse_after_gain", e.after_gain},
                                      {"gain", e.gain},
                                      {"rmse_sign_change_triangles", e.sign_change},
                                      {"samples", e.samples},
                                      {"sign_change_samples", e.sign_change_samples},
                                      {"edge_highlighting", e.edge_highlighting},
                                      {"edge_samples", e.edge_samples},
                                      {"inside_samples", e.inside_samples},
                                      {"gs_pixel_ops", e.pixel_ops}};
  return j;
}

void run(const args& a, context& ctx) {
  if (a.scenes > 64) throw usage_error("--scenes: at most 64, not " + std::to_string(a.scenes));
  if (a.s < 1 || a.s > 127) throw usage_error("--s: 1 to 127, not " + std::to_string(a.s));
  pipeline::render_options o;
  o.s = a.s;
  o.model = a.model.resolve();
  std::vector<pipeline::quality_scene> scenes;
  std::fprintf(stderr, "gsdot3 quality: the embedded scene\n");
  scenes.push_back(pipeline::measure_quality("embedded", pipeline::default_scene(), o));
  for (unsigned k = 0; k < a.scenes; ++k) {
    std::fprintf(stderr, "gsdot3 quality: random scene %u of %u (seed %llu)\n", k + 1, a.scenes,
                 static_cast<unsigned long long>(a.seed + k));
    scenes.push_back(pipeline::measure_quality("random-" + std::to_string(a.seed + k),
                                               pipeline::random_quality_scene(a.seed + k), o));
  }
  const auto rows = pipeline::quality_rows(scenes);
  if (a.json) {
    nlohmann::json j;
    j["options"] = {{"s", a.s}, {"random_scenes", a.scenes}, {"first_seed", a.seed}};
    for (const auto& opt : gs::option_catalogue())
      j["options"]["model"][std::string(opt.name)] = std::string(gs::option_value(o.model, opt.name));
    for (const auto& q : scenes) j["scenes"][q.name] = to_json(q);
    for (const auto& r : rows) {
      nlohmann::json pairs = nlohmann::json::array();
      for (const auto& [b, x] : r.per_scene) pairs.push_back({b, x});
      j["rows"].push_back({{"claim", r.claim},
                           {"paper", r.paper},
                           {"metric", r.metric},
                           {"better", r.better},
                           {"other", r.other},
                           {"verdict", r.verdict},
                           {"holds_on", r.holds_on},
                           {"per_scene_better_other", pairs}});
    }
    std::printf("%s\n", j.dump(2).c_str());
    ctx.exit_code = 0;
    return;
  }
  std::printf(
      "seed 000's comparative sentences on the embedded scene and %u random scenes (seeds %llu..%llu), s = %d, "
      "dot-product\n"
      "error in 1/128 units; 'holds': the method the paper calls better is lower on every scene. Per row: the "
      "embedded\n"
      "scene's pair (claimed better vs other), then the random scenes' smallest and largest ratio better/other.\n",
      a.scenes, static_cast<unsigned long long>(a.seed), static_cast<unsigned long long>(a.seed + a.scenes - 1), a.s);
  std::string claim;
  for (const auto& r : rows) {
    if (r.claim != claim) {
      claim = r.claim;
      std::printf("\n%s: %s vs %s\n  %s\n", r.claim.c_str(), r.better.c_str(), r.other.c_str(), r.paper.c_str());
    }
    double lo = 1e300, hi = 0;
    for (std::size_t k = 1; k < r.per_scene.size(); ++k) {
      const double q = r.per_scene[k].second > 0 ? r.per_scene[k].first / r.per_scene[k].second : 0;
      lo = std::min(lo, q);
      hi = std::max(hi, q);
    }
    std::printf("  %-28s %-14s embedded %10.4g vs %-10.4g", r.metric.c_str(), r.verdict.c_str(),
                r.per_scene.front().first, r.per_scene.front().second);
    if (r.per_scene.size() > 1) std::printf(" random ratio %.3f..%.3f", lo, hi);
    std::printf("\n");
  }
  ctx.exit_code = 0;
}
}  // namespace

void add_quality_command(CLI::App& app, context& ctx) {
  auto a = std::make_shared<args>();
  auto* cmd = app.add_subcommand(
      "quality", "seed 000's comparative quality sentences, evaluated on the embedded and seeded random scenes");
  cmd->add_option("--scenes", a->scenes, "random scenes besides the embedded one (0 to 64)")->capture_default_str();
  cmd->add_option("--seed", a->seed, "seed of the first random scene (scene k uses seed + k)")->capture_default_str();
  cmd->add_option("--s", a->s, "two-pass tolight scale (section 3.5)")->capture_default_str();
  a->model.add_to(cmd);
  cmd->add_flag("--json", a->json, "every scene's figures and every row as JSON on stdout");
  cmd->callback([a, &ctx] { run(*a, ctx); });
}

}  // namespace gsdot3::cli
