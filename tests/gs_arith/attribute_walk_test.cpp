// gs_arith_attribute_walk — gs::attribute_walker (the stepped fast path) against the readable
// formulas it replaces: triangle_attributes::colour_at and plane::at at every pixel a triangle
// covers, under every gouraud_setup and each uv_plane and uv_convert (drawn at random), pixel by pixel (at) and
// as runs of a row (row);
// floor_division_walk against C++'s own division.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "gs_arith/attribute_walk.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/span_raster.hpp"

namespace {

constexpr std::array<gs::gouraud_setup, 6> setups{
    gs::gouraud_setup::per_pixel_floor, gs::gouraud_setup::per_pixel,    gs::gouraud_setup::plane_steps,
    gs::gouraud_setup::pcsx2_rows_4,    gs::gouraud_setup::pcsx2_rows_8, gs::gouraud_setup::per_pixel_level};

// floor(n / d) written with truncating division and a correction, and trunc(n / d) as C++ gives it.
std::int64_t floor_of(std::int64_t n, std::int64_t d) { return n / d - (n % d != 0 && (n < 0) != (d < 0) ? 1 : 0); }

// Every start n0 in −60..60, step s in −60..60, divisor d in 1..17, 40 steps: quotient, remainder
// and the truncated quotient after each step (121·121·17·40 = 9 955 880 cases).
TEST(AttributeWalk, FloorDivisionWalkOnEverySmallCase) {
  gs::floor_division_walk w;  // one walk restarted throughout: with the step kept, and with a new step or divisor
  for (std::int64_t d = 1; d <= 17; ++d)
    for (std::int64_t s = -60; s <= 60; ++s)
      for (std::int64_t n0 = -60; n0 <= 60; ++n0) {
        w.start(n0, s, d);
        for (std::int64_t k = 0; k < 40; ++k) {
          const std::int64_t n = n0 + k * s;
          ASSERT_EQ(w.q, floor_of(n, d)) << n << " / " << d;
          ASSERT_EQ(w.r, n - d * floor_of(n, d)) << n << " / " << d;
          ASSERT_EQ(w.toward_zero(), n / d) << n << " / " << d;
          w.step();
        }
      }
}

struct walk_case {
  std::array<gs::xy124, 3> v;
  std::array<gs::rgba8, 3> c;
  std::array<std::array<std::int32_t, 2>, 3> uv;
  std::int32_t offset;
  gs::uv_rule uv_rule;
};

// Compares the walker with the reference at every covered pixel in raster order, and at every
// `skip`-th pixel only (moves that are not one pixel right start again).
void expect_walk_equal(const walk_case& k, gs::gouraud_setup s, int skip) {
  const gs::triangle_setup t = gs::setup_triangle(k.v);
  if (t.area2 == 0) return;
  const gs::triangle_attributes a = gs::setup_attributes(t, k.c, k.uv, k.offset, k.offset, s, k.uv_rule);
  gs::attribute_walker w(a);
  int n = 0;
  gs::rasterise_triangle(t, {0, 0, 1024, 1024}, [&](int x, int y) {
    if (n++ % skip != 0) return;
    const auto got = w.at(x, y);
    RC_ASSERT(static_cast<bool>(got.cf == a.colour_at(x, y)));
    RC_ASSERT(got.u == a.u.at(x, y));
    RC_ASSERT(got.v == a.v.at(x, y));
  });
}

// row(): the covered pixels as runs of a row (rasterise_triangle visits rows top down, x rising), or
// with `box` every row of the vertices' bounding box widened by 8 pixels each side (outside the
// triangle the planes leave [lo, hi] and clamp), each run cut at lengths up to `longest`, through
// attribute_walker::row, against the reference.
void expect_rows_equal(const walk_case& k, gs::gouraud_setup s, int longest, bool box) {
  const gs::triangle_setup t = gs::setup_triangle(k.v);
  if (t.area2 == 0) return;
  const gs::triangle_attributes a = gs::setup_attributes(t, k.c, k.uv, k.offset, k.offset, s, k.uv_rule);
  struct run {
    int x0, y, n;
  };
  std::vector<run> runs;
  auto add = [&](int x, int y) {
    if (!runs.empty() && runs.back().y == y && runs.back().x0 + runs.back().n == x && runs.back().n < longest)
      ++runs.back().n;
    else
      runs.push_back({x, y, 1});
  };
  if (box) {
    int x0 = 1 << 20, x1 = 0, y0 = 1 << 20, y1 = 0;
    for (const gs::xy124& p : k.v)
      x0 = std::min(x0, p.x / 16), x1 = std::max(x1, p.x / 16), y0 = std::min(y0, p.y / 16),
      y1 = std::max(y1, p.y / 16);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0 - 8; x <= x1 + 8; ++x) add(x, y);
  } else {
    gs::rasterise_triangle(t, {0, 0, 1024, 1024}, add);
  }
  gs::attribute_walker w(a);
  std::size_t pixels = 0;
  for (const run& r : runs) {
    int next = 0;
    w.row(r.x0, r.y, r.n, [&](int i, const gs::attribute_walker::values& got) {
      RC_ASSERT(i == next++);
      const int x = r.x0 + i;
      RC_ASSERT(static_cast<bool>(got.cf == a.colour_at(x, r.y)));
      RC_ASSERT(got.u == a.u.at(x, r.y));
      RC_ASSERT(got.v == a.v.at(x, r.y));
      ++pixels;
    });
    RC_ASSERT(next == r.n);
  }
  std::size_t covered = 0;
  for (const run& r : runs) covered += static_cast<std::size_t>(r.n);
  RC_ASSERT(pixels == covered);
}

