// proofs_rows_bound — the per-channel statements two-pass.max-s.interpolated's bound takes for the
// set-ups of a source (two_pass_triangle.hpp, above lag_window), checked against the model's colour
// on random small triangles, shallow and steep, at every pixel centre in the closed triangle. The
// plane is computed here from the barycentric weights in integers (not the model's plane), the row
// start by scanning the row for its first pixel centre in the triangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>

#include "gs_arith/gouraud.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"

namespace {
namespace tt = gsdot3::proofs::two_pass::triangle;
using i64 = std::int64_t;

struct tri {
  std::array<i64, 6> xy;  // 12.4
  std::array<int, 3> c;   // red levels
};
// Twice the signed area of (a, b, p), all in 12.4.
i64 edge(i64 ax, i64 ay, i64 bx, i64 by, i64 px, i64 py) { return (bx - ax) * (py - ay) - (by - ay) * (px - ax); }
// 128·det·P(p) for pixel centre (x, y), and det (> 0 after orientation).
struct plane_at {
  i64 num, det;
  bool inside;
};
plane_at plane(const tri& t, i64 x, i64 y) {
  const i64 px = 16 * x, py = 16 * y;
  i64 det = edge(t.xy[0], t.xy[1], t.xy[2], t.xy[3], t.xy[4], t.xy[5]);
  i64 w0 = edge(t.xy[2], t.xy[3], t.xy[4], t.xy[5], px, py), w1 = edge(t.xy[4], t.xy[5], t.xy[0], t.xy[1], px, py),
      w2 = edge(t.xy[0], t.xy[1], t.xy[2], t.xy[3], px, py);
  if (det < 0) det = -det, w0 = -w0, w1 = -w1, w2 = -w2;
  return {128 * (w0 * t.c[0] + w1 * t.c[1] + w2 * t.c[2]), det, w0 >= 0 && w1 >= 0 && w2 >= 0};
}

TEST(RowsBound, EveryPixelIsWithinTheWindowOrTheRowsSegment) {
  std::mt19937 rng(2026);
  std::uniform_int_distribution<int> coord(0, 40 * 16), level(1, 255), steep(0, 3);
  int pixels = 0, saturated = 0;
  for (int lanes : {4, 8}) {
    gs::model_options o;
    o.setup = lanes == 4 ? gs::gouraud_setup::pcsx2_rows_4 : gs::gouraud_setup::pcsx2_rows_8;
    const i64 W = tt::lag_window(o);
    for (int k = 0; k < 3000; ++k) {
      tri t{};
      const bool thin = steep(rng) == 0;  // a sliver a few pixels wide: steep rows
      for (int v = 0; v < 3; ++v) {
        t.xy[2 * v] = thin ? 16 * 20 + coord(rng) % 48 : coord(rng);
        t.xy[2 * v + 1] = coord(rng);
        t.c[v] = level(rng);
      }
      std::array<gs::gouraud_vertex, 3> gv{};
      for (int v = 0; v < 3; ++v)
        gv[v] = {static_cast<std::int32_t>(t.xy[2 * v]), static_cast<std::int32_t>(t.xy[2 * v + 1]),
                 gs::rgba8::from_u32(static_cast<std::uint32_t>(t.c[v]))};
      const auto p = gs::gouraud_triangle(gv[0], gv[1], gv[2], 0, 0);
      if (!p) continue;
      for (i64 y = 0; y <= 41; ++y) {
        i64 left = -1;
        for (i64 x = 0; x <= 41; ++x) {
          const auto at = plane(t, x, y);
          if (!at.inside) continue;
          if (left < 0) left = x;
          ++pixels;
          const auto first = plane(t, left, y);
          const i64 n = (x - left + left % lanes) / lanes;
          const i64 L =
              gs::gouraud_colour(*p, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), o.setup).r.value();
          // |L − P(p)| < W, i.e. |L·det − num| < W·det; or (n = 1) within 3 units of the segment P(left)..P(p)
          const bool near = std::abs(L * at.det - at.num) < W * at.det;
          const i64 lo = std::min(first.num * at.det, at.num * first.det),
                    hi = std::max(first.num * at.det, at.num * first.det);
          const i64 d2 = at.det * first.det, l = L * d2;
          const bool segment = n == 1 && l > lo - 3 * d2 && l < hi + 3 * d2;
          saturated += !near && segment;
          ASSERT_TRUE(near || segment) << "lanes " << lanes << " pixel (" << x << ", " << y << ") L " << L << " P·det "
                                       << at.num << "/" << at.det << " left " << left;
        }
      }
    }
  }
  EXPECT_GT(pixels, 100000);
  EXPECT_GT(saturated, 0);  // the steep case is exercised
}
}  // namespace
