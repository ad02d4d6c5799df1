// tests/schemes/valve/render_test.cpp — the rnm and ssbump report methods on a flat quad with a
// single normal and a single light direction, against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/render.hpp"
#include "pipeline/scheme_method.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

float centre(const scheme_frame& f, const test::flat_quad& q) {
  return f.dot[0][static_cast<std::size_t>(20 * q.s.width + 30)];
}

scheme_frame run(const char* method, const test::flat_quad& q) {
  const frame g = render(q.s, q.ps, method::two_pass, {});
  const auto* m = find_scheme_method(method);
  EXPECT_NE(m, nullptr);
  EXPECT_TRUE(m->non_negative);
  return m->render(q.s, q.ps, g.visible_triangle, {});
}

// Flat normal, light overhead: texel (128, 128, 255); L_i = B_i·z = 1/√3 each. RNM: Σ D_i = 1 so
// 128·(1/√3) = 73.90; SSBump: normal2ssbump gives (85, 85, 83) (closed_form_test.cpp), so
// 128·(253/255)·(1/√3) = 73.32. Against N·L = 1 (128) both are low: the projected light is exact
// only for weights ∝ B_i·N, not (B_i·N)².
TEST(ValveRender, FlatNormalOverheadLight) {
  const auto q = test::make_flat_quad({0, 0, 1}, {0, 0, 1});
  EXPECT_NEAR(centre(run("rnm", q), q), 128.0 / std::sqrt(3.0), 1e-3);
  EXPECT_NEAR(centre(run("ssbump", q), q), 128.0 * 253.0 / 255.0 / std::sqrt(3.0), 1e-3);
}

// Normal on B0 = (√(2/3), 0, 1/√3), light along B0: L = (1, 0, 0) (B1·B0 = B2·B0 = 0). Texel
// (232, 128, 201) has D ≈ (1 − 1e-6, 1e-6, 0) (tools_test.cpp): RNM 128·D0 ≈ 128; SSBump's texel is
// (254, 0, 0): 128·254/255 = 127.50.
TEST(ValveRender, NormalAndLightOnB0) {
  const glm::vec3 b0(0.81649658f, 0.0f, 0.57735027f);
  const auto q = test::make_flat_quad(b0, b0);
  EXPECT_NEAR(centre(run("rnm", q), q), 128.0, 1e-3);
  EXPECT_NEAR(centre(run("ssbump", q), q), 128.0 * 254.0 / 255.0, 1e-3);
}

// A light straight from below: B_i·(−z) = −1/√3 < 0 for every i, so L = 0 and both give 0. A light
// at T = (0.6, 0, −0.8), below the surface, still reaches B0 (B0·T = 0.4899 − 0.4619 = 0.0280): the
// projection lights the flat normal by 128·D0·0.0280 ≈ 1.2 where N·L = −0.8 (shown as 0 by GS).
TEST(ValveRender, LightFromBelow) {
  const auto q = test::make_flat_quad({0, 0, 1}, {0, 0, -1});
  EXPECT_EQ(centre(run("rnm", q), q), 0.0f);
  EXPECT_EQ(centre(run("ssbump", q), q), 0.0f);
  const auto r = test::make_flat_quad({0, 0, 1}, {0.6f, 0, -0.8f});
  const double b0t = 0.81649658 * 0.6 - 0.57735027 * 0.8, d0 = 0.337031;  // D0 of (128, 128, 255), closed_form_test.cpp
  EXPECT_NEAR(centre(run("rnm", r), r), 128.0 * d0 * b0t, 1e-2);
}

}  // namespace
}  // namespace gsdot3::pipeline
