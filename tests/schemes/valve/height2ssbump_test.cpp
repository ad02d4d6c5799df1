// tests/schemes/valve/height2ssbump_test.cpp — Source's height2ssbump steps on tiny height fields
// whose results are worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "valve/encode.hpp"
#include "valve/height2ssbump.hpp"

namespace gsdot3::valve {
namespace {

// Halton element 2: base 2 → 0.25 (z = −0.5 → |z| = 0.5), base 3 → 2/3 (θ = 240°), so
// dir = (cos 240°·sin 120°, sin 240°·sin 120°, 0.5) = (−0.4330, −0.75, 0.5).
TEST(ValveHeight2Ssbump, FirstTraceDirections) {
  const auto d = trace_directions(2);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d[0].x, -0.4330127, 1e-6);
  EXPECT_NEAR(d[0].y, -0.75, 1e-6);
  EXPECT_NEAR(d[0].z, 0.5, 1e-6);
  // Element 3: base 2 → 0.75 (z = 0.5), base 3 → 1/9 (θ = 40°): (cos 40°·0.8660, sin 40°·0.8660, 0.5).
  EXPECT_NEAR(d[1].x, std::cos(40.0 * M_PI / 180) * 0.8660254, 1e-6);
  EXPECT_NEAR(d[1].y, std::sin(40.0 * M_PI / 180) * 0.8660254, 1e-6);
  EXPECT_NEAR(d[1].z, 0.5, 1e-6);
}

// A ramp h = 0.1·x (bump scale 1): every triangle of an interior texel has normal ∝ (−0.1, 0, 1)
// (see the derivation in the report; the second triangle of the left column is degenerate and adds 0).
TEST(ValveHeight2Ssbump, RampNormals) {
  const int w = 8, h = 8;
  std::vector<float> height(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) height[static_cast<std::size_t>(y * w + x)] = 0.1f * static_cast<float>(x);
  const auto n = vertex_normals(height, w, h, 1.0f);
  for (int x = 2; x <= 5; ++x) {
    const auto& v = n[static_cast<std::size_t>(3 * w + x)];
    EXPECT_NEAR(v.x, -0.1 / std::sqrt(1.01), 1e-6) << x;
    EXPECT_NEAR(v.y, 0.0, 1e-6) << x;
    EXPECT_NEAR(v.z, 1.0 / std::sqrt(1.01), 1e-6) << x;
  }
}

// A flat field: normals (0, 0, 1), nothing blocks a ray from 0.55 above the plane, so every
// channel is B_c·N = 0.57735025882720947 (the float 1/√3), stored as trunc(255·0.57735) = 147.
TEST(ValveHeight2Ssbump, FlatUnoccludedIs147) {
  const std::vector<float> height(64, 0.5f);
  height2ssbump_options o;
  o.bump_scale = 4.0f;
  o.threads = 2;
  const auto out = height2ssbump(height, 8, 8, o);
  for (const auto& v : out) {
    EXPECT_FLOAT_EQ(v.x, 0.57735025882720947f);
    EXPECT_FLOAT_EQ(v.y, 0.57735025882720947f);
    EXPECT_FLOAT_EQ(v.z, 0.57735025882720947f);
    EXPECT_EQ(ssbump_texel(v), (texel{147, 147, 147}));
  }
}

// Progress: fractions in (0, 1], calls one at a time, and 1.0 exactly once, last, on
// every run with two and four workers (the CLI's "100%" line comes from it; a last row finished while
// another worker was reporting once left it out: checked to fail that way).
TEST(ValveHeight2Ssbump, ProgressEndsWithOneExactlyOnce) {
  const std::vector<float> height(16 * 16, 0.5f);
  for (unsigned threads : {2u, 4u})
    for (int run = 0; run < 5; ++run) {
      height2ssbump_options o;
      o.bump_scale = 1.0f;
      o.rays = 8;
      o.threads = threads;
      std::vector<double> seen;
      // Called one at a time, so no lock. The first call is slow (a slow terminal): the other workers
      // finish every row while it holds the report, the case that lost the 1.0.
      o.progress = [&](double f) {
        seen.push_back(f);
        if (seen.size() == 1) std::this_thread::sleep_for(std::chrono::milliseconds(30));
      };
      height2ssbump(height, 16, 16, o);
      ASSERT_FALSE(seen.empty());
      EXPECT_EQ(seen.back(), 1.0);
      EXPECT_EQ(std::count(seen.begin(), seen.end(), 1.0), 1);
      for (double f : seen) {
        EXPECT_GT(f, 0.0);
        EXPECT_LE(f, 1.0);
      }
    }
}

// A pit: one texel 0, the rest at 1 with a large bump scale. The pit's normal is still (0, 0, 1)
// by symmetry, and the walls (height 20 one texel away) block every ray below ~87° elevation, so
// each channel is far below the flat 0.577; the far texels stay near flat.
TEST(ValveHeight2Ssbump, PitIsShadowed) {
  const int w = 8;
  std::vector<float> height(64, 1.0f);
  height[static_cast<std::size_t>(4 * w + 4)] = 0.0f;
  height2ssbump_options o;
  o.bump_scale = 20.0f;
  o.filter_radius = 0;
  const auto out = height2ssbump(height, w, w, o);
  const auto& pit = out[static_cast<std::size_t>(4 * w + 4)];
  EXPECT_LT(pit.x, 0.1f);
  EXPECT_LT(pit.y, 0.1f);
  EXPECT_LT(pit.z, 0.1f);
  const auto& far = out[0];
  EXPECT_NEAR(far.z, 0.57735f, 0.02f);
}

// The bilateral filter keeps a step higher than the threshold (2/255) and averages within it.
TEST(ValveHeight2Ssbump, BilateralKeepsEdges) {
  std::vector<float> height(64, 0.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 4; x < 8; ++x) height[static_cast<std::size_t>(y * 8 + x)] = 0.5f;
  EXPECT_EQ(bilateral_filter(height, 8, 8, 10, 2.0f / 255.0f), height);
  // Two levels 1/255 apart: each texel averages with weight 1/2 for the other level.
  std::vector<float> h2(64, 0.0f);
  for (std::size_t i = 32; i < 64; ++i) h2[i] = 1.0f / 255.0f;
  const auto f = bilateral_filter(h2, 8, 8, 10, 2.0f / 255.0f);
  EXPECT_GT(f[0], 0.0f);
  EXPECT_LT(f[0], 0.5f / 255.0f);
}

}  // namespace
}  // namespace gsdot3::valve
