// proofs/powervr_sweeps.hpp — the seed 004 sweeps shared by the catalogue rows (small grids) and the
// exhaustive tests (tests/schemes/powervr, full grids): the bump unit's 8-bit output against the
// exact identity value, under one precision option.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "powervr/evaluate.hpp"
#include "proofs/sweep.hpp"

namespace gsdot3::proofs::powervr_sweeps {

namespace pvr = schemes::powervr;

// The light grid of an identity sweep: every texel (S, R) × every Q byte in `q_bytes` × every
// elevation in `elevations` (radians) × every intensity in `intensities`. K1..K3 are the seed's,
// rounded to nearest (offset_nearest); the expected value is 255·clamp((1 − S_l) + S_l·N·L, 0, 1)
// with N the texel's normal and L the light at the exact Q = Q_byte·2π/steps.
struct identity_grid {
  std::vector<int> q_bytes;
  std::vector<double> elevations, intensities;
  std::uint64_t size() const noexcept { return 65536ull * q_bytes.size() * elevations.size() * intensities.size(); }
};

struct error_stats {
  double max_abs = 0, sum = 0, sum_sq = 0;
  std::uint64_t n = 0, arg_max = 0;
  void add(double e, std::uint64_t i) noexcept {
    if (std::abs(e) > max_abs) max_abs = std::abs(e), arg_max = i;
    sum += e, sum_sq += e * e, ++n;
  }
  void merge(const error_stats& later) noexcept {
    if (later.max_abs > max_abs) max_abs = later.max_abs, arg_max = later.arg_max;
    sum += later.sum, sum_sq += later.sum_sq, n += later.n;
  }
  double mean() const noexcept { return n ? sum / static_cast<double>(n) : 0.0; }
  double rmse() const noexcept { return n ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0; }
};

// Index i = ((texel·|Q| + q)·|T| + t)·|S_l| + l, texel = S·256 + R.
struct identity_case {
  pvr::bump_texel texel;
  pvr::offset_colour k;
  double S_l, T, expected;  // expected in output units (0..255)
};
identity_case identity_case_at(const identity_grid& g, pvr::azimuth_scale a, std::uint64_t i);

// 8-bit output − expected, over the grid (errors in 1/255 of full intensity).
error_stats identity_8bit_error(const identity_grid& g, pvr::azimuth_scale a, pvr::precision p,
                                const sweep_config& cfg);

}  // namespace gsdot3::proofs::powervr_sweeps
