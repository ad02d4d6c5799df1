// tests/pipeline/span_rule.hpp — the fill rule of ../shared/spec/gs-alu-facts.md written as spans, with exact
// rationals: rows ceil(y_top) .. ceil(y_bottom) exclusive; columns ceil(x_left) .. ceil(x_right) exclusive,
// where x_left/x_right are where the triangle's edges cross the row's centre line. Independent of the
// edge-function form in src/pipeline/raster.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pipeline/raster.hpp"

namespace gsdot3::pipeline::test {

// Is 16·px ≥ (or >) the x where edge a→b (a above b) crosses 16·py? Exact: cross-multiplied.
// x(py) = a.x + (16py − a.y)·(b.x − a.x)/(b.y − a.y).
inline std::int64_t side(xy124 a, xy124 b, int px, int py) {
  // sign of 16px − x(py), times (b.y − a.y) > 0
  return (std::int64_t{16} * px - a.x) * (b.y - a.y) - (std::int64_t{16} * py - a.y) * (b.x - a.x);
}

inline bool span_rule_covers(const std::array<xy124, 3>& v, int px, int py) {
  const std::int64_t y16 = std::int64_t{16} * py;
  // The two edges crossing the row (half-open in y, horizontal edges never cross).
  std::vector<std::pair<xy124, xy124>> crossing;
  for (int i = 0; i < 3; ++i) {
    xy124 a = v[static_cast<std::size_t>(i)], b = v[static_cast<std::size_t>((i + 1) % 3)];
    if (a.y > b.y) std::swap(a, b);
    if (a.y != b.y && a.y <= y16 && y16 < b.y) crossing.push_back({a, b});
  }
  if (crossing.size() != 2) return false;
  // Left edge: the one whose crossing is smaller; compare crossings exactly by testing each against px.
  const bool ge0 = side(crossing[0].first, crossing[0].second, px, py) >= 0;  // 16px ≥ x0
  const bool ge1 = side(crossing[1].first, crossing[1].second, px, py) >= 0;
  const bool gt0 = side(crossing[0].first, crossing[0].second, px, py) < 0;  // 16px < x0
  const bool gt1 = side(crossing[1].first, crossing[1].second, px, py) < 0;
  // px is inside iff it is ≥ one crossing and < the other.
  return (ge0 && gt1) || (ge1 && gt0);
}

}  // namespace gsdot3::pipeline::test
