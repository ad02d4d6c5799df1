// valve/height2ssbump.hpp — Source's height2ssbump (Source SDK 2013 src/utils/height2ssbump and the
// bitmap library's FloatBitMap_t::ComputeSelfShadowedBumpmapFromHeightInAlphaChannel,
// TileableBilateralFilter and mathlib's halton.cpp/halton.h, read in stored copies), step by step:
//  1. TileableBilateralFilter(radius 10, threshold 2/255) on the height (wrapped): spatial weight
//     exp(−(dx² + dy²) / (2·radius·0.033)) — radius, not radius², as Source writes it — times the
//     similarity 1 − |Δh|/threshold (0 beyond the threshold).
//  2. Vertex (x, y, scale·h); per-texel normal = normalize(Σ of 18 unit triangle normals) of the
//     3×3 neighbourhood, flipped to +z, with Source's index quirks kept: the wrapped neighbour's
//     position is its unwrapped (x, y), and the second triangle of each cell uses the centre column x.
//  3. `rays` directions from DirectionalSampler_t (z from Halton base 2, angle from base 3;
//     GetElement reads the member seed after NextValue's seed++, so the first element is 2), z = |z|, traced
//     from (x, y, scale·h + origin_bias) over length 3·max(W, H) against the height field's
//     triangles tiled (1 + 2·tile_reps)² times (half tiles at the border as Source adds them).
//  4. Per basis vector B_c (bumpvects.h float basis): 0 if B_c·N < 0, else
//     (B_c·N)·Σ_unblocked(B_c·dir)/Σ_all(B_c·dir) over the rays with B_c·dir > 0. Not squared and
//     not normalised: a flat unoccluded texel gives 1/√3 = 0.57735 on every channel.
#pragma once

#include <functional>
#include <vector>

#include "valve/basis.hpp"

namespace gsdot3::valve {

struct height2ssbump_options {
  float bump_scale = 1.0f;    // Source's second argument (no default there)
  int rays = 250;             // -r
  float origin_bias = 0.55f;  // "move the ray origin up a hair"
  int tile_reps = 1;          // NREPS_TILE: 1 (Source) or 0 (no tiling)
  int filter_radius = 10;     // -f (0 = no filter)
  float filter_threshold = 2.0f / 255.0f;
  unsigned threads = 0;                  // 0: hardware concurrency
  std::function<void(double)> progress;  // fraction done, one call at a time; 1.0 exactly once, last
};

// Heights in [0, 1] (8-bit value / 255), row-major w×h.
std::vector<float> bilateral_filter(const std::vector<float>& height, int w, int h, int radius, float threshold);
std::vector<vec3<float>> vertex_normals(const std::vector<float>& height, int w, int h, float bump_scale);
std::vector<vec3<float>> trace_directions(int rays);
// The SSBump weights per texel (floats; ssbump_texel() in encode.hpp makes them 8-bit).
std::vector<vec3<float>> height2ssbump(const std::vector<float>& height, int w, int h, const height2ssbump_options& o);

}  // namespace gsdot3::valve