rc::Gen<walk_case> triangle_gen(int span) {
  auto xy = rc::gen::construct<gs::xy124>(rc::gen::inRange(0, span * 16), rc::gen::inRange(0, span * 16));
  auto colour =
      rc::gen::map(rc::gen::arbitrary<std::uint32_t>(), [](std::uint32_t c) { return gs::rgba8::from_u32(c); });
  auto uv = rc::gen::container<std::array<std::int32_t, 2>>(rc::gen::inRange(-(1 << 16), 1 << 16));
  return rc::gen::construct<walk_case>(
      rc::gen::container<std::array<gs::xy124, 3>>(xy), rc::gen::container<std::array<gs::rgba8, 3>>(colour),
      rc::gen::container<std::array<std::array<std::int32_t, 2>, 3>>(uv), rc::gen::element(0, 2048, 4000),
      rc::gen::map(rc::gen::pair(rc::gen::element(gs::uv_plane_mode::exact, gs::uv_plane_mode::fixed_16),
                                 rc::gen::element(gs::uv_convert_mode::floor, gs::uv_convert_mode::floor_1_64)),
                   [](const auto& r) {
                     return gs::uv_rule{r.first, r.second};
                   }));
}

RC_GTEST_PROP(AttributeWalk, EqualsTheReferenceOnSmallTriangles, ()) {
  const walk_case k = *triangle_gen(48);
  for (gs::gouraud_setup s : setups) expect_walk_equal(k, s, 1);
}

RC_GTEST_PROP(AttributeWalk, EqualsTheReferenceOnLargeAndThinTriangles, ()) {
  const walk_case k = *triangle_gen(700);
  const int skip = *rc::gen::element(1, 1, 3);
  for (gs::gouraud_setup s : setups) expect_walk_equal(k, s, skip);
}

RC_GTEST_PROP(AttributeWalk, RowsEqualTheReference, ()) {
  walk_case k = *triangle_gen(*rc::gen::element(48, 700));
  if (*rc::gen::arbitrary<bool>()) k.c[1] = k.c[2] = k.c[0];
  const int longest = *rc::gen::element(1, 2, 7, 64, 4096);
  for (gs::gouraud_setup s : setups) expect_rows_equal(k, s, longest, false);
}

RC_GTEST_PROP(AttributeWalk, RowsOverTheBoundingBoxEqualTheReference, ()) {
  const walk_case k = *triangle_gen(48);
  const int longest = *rc::gen::element(2, 7, 64, 4096);
  for (gs::gouraud_setup s : setups) expect_rows_equal(k, s, longest, true);
}

