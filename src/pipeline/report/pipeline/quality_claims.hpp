// pipeline/quality_claims.hpp — the paper's comparative quality sentences (seed 000) evaluated on
// renders: the embedded scene and a fixed set of seeded random scenes. They live in the pipeline, not
// in the proof catalogue: src/proofs is a lower layer and renders nothing. `gsdot3 report` writes them
// into report.json ("quality_claims", the embedded scene only) and `gsdot3 quality` prints them with
// the random scenes (docs/quality-claims.md says which sentence each row tests and why that metric).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/prepare.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// The errors of one method's dot products on one scene, in 1/128 units over covered pixels × lights.
//   vs_renormalised:  RMSE against 128·fade·N·normalize(ΣλT) (PC-style per-pixel DOT3)
//   vs_unnormalised:  RMSE against 128·N·Σλ(fade·T), the product neither two-pass nor 2002 normalises
//   after_gain:       RMSE against gain·unnormalised, gain the least-squares fit Σdr/Σr² (a global
//                     scale such as two-pass's s/128 can be undone by the intensity palette, the ILP)
//   sign_change:      RMSE against unnormalised over the samples whose triangle has a vertex tolight
//                     component of each sign: where section 2's per-vertex clamping acts (figure 1)
//   edge_highlighting: |mean(d − r) near a triangle's edge − mean(d − r) inside it| against the
//                     renormalised reference r: "near" is a pixel centre whose smallest barycentric
//                     weight is below 0.1, "inside" above 0.25 — section 3.5's "lighting ... decrease[s]
//                     in intensity across the triangle and results in edge highlighting"
//   pixel_ops:        pixels sent through the GS pixel pipeline for the frame (a count, not a timing)
// What an entry measures: the frame of the scene's map against the reference of that map (own_map), or,
// against the reference of the unquantised normals (the 24-bit map, scene.hpp), the frame of the 8-bit
// palettised map (palettised) or of four-pass's three 8-bit component maps (three_maps, section 3.6).
enum class map_read : std::uint8_t { own_map, palettised, three_maps };
struct method_errors {
  method m{};
  map_read map = map_read::own_map;
  double vs_renormalised = 0, vs_unnormalised = 0, after_gain = 0, gain = 0, sign_change = 0, edge_highlighting = 0;
  std::size_t samples = 0, sign_change_samples = 0, edge_samples = 0, inside_samples = 0, pixel_ops = 0;
};

// One sentence of the paper compared on one metric over every scene: `better` is the method the
// sentence says is better. Verdict: "holds" (lower on every scene), "refuted" (on none; "refuted
// (equal on every scene)" when the two are the same everywhere), otherwise
// "mixed" with the count; the per-scene pairs (better, other) are the figures.
struct quality_row {
  std::string claim, paper, metric;
  std::string better, other;  // label(): the method and the map it read
  std::vector<std::pair<double, double>> per_scene;
  std::size_t holds_on = 0;
  std::string verdict;
};

struct quality_scene {
  std::string name;  // "embedded", "random-1", ...
  std::vector<method_errors> methods;
};

// "four-pass", "four-pass, 8-bit map vs unquantised", "four-pass, three 8-bit maps vs unquantised".
std::string label(method m, map_read map);
// The errors of one method's frame against the reference of the same prepared scene.
method_errors measure_errors(method m, const frame& f, const reference_frame& ref, const prepared_scene& ps,
                             map_read map = map_read::own_map);
// The errors of every GS method on one scene, and four-pass's palettised and three-map frames against
// the unquantised normals.
quality_scene measure_quality(const std::string& name, const scene& s, const render_options& o);
// The scene of the random set with this seed: the embedded head at a random tessellation, 1 to 3 point
// lights and a camera at random positions (a SplitMix64 stream, the same on every platform), w × h.
scene random_quality_scene(std::uint64_t seed, int width = 256, int height = 224);
// The ids of the claims the rows test ("quality.two-pass-vs-2002", ...; the coverage table cites them).
std::vector<std::string> quality_claim_ids();

// The rows of every claim × metric over the given scenes; a claim whose entries the first scene lacks
// (a report of some methods only) has no rows.
std::vector<quality_row> quality_rows(const std::vector<quality_scene>& scenes);

}  // namespace gsdot3::pipeline
