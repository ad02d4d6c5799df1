// gs_arith/span_raster.hpp — rasterise_triangle's pixels as row spans: the fast path of the
// rasteriser (rasteriser.hpp, which stays the readable reference). Per row each edge's bound on x
// comes from one floor division, stepped from row to row without a division (floor_division_walk):
// edge E(x, y) = e0 + step_x·x + step_y·y + bias >= 0 with c(y) = e0 + step_y·y + bias is
// x >= −floor(c / step_x) for step_x > 0, x <= floor(c / −step_x) for step_x < 0, and every x or none
// (c >= 0) for step_x = 0; the span is those bounds within the bounding box and the clip. Equal to
// rasterise_triangle's pixels on every triangle (tests/gs_arith/span_raster_test.cpp: random and
// exhaustive small triangles, clipped).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "gs_arith/attribute_walk.hpp"
#include "gs_arith/rasteriser.hpp"

namespace gs {

// fn(y, x0, x1) for every row y with pixels, x in [x0, x1) (x0 < x1), rows in increasing y: the pixels
// rasterise_triangle(t, clip, ...) visits, in the same order.
template <class Fn>
void rasterise_spans(const triangle_setup& t, const scissor& clip, Fn&& fn) {
  if (t.area2 == 0) return;
  const auto e = raster_detail::edges(t);
  const auto [x0, x1, y0, y1] = raster_detail::bounds(t, clip);
  if (x0 >= x1 || y0 >= y1) return;
  std::array<floor_division_walk, 3> w{};
  for (std::size_t i = 0; i < 3; ++i)
    if (e[i].step_x != 0)  // floor(c(y) / |step_x|)
      w[i].start(e[i].e0 + e[i].step_y * y0 + e[i].bias, e[i].step_y, e[i].step_x < 0 ? -e[i].step_x : e[i].step_x);
  for (int y = y0; y < y1; ++y) {
    std::int64_t lo = x0, hi = x1;  // [lo, hi)
    for (std::size_t i = 0; i < 3; ++i) {
      if (e[i].step_x == 0) {
        if (e[i].e0 + e[i].step_y * y + e[i].bias < 0) hi = lo;
      } else if (e[i].step_x > 0) {
        lo = std::max(lo, -w[i].q);  // x >= −floor(c / step_x) = ceil(−c / step_x)
      } else {
        hi = std::min(hi, w[i].q + 1);  // x <= floor(c / −step_x)
      }
      w[i].step();
    }
    if (lo < hi) fn(y, static_cast<int>(lo), static_cast<int>(hi));
  }
}

}  // namespace gs
