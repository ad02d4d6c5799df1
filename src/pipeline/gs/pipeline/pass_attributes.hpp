// pipeline/pass_attributes.hpp — the per-triangle attributes a triangle pass draws with: the Gouraud
// colour plane and the UV planes (gs::setup_attributes) from the pass's vertex colours and texture
// coordinates. Internal to render.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "gs_arith/attribute_setup.hpp"
#include "gs_arith/options.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/raster.hpp"

namespace gsdot3::pipeline::detail {

// Per-triangle attributes of one pass: the Gouraud plane and the UV planes (gs::setup_attributes).
using tri_attr = gs::triangle_attributes;

// The pixels a triangle can cover: its vertices' bounding box (12.4), rounded out by a pixel each side.
constexpr scissor vertex_bounds(const gs::triangle_setup& s) noexcept {
  const auto [x0, x1] = std::minmax({s.v[0].x, s.v[1].x, s.v[2].x});
  const auto [y0, y1] = std::minmax({s.v[0].y, s.v[1].y, s.v[2].y});
  return {(x0 >> 4) - 1, (y0 >> 4) - 1, (x1 >> 4) + 2, (y1 >> 4) + 2};
}
// Whether a triangle can cover a pixel of rows [y0, y1).
constexpr bool may_cover_rows(const gs::triangle_setup& s, int y0, int y1) noexcept {
  const scissor b = vertex_bounds(s);
  return b.y0 < y1 && b.y1 > y0;
}

// Vertex colours → per-triangle attributes of `triangles` (the DOT3 mesh's, or step 5's); `uv` picks
// the 12.4 texture coordinates per corner. Only a band's rows [y0, y1) (all rows if not given) are drawn with them: a
// triangle that cannot cover one of its pixels keeps default attributes (no pass of the band reads them, as it
// rasterises nothing of that triangle), which halves each band's set-up at 2 threads.
template <class Colour, class UV>
std::vector<tri_attr> attributes(const std::vector<prepared_triangle>& triangles, const gs::model_options& model,
                                 Colour&& colour, UV&& uv, int y0 = std::numeric_limits<int>::min(),
                                 int y1 = std::numeric_limits<int>::max()) {
  std::vector<tri_attr> out(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const prepared_triangle& tri = triangles[t];
    if (!may_cover_rows(tri.setup, y0, y1)) continue;
    std::array<gs::rgba8, 3> c{};
    std::array<std::array<std::int32_t, 2>, 3> uv16{};
    for (int k = 0; k < 3; ++k) {
      c[static_cast<std::size_t>(k)] = colour(tri.vertex[static_cast<std::size_t>(k)]);
      const auto [u, v] = uv(tri, k);
      uv16[static_cast<std::size_t>(k)] = {u, v};
    }
    out[t] = gs::setup_attributes(tri.setup, c, uv16, xy_offset_pixels, xy_offset_pixels, model.setup,
                                  gs::uv_rule_of(model));
  }
  return out;
}
template <class Colour, class UV>
std::vector<tri_attr> attributes(const prepared_scene& ps, const gs::model_options& model, Colour&& colour, UV&& uv,
                                 int y0 = std::numeric_limits<int>::min(), int y1 = std::numeric_limits<int>::max()) {
  return attributes(ps.triangles, model, colour, uv, y0, y1);
}

}  // namespace gsdot3::pipeline::detail
