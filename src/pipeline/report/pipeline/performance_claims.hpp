// pipeline/performance_claims.hpp — seed 000's performance sentences priced on the console's GS: each
// frame is the stream `gsdot3 dump` writes, priced by the GS cost model (console_time.hpp, src/gs_cost,
// docs/cost.md) under the cost options given; `gsdot3 cost --claims` prints the rows (docs/
// performance-claims.md is that output for the embedded scene) and `gsdot3 report --cost` adds them to
// report.json. Like the quality sentences they live here, not in the proof catalogue: src/proofs
// renders nothing. A figure is one scene's frame under the default model options, not a proof.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "gs_cost/constants.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// The rows' ids, in the order performance_rows returns them (the coverage table cites them).
namespace performance_ids {
inline constexpr std::string_view two_vs_four = "perf.two-vs-four", two_vs_2002 = "perf.two-vs-2002",
                                  four_vs_2002 = "perf.four-vs-2002", free_dpb_clear = "perf.free-dpb-clear",
                                  cost_per_light = "perf.cost-per-light", real_time = "perf.real-time",
                                  specular = "perf.specular", two_vs_three = "perf.two-vs-three",
                                  ordinary_shading = "perf.ordinary-shading";
inline constexpr std::string_view all[] = {two_vs_four, two_vs_2002, four_vs_2002, free_dpb_clear,  cost_per_light,
                                           real_time,   specular,    two_vs_three, ordinary_shading};
}  // namespace performance_ids

struct performance_row {
  std::string claim, paper, statement;  // the claim id, where in the seed, the sentence tested
  std::string figures;                  // the priced figures behind the verdict, in words
  std::string verdict;                  // "holds", "refuted", or "bound: ..." (a priced extreme)
};

// Progress per priced frame when `progress` is set. The scene's lights are used as they are for the
// method comparison; the light-count rows take its first light repeated 1, 2 and 3 times; the step 5
// row adds the scene's non-normal-mapped geometry, or a floor under its model (floor.hpp) when it has none.
std::vector<performance_row> performance_rows(const scene& s, const render_options& o, const gs::cost::cost_options& c,
                                              const std::function<void(const std::string&)>& progress = {});
// The rows as a Markdown table with one section per row (docs/performance-claims.md).
std::string performance_markdown(const std::vector<performance_row>& rows, const std::string& scene_description);

}  // namespace gsdot3::pipeline