// Equal vertex colours (the methods' white passes): the walker keeps the colour it computed where it
// started (attribute_walk.hpp); the reference evaluates the plane at every pixel.
RC_GTEST_PROP(AttributeWalk, EqualsTheReferenceWithEqualVertexColours, ()) {
  walk_case k = *triangle_gen(300);
  k.c[1] = k.c[2] = k.c[0];
  const int skip = *rc::gen::element(1, 1, 3);
  for (gs::gouraud_setup s : setups) expect_walk_equal(k, s, skip);
}

// The pixel distance crosses clamp_distance's bound (±2^16) inside a row: the walker starts again
// there, as the reference's clamp stops the plane. A 4000-pixel triangle whose red rises by four levels
// (0.128 units per pixel) stays unsaturated 65 536 pixels out, so the clamp shows in the colour.
TEST(AttributeWalk, RowsAcrossTheDistanceClamp) {
  const gs::triangle_setup t = gs::setup_triangle({gs::xy124{0, 0}, gs::xy124{16 * 4000, 0}, gs::xy124{0, 16 * 4000}});
  const std::array<gs::rgba8, 3> c{gs::rgba8::from_u32(0x80808080), gs::rgba8::from_u32(0x7C7C8484),
                                   gs::rgba8::from_u32(0x80808080)};
  for (gs::gouraud_setup s : setups) {
    gs::triangle_attributes a = gs::setup_attributes(t, c, {}, 0, 0, s, gs::uv_rule{});
    a.offset_x = 65536 - 30;  // pixels 0..59 of a row are at distances 65506 .. 65565
    gs::attribute_walker w(a), rows(a);
    rows.row(0, 1, 60, [&](int x, const gs::attribute_walker::values& got) {
      ASSERT_TRUE(got.cf == a.colour_at(x, 1)) << "row, x " << x;
    });
    std::array<int, 2> red_changes{};  // before and after the bound
    for (int x = 0; x < 60; ++x) {
      ASSERT_TRUE(w.at(x, 1).cf == a.colour_at(x, 1)) << "x " << x;
      if (x > 0) red_changes[x + a.offset_x > 65536] += a.colour_at(x, 1).r != a.colour_at(x - 1, 1).r;
    }
    // per_pixel shows it (plane_steps' truncated step is 0 here, and a step of one unit per pixel
    // saturates long before the bound).
    if (s == gs::gouraud_setup::per_pixel) {
      EXPECT_GT(red_changes[0], 0);  // the plane moves before the bound ...
      EXPECT_EQ(red_changes[1], 0);  // ... and not after it
    }
  }
}

// plane_walk::at along each row a triangle covers against plane::at, for the depth plane of the
// renderer's set-up (make_plane, 16 fraction bits: vertex depths of 24 bits) and an exact plane (vertex
// values within ±2^20, the UV planes' range and more): random triangles in a 1024² window, each clamped
// to a random [lo, hi] inside its values' range, so that the clamp acts at either end.
RC_GTEST_PROP(AttributeWalk, PlaneWalkAlongRowsIsPlaneAt, ()) {
  const auto coordinate = rc::gen::inRange(0, 16 * 1024);
  std::array<gs::xy124, 3> v;
  for (gs::xy124& p : v) p = {*coordinate, *coordinate};
  const gs::triangle_setup t = gs::setup_triangle(v);
  if (t.area2 == 0) return;
  std::array<std::int32_t, 3> z, e;
  for (std::int32_t& k : z) k = *rc::gen::inRange(0, 0x1000000);
  for (std::int32_t& k : e) k = *rc::gen::inRange(-(1 << 20), 1 << 20);
  const std::int32_t zlo = *rc::gen::inRange(0, 1 << 23), elo = *rc::gen::inRange(-(1 << 20), 0);
  const gs::plane depth = gs::make_plane(v, z, zlo, zlo + *rc::gen::inRange(0, 1 << 23));
  const gs::plane exact = gs::make_exact_plane(v, e, elo, elo + *rc::gen::inRange(0, 1 << 21));
  for (const gs::plane& p : {depth, exact})
    gs::rasterise_spans(t, {0, 0, 1024, 1024}, [&](int y, int x0, int x1) {
      gs::plane_walk w;
      w.start(p, x0, y);
      for (int x = x0; x < x1; ++x, w.step(p)) RC_ASSERT(w.at(p) == p.at(x, y));
    });
}

}  // namespace
