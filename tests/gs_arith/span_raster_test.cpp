// gs::rasterise_spans (span_raster.hpp) against the reference rasteriser gs::rasterise_triangle: the same
// pixels in the same order on every triangle with 12.4 vertices in a small box (exhaustive over a
// coarse lattice), on random triangles of every size and orientation, and under clips.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "gs_arith/span_raster.hpp"

namespace gs {
namespace {

using pixels = std::vector<std::pair<int, int>>;

pixels reference_pixels(const triangle_setup& t, const scissor& clip) {
  pixels out;
  rasterise_triangle(t, clip, [&](int x, int y) { out.emplace_back(x, y); });
  return out;
}
pixels span_pixels(const triangle_setup& t, const scissor& clip) {
  pixels out;
  int last_y = -1 << 30;
  rasterise_spans(t, clip, [&](int y, int x0, int x1) {
    EXPECT_GT(y, last_y) << "rows in increasing y, one span each";
    EXPECT_LT(x0, x1);
    last_y = y;
    for (int x = x0; x < x1; ++x) out.emplace_back(x, y);
  });
  return out;
}
std::string describe(const triangle_setup& t) {
  std::ostringstream s;  // (a stream: g++ 12's -Wrestrict misfires on string concatenation)
  for (const xy124& v : t.v) s << '(' << v.x << ", " << v.y << ") ";
  return s.str();
}

TEST(SpanRaster, EveryTriangleOfASmallLatticeMatchesTheReference) {
  // Vertices on a 12.4 lattice of step 6 over 0..48 (9 × 9 points, sub-pixel offsets included): every
  // ordered triple with a distinct first vertex, both orientations, 9^6 = 531 441 triangles.
  const scissor clip{0, 0, 16, 16};
  long checked = 0, drawn = 0;
  std::vector<xy124> pts;
  for (int y = 0; y <= 48; y += 6)
    for (int x = 0; x <= 48; x += 6) pts.push_back({x, y});
  for (const xy124& a : pts)
    for (const xy124& b : pts)
      for (const xy124& c : pts) {
        const triangle_setup t = setup_triangle({a, b, c});
        const pixels want = reference_pixels(t, clip);
        ASSERT_EQ(span_pixels(t, clip), want) << describe(t);
        ++checked, drawn += !want.empty();
      }
  EXPECT_EQ(checked, 531441);
  EXPECT_GT(drawn, 100000) << "most lattice triangles cover a pixel";
}

TEST(SpanRaster, RandomTrianglesAndClipsMatchTheReference) {
  std::mt19937 rng(7);
  long drawn = 0;
  for (int i = 0; i < 20000; ++i) {
    const int range = i % 4 == 0 ? 16 * 600 : i % 4 == 1 ? 16 * 40 : i % 4 == 2 ? 16 * 6 : 16 * 2000;
    std::uniform_int_distribution<int> coord(0, range);
    std::array<xy124, 3> v{};
    for (xy124& p : v) p = {coord(rng), coord(rng)};
    const triangle_setup t = setup_triangle(v);
    std::uniform_int_distribution<int> edge(0, range / 16);
    const int cx0 = edge(rng) / 2, cy0 = edge(rng) / 2;
    const scissor clip = i % 3 == 0 ? scissor{0, 0, 2048, 2048} : scissor{cx0, cy0, cx0 + edge(rng), cy0 + edge(rng)};
    const pixels want = reference_pixels(t, clip);
    ASSERT_EQ(span_pixels(t, clip), want)
        << describe(t) << " clip " << clip.x0 << ", " << clip.y0 << ", " << clip.x1 << ", " << clip.y1;
    drawn += !want.empty();
  }
  EXPECT_GT(drawn, 5000);
}

}  // namespace
}  // namespace gs
