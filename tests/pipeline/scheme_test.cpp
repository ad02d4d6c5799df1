// tests/pipeline/scheme_test.cpp — the hook the other seeds' schemes use (pixel_walk.hpp,
// scheme_method.hpp, the report's scheme rows), checked on the flat quad against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "pipeline/pixel_walk.hpp"
#include "pipeline/report.hpp"
#include "pipeline/scheme_method.hpp"
#include "pipeline/render.hpp"
#include "test_scenes.hpp"
#include "common/temp_dir.hpp"

namespace gsdot3::pipeline {
namespace {

// The scheme a float shader would be: 128·fade·N·normalize(T), with N the texel's palette normal.
scheme_frame exact_scheme(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                          const render_options&) {
  scheme_frame f;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  f.dot.assign(s.lights.size(), std::vector<float>(n, NAN));
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    const auto u = p.u16 >> 4, v = p.v16 >> 4;
    const glm::dvec3 N(s.normals.palette[s.normals.index[wrapped_texel(s.normals.width, s.normals.height, u, v)]]);
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const pixel_light pl = interpolate_light(ps, l, p);
      f.dot[l][p.index] = static_cast<float>(128.0 * pl.fade * glm::dot(N, glm::normalize(pl.T)));
    }
  });
  f.colour = compose_lit(s, ps, visible, f.dot, false, 1.0);
  return f;
}

// The same, clamped at zero (a scheme whose output cannot go negative).
scheme_frame clamped_scheme(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                            const render_options& o) {
  scheme_frame f = exact_scheme(s, ps, visible, o);
  for (auto& light : f.dot)
    for (float& d : light) d = std::isnan(d) ? d : std::max(d, 0.0f);
  return f;
}

TEST(SchemeHook, PixelWalkCoversTheQuadWithTheClosedFormDot) {
  const glm::vec3 n(0.3f, -0.2f, 0.93f), T(-0.5f, 0.4f, 0.77f);
  const auto q = test::make_flat_quad(n, T);
  const frame g = render(q.s, q.ps, method::four_pass, {});
  const scheme_frame f = exact_scheme(q.s, q.ps, g.visible_triangle, {});
  const double expected = 128.0 * glm::dot(glm::normalize(glm::dvec3(n)), glm::normalize(glm::dvec3(T)));
  int covered = 0;
  for (int y = 0; y < q.s.height; ++y)
    for (int x = 0; x < q.s.width; ++x) {
      const float d = f.dot[0][static_cast<std::size_t>(y * q.s.width + x)];
      const bool inside = x >= 8 && x < 56 && y >= 8 && y < 40;  // the quad's pixel centres
      ASSERT_EQ(inside, !std::isnan(d)) << x << "," << y;
      if (inside) {
        ++covered;
        EXPECT_NEAR(d, expected, 1e-3) << x << "," << y;
      }
    }
  EXPECT_EQ(covered, 48 * 32);
}

TEST(SchemeHook, ReportComparesSchemesWithTheReferenceAndClampsWhereTheySaySo) {
  const scheme_method exact{"exact-test", "none", "float N·L", false, exact_scheme};
  const scheme_method clamped{"clamped-test", "none", "float max(N·L, 0)", true, clamped_scheme};
  const auto dir = gsdot3::test::fresh_temp_dir("gsdot3-scheme-test");
  report_request req;
  req.out_dir = dir;
  req.methods = {method::two_pass};
  req.schemes = {&exact, &clamped};
  // The report prepares its scene itself (camera, lights): run it on the embedded scene.
  const report_summary sum = write_report(default_scene(), req);
  ASSERT_EQ(sum.schemes.size(), 2u);
  EXPECT_GT(sum.schemes[0].vs_renormalised.samples, 1000u);
  EXPECT_LT(sum.schemes[0].vs_renormalised.max_abs, 1e-3);  // the exact scheme is the reference (float rounding only)
  EXPECT_LT(sum.schemes[1].vs_renormalised.max_abs, 1e-3);  // clamped, compared with max(reference, 0)
  std::ifstream in(dir / "report.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["methods"]["clamped-test"]["compared_with"], "max(reference, 0)");
  EXPECT_EQ(j["methods"]["exact-test"]["seed"], "none");
  EXPECT_TRUE(std::filesystem::exists(dir / "clamped-test-error-light1.png"));
  std::filesystem::remove_all(dir);

  // On a quad lit from behind (N·L < 0 everywhere), the clamped scheme is 0 where the exact one is negative.
  const auto q = test::make_flat_quad({0, 0, 1}, {0.6f, 0, -0.8f});
  const frame g = render(q.s, q.ps, method::two_pass, {});
  const scheme_frame c = clamped_scheme(q.s, q.ps, g.visible_triangle, {});
  const std::size_t centre = static_cast<std::size_t>(20 * q.s.width + 30);
  EXPECT_EQ(c.dot[0][centre], 0.0f);
  EXPECT_NEAR(exact_scheme(q.s, q.ps, g.visible_triangle, {}).dot[0][centre], -0.8 * 128.0, 1e-3);
}

TEST(SchemeHook, TableNamesAreUniqueAndFound) {
  for (const auto& m : scheme_methods()) {
    EXPECT_EQ(find_scheme_method(m.name), &m);
    EXPECT_NE(m.render, nullptr);
    EXPECT_FALSE(m.summary.empty());
  }
  EXPECT_EQ(find_scheme_method("two-pass"), nullptr);
}

}  // namespace
}  // namespace gsdot3::pipeline
