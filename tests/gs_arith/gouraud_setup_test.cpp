// gs_arith_gouraud_setup — the triangle colour set-ups of gs::gouraud_colour on small triangles whose
// values are worked by hand below (exact fractions, then the rounding each set-up names), not read
// back from the model.
#include <gtest/gtest.h>

#include "gs_arith/gouraud.hpp"

namespace {
using gs::gouraud_setup;
using gs::rgba8;

// Vertex at whole pixel (x, y) with red channel r (the other channels 0, alpha 0x80).
gs::gouraud_vertex at(int x, int y, int r) {
  return {16 * x, 16 * y, rgba8::from_u32(0x80000000u | static_cast<unsigned>(r))};
}

int red(const gs::gouraud_plane& p, int x, int y, gouraud_setup s) { return gs::gouraud_colour(p, x, y, s).r.value(); }

// A(0, 0) = 0, B(40, 0) = 7, C(0, 8) = 0: red = 7·128·x/40 = 22.4·x units, the same on every row; the
// left edge is x = 0, so every row starts at pixel 0 with start value 0 and skip 0.
// Lane offsets trunc(22.4·m): m = 1 → 22, 3 → 67, 5 → 112, 7 → 156; steps trunc(89.6) = 89 (4 lanes),
// trunc(179.2) = 179 (8 lanes).
TEST(GouraudSetup, Pcsx2RowsOnAnAxisAlignedRamp) {
  const auto p = gs::gouraud_triangle(at(0, 0, 0), at(40, 0, 7), at(0, 8, 0), 0, 0);
  ASSERT_TRUE(p.has_value());
  // x = 13: 4 lanes n = 3, m = 1: 22 + 3·89 = 289; 8 lanes n = 1, m = 5: 112 + 179 = 291;
  // the exact plane 291.2 truncates to 291.
  EXPECT_EQ(red(*p, 13, 2, gouraud_setup::pcsx2_rows_4), 289);
  EXPECT_EQ(red(*p, 13, 2, gouraud_setup::pcsx2_rows_8), 291);
  EXPECT_EQ(red(*p, 13, 2, gouraud_setup::per_pixel), 291);
  // x = 39: 4 lanes n = 9, m = 3: 67 + 9·89 = 868; 8 lanes n = 4, m = 7: 156 + 4·179 = 872; exact 873.6.
  EXPECT_EQ(red(*p, 39, 0, gouraud_setup::pcsx2_rows_4), 868);
  EXPECT_EQ(red(*p, 39, 0, gouraud_setup::pcsx2_rows_8), 872);
  EXPECT_EQ(red(*p, 39, 0, gouraud_setup::per_pixel), 873);
  // per_pixel_level: 128·floor((22.4·x + 1/2)/128), a whole level: x = 11 → 246.9 → 128; x = 17 → 381.3 → 256.
  EXPECT_EQ(red(*p, 11, 1, gouraud_setup::per_pixel_level), 128);
  EXPECT_EQ(red(*p, 17, 1, gouraud_setup::per_pixel_level), 256);
}

// A(6, 0) = 0, B(40, 0) = 7, C(2, 8) = 0: the left edge AC is x = 6 − y/2 and red is 0 along it, so
// red = 896·(x − 6 + y/2)/34 units (gradient 896/34 = 26.35 per pixel). Row 3: the edge at 4.5, the
// row starts at pixel 5 with 896·0.5/34 = 13.18 → 13; lane offsets trunc(26.35·m), steps trunc(105.41) =
// 105 (4 lanes) and trunc(210.82) = 210 (8 lanes).
TEST(GouraudSetup, Pcsx2RowsStartAtTheRowsFirstPixel) {
  const auto p = gs::gouraud_triangle(at(6, 0, 0), at(40, 0, 7), at(2, 8, 0), 0, 0);
  ASSERT_TRUE(p.has_value());
  // Row 3 covers pixels 5 .. 25 (the right edge BC is at 25.75). x = 25: 4 lanes: skip 1, the vector
  // from 4, n = 5, m = 25 − 5 − 20 = 0: 13 + 5·105 = 538; 8 lanes: skip 5, n = 3, m = −4:
  // 13 + trunc(−105.41) + 3·210 = 538; the exact plane 896·20.5/34 = 540.2 → 540.
  EXPECT_EQ(red(*p, 25, 3, gouraud_setup::pcsx2_rows_4), 538);
  EXPECT_EQ(red(*p, 25, 3, gouraud_setup::pcsx2_rows_8), 538);
  EXPECT_EQ(red(*p, 25, 3, gouraud_setup::per_pixel), 540);
  // x = 12: 4 lanes n = 2, m = −1: 13 − 26 + 2·105 = 197; exact 896·7.5/34 = 197.6 → 197.
  EXPECT_EQ(red(*p, 12, 3, gouraud_setup::pcsx2_rows_4), 197);
  // A scissor from pixel 20 on: the row starts there, 896·15.5/34 = 408.5 → 408; x = 25, 4 lanes: skip 0,
  // n = 1, m = 1: 408 + 26 + 105 = 539.
  auto clipped = *p;
  clipped.clip_x0 = 20;
  EXPECT_EQ(red(clipped, 25, 3, gouraud_setup::pcsx2_rows_4), 539);
}

// A(3, 0) = 0, B(5, 0) = 255, C(3, 2) = 0: red = 16320·(x − 3) units per pixel on row 0, which starts
// at 3. 4 lanes: skip 3, pixel 4 is the next vector's lane 0: offset trunc(16320·(−3)) = −48960
// saturates to −32768, the step 65280 to 32767, and −32768 + 32767 = −1 clamps to 0. 8 lanes: pixel 4 is
// still in the first vector (lane 4, offset 16320). The exact plane: 16320.
TEST(GouraudSetup, Pcsx2RowsSaturateASteepVectorStep) {
  const auto p = gs::gouraud_triangle(at(3, 0, 0), at(5, 0, 255), at(3, 2, 0), 0, 0);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(red(*p, 4, 0, gouraud_setup::pcsx2_rows_4), 0);
  EXPECT_EQ(red(*p, 4, 0, gouraud_setup::pcsx2_rows_8), 16320);
  EXPECT_EQ(red(*p, 4, 0, gouraud_setup::per_pixel), 16320);
}

// A(108, 0) = 0, B(108, 1500) = 0, C(1132, 0) = 2: red = 0.25·(x − 108) units. At x = 619: 127.75, within
// half a unit below the level 128: per_pixel truncates to 127, per_pixel_level (+1/2 unit) floors to 128.
TEST(GouraudSetup, PerPixelLevelLiftsHalfAUnitBelowALevel) {
  const auto p = gs::gouraud_triangle(at(108, 0, 0), at(108, 1500, 0), at(1132, 0, 2), 0, 0);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(red(*p, 619, 2, gouraud_setup::per_pixel), 127);
  EXPECT_EQ(red(*p, 619, 2, gouraud_setup::per_pixel_level), 128);
  EXPECT_EQ(red(*p, 617, 2, gouraud_setup::per_pixel_level), 0);  // 127.25 + 0.5 < 128
}

// A(623, 0) = 1, B(2671, 0) = 0, C(623, 8) = 1: red = 128 − (x − 623)/16 units, falling away from vertex 0.
// At x = 627: 127.75. per_pixel_floor floors the value, 127; per_pixel truncates the distance −0.25 from
// vertex 0's 128 toward zero, 128 (issue 53: DobieStation's float truncation of the value is the former).
// At x = 631: 127.5, the same split; at x = 639 (623 + 16): exactly 127 under both.
TEST(GouraudSetup, PerPixelFloorFloorsTheValueNotTheDistanceFromVertexZero) {
  const auto falling = gs::gouraud_triangle(at(623, 0, 1), at(2671, 0, 0), at(623, 8, 1), 0, 0);
  // Rising from vertex 0 the two agree: the ramp of PerPixelLevelLiftsHalfAUnitBelowALevel, 127.75 -> 127.
  const auto rising = gs::gouraud_triangle(at(108, 0, 0), at(108, 1500, 0), at(1132, 0, 2), 0, 0);
  ASSERT_TRUE(falling.has_value() && rising.has_value());
  const struct {
    const gs::gouraud_plane& p;
    int x;
    int floored, from_vertex_0;  // per_pixel_floor, per_pixel
  } cases[] = {
      {*falling, 627, 127, 128}, {*falling, 631, 127, 128}, {*falling, 639, 127, 127}, {*rising, 619, 127, 127}};
  for (const auto& c : cases) {
    EXPECT_EQ(red(c.p, c.x, 2, gouraud_setup::per_pixel_floor), c.floored) << c.x;
    EXPECT_EQ(red(c.p, c.x, 2, gouraud_setup::per_pixel), c.from_vertex_0) << c.x;
  }
}

// The option's names and its default (the value with the most sources, docs/evidence.md R9).
TEST(GouraudSetup, OptionNamesAndDefault) {
  gs::model_options o;
  EXPECT_EQ(gs::option_value(o, "gouraud_setup"), "per_pixel_floor");
  for (const char* v :
       {"plane_steps", "pcsx2_rows_4", "pcsx2_rows_8", "per_pixel_level", "per_pixel", "per_pixel_floor"}) {
    EXPECT_FALSE(gs::set_option(o, "gouraud_setup", v).has_value()) << v;
    EXPECT_EQ(gs::option_value(o, "gouraud_setup"), v);
  }
  EXPECT_TRUE(gs::set_option(o, "gouraud_setup", "pcsx2_rows").has_value());
}
}  // namespace
