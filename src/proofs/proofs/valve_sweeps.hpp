// proofs/valve_sweeps.hpp — the whole-texel-set sweeps behind seed 001's claims (claims_valve.cpp),
// over a named domain so the catalogue can run a stated sub-lattice and the `exhaustive` ctest all
// 2^24 RGB8 texels with the same code.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::valve_sweeps {

// The texels (r, g, b) with every channel in `values` (ascending).
struct texel_domain {
  std::vector<std::uint8_t> values;
  std::string description;
  std::uint64_t size() const noexcept {
    return static_cast<std::uint64_t>(values.size()) * values.size() * values.size();
  }
  std::uint32_t rgb(std::uint64_t i) const noexcept;  // 0xRRGGBB of index i (b fastest)
  static texel_domain all();                          // 0..255: 2^24 texels
  static texel_domain catalogue();                    // {0, 4, …, 252, 255}: 65³ = 274 625 texels
};

// A distribution of non-negative errors: max (first index reaching it), mean, RMSE.
struct stat {
  double max = -1, sum = 0, sum2 = 0;
  std::uint64_t n = 0, arg_max = 0;
  void add(double e, std::uint64_t index) noexcept {
    if (e > max) max = e, arg_max = index;
    sum += e, sum2 += e * e, ++n;
  }
  void merge(const stat& later) noexcept {
    if (later.max > max) max = later.max, arg_max = later.arg_max;
    sum += later.sum, sum2 += later.sum2, n += later.n;
  }
  double mean() const noexcept { return n ? sum / static_cast<double>(n) : 0.0; }
  double rmse() const noexcept;
};

// The same paths from a continuous unit normal n (θ, φ grid over the upper hemisphere, step in
// degrees): RNM stores round(127.5·n + 127.5), SSBump stores D(n) rounded to 8 bits (an ideal tool)
// or normal2ssbump of the RGB8 texel (Source's pipeline); errors against eq. (3) on n.
struct true_normal_result {
  std::uint64_t samples = 0;
  stat rnm_fp32, ssbump_ideal, ssbump_source;
};
true_normal_result true_normal_sweep(double step_degrees);

// Precision of the lighting (three unit lightmap colours, so each light's value is one weight D_i),
// in 1/255 units, against eq. (3) evaluated exactly on the normalised normal the texel encodes.
struct precision_result {
  std::uint64_t domain = 0, zero_sum = 0, unit_texels = 0;
  // [path][subset]: paths rnm_fp32, rnm_fp24, ssbump (Source's normal2ssbump, truncating),
  // ssbump_nearest (the same, rounding to nearest); subsets all texels, unit texels.
  stat err[4][2];
  std::uint64_t nan[4] = {};          // shader results that are NaN although the exact Σd ≠ 0 (not in err)
  std::uint64_t literal_changes = 0;  // texels whose normal2ssbump 8-bit output changes with the exact float basis
  stat reconstruct[2][2];             // angle (degrees), [Σ D·B, Σ √D·B][all, every N·B_i ≥ 0]
  void merge(const precision_result& later);
};
precision_result precision_sweep(const texel_domain& d, const sweep_config& cfg);

struct zero_sum_result {
  std::uint64_t domain = 0, exact = 0, fp32 = 0, fp24 = 0, not_nan_fp32 = 0, not_nan_fp24 = 0, tool_not_nan = 0;
  std::vector<std::uint32_t> first;  // first witnesses (0xRRGGBB)
  void merge(const zero_sum_result& later);
};
zero_sum_result zero_sum_sweep(const sweep_config& cfg);

// RNM filtering: unit normals on a (step × step) grid of (x, y) in the disc, as RGB8 texels; every
// unordered pair × bilinear weight w/16, w = 1..15. Error in 1/255 units (three unit lights).
struct filtering_result {
  std::uint64_t texels = 0, pairs = 0;
  stat by_weight[15];
  stat all, near;  // near: the pairs whose normals are within 10° (neighbouring texels of a smooth map)
  std::uint64_t over_half = 0, over_one = 0;  // errors > 0.5/255 and > 1/255
  std::uint32_t worst_a = 0, worst_b = 0;
  int worst_w = 0;
  void merge(const filtering_result& later);
};
filtering_result rnm_filtering_sweep(int grid, const sweep_config& cfg);

}  // namespace gsdot3::proofs::valve_sweeps
