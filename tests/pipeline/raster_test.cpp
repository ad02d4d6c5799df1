// Fill rule and attribute planes of the pipeline's rasteriser.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <random>

#include "pipeline/raster.hpp"
#include "span_rule.hpp"

namespace gsdot3::pipeline {
namespace {

std::map<std::pair<int, int>, int> hits_of_quad(xy124 a, xy124 b) {
  // Two triangles sharing the diagonal, both front-facing: (a, bl, tr) and (tr, bl, b).
  const xy124 tr{b.x, a.y}, bl{a.x, b.y};
  std::map<std::pair<int, int>, int> hits;
  const scissor all{-64, -64, 256, 256};
  for (const auto& tri : {std::array<xy124, 3>{a, bl, tr}, std::array<xy124, 3>{tr, bl, b}})
    rasterise_triangle(setup_triangle(tri), all, [&](int x, int y) { ++hits[{x, y}]; });
  return hits;
}

// A fully covered rectangle drawn as two triangles covers exactly the sprite rule of
// ../shared/spec/gs-alu-facts.md (ceil of both corners, right and bottom excluded), every pixel once: no
// gaps, no double hits.
TEST(FillRule, QuadOfTwoTrianglesEqualsSpriteRule) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coord(0, 100 * 16);
  for (int trial = 0; trial < 500; ++trial) {
    xy124 a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
    if (a.x > b.x) std::swap(a.x, b.x);
    if (a.y > b.y) std::swap(a.y, b.y);
    if (trial % 5 == 0) a = {a.x & ~15, a.y & ~15}, b = {b.x & ~15, b.y & ~15};  // corners on pixel centres
    if (a.x == b.x || a.y == b.y) continue;
    const auto hits = hits_of_quad(a, b);
    std::map<std::pair<int, int>, int> expected;
    const scissor all{-64, -64, 256, 256};
    rasterise_sprite(a, b, all, [&](int x, int y) { ++expected[{x, y}]; });
    // The sprite rule itself, written out: ceil(v/16) for the corners.
    auto ceil16 = [](int v) { return (v + 15) / 16; };
    ASSERT_EQ(expected.size(), static_cast<std::size_t>((ceil16(b.x) - ceil16(a.x)) * (ceil16(b.y) - ceil16(a.y))));
    ASSERT_EQ(hits, expected) << "corners " << a.x << "," << a.y << " " << b.x << "," << b.y << " (12.4)";
  }
}

// The triangle rasteriser (incremental edge functions), the readable predicate `covers` and the
// digest's span rule (exact rationals, tests/pipeline/span_rule.hpp) agree on random triangles,
// including many with vertices and edges through pixel centres.
TEST(FillRule, TrianglesMatchTheSpanRule) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> fine(0, 40 * 16), coarse(0, 40);
  const scissor all{-8, -8, 64, 64};
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<xy124, 3> v{};
    for (auto& p : v) p = trial % 2 ? xy124{fine(rng), fine(rng)} : xy124{coarse(rng) * 16, coarse(rng) * 16};
    const triangle_setup t = setup_triangle(v);
    if (t.area2 == 0) continue;
    std::set<std::pair<int, int>> raster;
    rasterise_triangle(t, all, [&](int x, int y) { raster.insert({x, y}); });
    for (int y = -8; y < 64; ++y)
      for (int x = -8; x < 64; ++x) {
        const bool expect = test::span_rule_covers(v, x, y);
        ASSERT_EQ(covers(t, x, y), expect) << "pixel " << x << "," << y << " triangle " << v[0].x << "," << v[0].y
                                           << " " << v[1].x << "," << v[1].y << " " << v[2].x << "," << v[2].y;
        ASSERT_EQ(raster.count({x, y}) == 1, expect) << "pixel " << x << "," << y;
      }
  }
}

// A plane through three values reproduces them at pixel-centre vertices and is exact for
// attributes linear in whole pixels.
TEST(Plane, ExactAtVerticesAndForIntegerGradients) {
  const std::array<xy124, 3> p{xy124{16 * 2, 16 * 3}, xy124{16 * 20, 16 * 3}, xy124{16 * 2, 16 * 13}};
  // value = 100 + 5·(x − 2) − 7·(y − 3)
  auto f = [](int x, int y) { return 100 + 5 * (x - 2) - 7 * (y - 3); };
  const plane pl = make_plane(p, {f(2, 3), f(20, 3), f(2, 13)}, -100000, 100000);
  for (int y = 3; y <= 13; ++y)
    for (int x = 2; x <= 20; ++x) ASSERT_EQ(pl.at(x, y), f(x, y)) << x << "," << y;
}

TEST(Plane, ClampsToItsRange) {
  const std::array<xy124, 3> p{xy124{0, 0}, xy124{160, 0}, xy124{0, 160}};
  const plane pl = make_plane(p, {0, 1000, 0}, 0, 500);
  EXPECT_EQ(pl.at(-5, 0), 0);
  EXPECT_EQ(pl.at(9, 0), 500);
}

}  // namespace
}  // namespace gsdot3::pipeline
