// tests/pipeline/trace_test.cpp — render_options::trace (the report page's inspector data): tracing
// does not change the render, and each recorded pass holds what that pass computes, checked on a flat
// quad against its inputs (the packed vertex light, the CLUT entry) and the ILP's definition (3.4).
#include <gtest/gtest.h>

#include "pipeline/default_scene.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/render.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

TEST(Trace, TracedRenderIsTheRender) {
  scene s = default_scene(16);
  s.width = 64;
  s.height = 56;
  const prepared_scene ps = prepare(s);
  for (method m : {method::two_pass, method::four_pass, method::baseline}) {
    std::vector<pass_record> trace;
    render_options o;
    o.trace = &trace;
    const frame traced = render(s, ps, m, o), plain = render(s, ps, m, {});
    EXPECT_EQ(traced.colour, plain.colour) << name(m);
    EXPECT_EQ(traced.dot, plain.dot) << name(m);
    ASSERT_FALSE(trace.empty());
    const std::size_t n = static_cast<std::size_t>(s.width * s.height);
    for (const pass_record& p : trace) {
      EXPECT_EQ(p.word.size(), n) << p.label;
      EXPECT_EQ(p.colour.size(), 4 * n) << p.label;
    }
    // The last DPB pass of each light is the post-filter sum the frame reports.
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const pass_record* sum = nullptr;
      for (const pass_record& p : trace)
        if (p.light == static_cast<int>(l) && p.target == "DPB") sum = &p;
      ASSERT_NE(sum, nullptr);
      for (std::size_t i = 0; i < n; ++i)
        if (traced.visible_triangle[i] >= 0) {
          ASSERT_EQ(sum->word[i] & 0xFFu, traced.dot[l][i]) << name(m) << " pixel " << i;
        }
    }
  }
}

TEST(Trace, TwoPassPassesHoldTheirInputsAndOutputs) {
  const auto q = test::make_flat_quad({0, 0, 1}, {0.6f, 0, 0.8f});
  std::vector<pass_record> trace;
  render_options o;
  o.trace = &trace;
  const frame f = render(q.s, q.ps, method::two_pass, o);
  // 1, 2.1, 2.3 ×2, 2.4a, 2.4 ×2, 2.6, 3, 4 for one light.
  ASSERT_EQ(trace.size(), 10u);
  const pass_record &clear = trace[1], &positive = trace[2], &ilp = trace[7];
  EXPECT_EQ(ilp.target, "LAB");
  const gs::rgba8 light = pack_tolight(glm::normalize(glm::vec3{0.6f, 0, 0.8f}), 122);  // the vertex colour
  const gs::rgba8 texel = two_pass_palette(q.s.normals.palette, false)[0];              // palette entry 0
  const int vertex[4] = {light.r.value(), light.g.value(), light.b.value(), light.a.value()};
  std::size_t covered = 0;
  for (std::size_t i = 0; i < f.visible_triangle.size(); ++i) {
    if (f.visible_triangle[i] < 0) {
      EXPECT_EQ(positive.shaded[i], 0) << i;
      continue;
    }
    ++covered;
    EXPECT_EQ(clear.word[i], 0x00808080u);
    ASSERT_EQ(positive.shaded[i], 1) << i;
    EXPECT_EQ(positive.texel[i], texel.to_u32());
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(positive.colour[4 * i + static_cast<std::size_t>(k)], vertex[k] << 7)
          << k;                                // a constant plane: c.0 in 8.7
    const int d = (f.dot[0][i] - 128) & 0xFF;  // ILP (section 3.4): d + 1 for dot products d = 0..127, else 0
    const std::uint32_t level = d < 128 ? static_cast<std::uint32_t>(d + 1) : 0u;
    EXPECT_EQ(ilp.texel[i], 0x80000000u | level << 16 | level << 8 | level);
  }
  EXPECT_EQ(covered, 48u * 32u);
}

}  // namespace
}  // namespace gsdot3::pipeline
