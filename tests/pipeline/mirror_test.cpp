// A mirror-symmetric scene (the head mesh is symmetric in x, a flat normal map, one light on the
// mirror plane, the camera on it) gives a mirror-symmetric frame: pixel x and pixel W − x agree,
// except where a pixel centre lies exactly on a triangle edge (the top-left fill rule is not
// mirror-symmetric: a left edge includes its centres, a right edge excludes them), and up to one
// unit (1/128) on a few pixels: the GS's interpolation is not mirror-symmetric in its last bit (the
// 12.4 rounding of projected vertices, gradients truncated toward zero from the triangle's top-left
// pixel, texel addressing by floor). Measured on this scene: 186 / 50 / 254 of 14132 pixels differ
// by 1 (two-pass / four-pass / baseline). An asymmetric mesh (same-direction quad diagonals) gave
// differences up to 16: that is what this test guards against.
#include <gtest/gtest.h>

#include <cstdlib>

#include "pipeline/default_scene.hpp"
#include "pipeline/render.hpp"

namespace gsdot3::pipeline {
namespace {

bool on_an_edge(const prepared_scene& ps, int x, int y) {
  for (const prepared_triangle& t : ps.triangles)
    for (int i = 0; i < 3; ++i) {
      const xy124 a = t.setup.v[static_cast<std::size_t>(i)], b = t.setup.v[static_cast<std::size_t>((i + 1) % 3)];
      const std::int64_t e =
          static_cast<std::int64_t>(b.x - a.x) * (16 * y - a.y) - static_cast<std::int64_t>(b.y - a.y) * (16 * x - a.x);
      const bool within = 16 * x >= std::min(a.x, b.x) && 16 * x <= std::max(a.x, b.x) &&
                          16 * y >= std::min(a.y, b.y) && 16 * y <= std::max(a.y, b.y);
      if (e == 0 && within) return true;
    }
  return false;
}

class Mirror : public ::testing::TestWithParam<method> {};

TEST_P(Mirror, SymmetricSceneGivesSymmetricFrame) {
  scene s = default_scene(16);
  s.width = 128;
  s.height = 112;
  s.normals.index.assign(s.normals.index.size(), 0);
  s.normals.palette = {glm::vec3(0, 0, 1)};
  s.lights = {{{0.0f, 0.9f, 2.5f}, {0x80, 0x80, 0x80}}};
  s.view.eye = {0.0f, 0.15f, 3.6f};
  const prepared_scene ps = prepare(s);
  const frame f = render(s, ps, GetParam(), {});
  int compared = 0, mismatched = 0, worst = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 1; x < s.width; ++x) {
      const std::size_t a = static_cast<std::size_t>(y * s.width + x),
                        b = static_cast<std::size_t>(y * s.width + (s.width - x));
      if (on_an_edge(ps, x, y) || on_an_edge(ps, s.width - x, y)) continue;
      ++compared;
      const int d = std::abs(dot_value(f.dot[0][a]) - dot_value(f.dot[0][b]));
      if (d != 0) ++mismatched;
      worst = std::max(worst, d);
    }
  EXPECT_GT(compared, 10000);
  EXPECT_LE(worst, 1) << name(GetParam());
  EXPECT_LT(mismatched, compared / 40) << name(GetParam()) << ": " << mismatched << " of " << compared << " differ";
}

INSTANTIATE_TEST_SUITE_P(Methods, Mirror, ::testing::ValuesIn(gs_methods));

}  // namespace
}  // namespace gsdot3::pipeline
