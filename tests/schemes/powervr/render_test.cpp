// tests/schemes/powervr/render_test.cpp — the seed 004 report methods on the flat quad (one normal,
// one directional light, fade 1): every covered pixel is the closed form 128·clamp(N·L, 0, 1) within
// the bump unit's a-priori 8-bit bound (bounds.hpp, scaled from 1/255 to 1/128) plus the texel's
// quantisation (the normal's direction moves by at most π/1020 + π/255 rad: |ΔN·L| ≤ that angle).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../../pipeline/test_scenes.hpp"
#include "bounds.hpp"
#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline {
namespace {

TEST(PowervrRender, FlatQuadIsTheClosedForm) {
  const glm::vec3 n(0.3f, -0.2f, 0.93f), T(-0.5f, 0.4f, 0.77f);
  const auto q = test::make_flat_quad(n, T);
  const frame g = render(q.s, q.ps, method::four_pass, {});
  const double NL = glm::dot(glm::normalize(glm::dvec3(n)), glm::normalize(glm::dvec3(T)));
  const double angle = std::numbers::pi / 1020.0 + std::numbers::pi / 255.0;
  for (auto name : {"pvr-float", "pvr-fixed8", "pvr-gouraud", "pvr-pixel"}) {
    const auto* m = find_scheme_method(name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_TRUE(m->non_negative);
    const auto p = std::string_view(name) == "pvr-fixed8" ? schemes::powervr::precision::fixed8
                                                          : schemes::powervr::precision::float32;
    const double bound = (schemes::powervr::test::identity_error_bound(p) + 255.0 * angle) * 128.0 / 255.0;
    const scheme_frame f = m->render(q.s, q.ps, g.visible_triangle, {});
    int covered = 0;
    for (float d : f.dot[0])
      if (!std::isnan(d)) {
        ++covered;
        ASSERT_NEAR(d, 128.0 * std::clamp(NL, 0.0, 1.0), bound) << name;
      }
    EXPECT_EQ(covered, 48 * 32) << name;
  }
}

}  // namespace
}  // namespace gsdot3::pipeline
