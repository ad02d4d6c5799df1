// gs_arith/rasteriser.hpp — the GS rasteriser (a hardware unit below the pipeline: the renderer and the
// packet interpreter draw through this one implementation).
//
// Evidence (../shared/spec/gs-alu-facts.md, "Rasterisation and interpolation"; PCSX2 SW only, not HW-verified):
// - Vertex XY are 12.4 fixed point; pixel centres are at integer coordinates.
// - Top-left fill rule: rows ceil(y_top) .. ceil(y_bottom) exclusive, columns ceil(x_left) ..
//   ceil(x_right) exclusive. Evaluated here with exact integer edge functions: a pixel centre on an
//   edge is inside only for a left edge (interior towards +x) or a horizontal top edge (interior
//   towards +y); `covers` states it and the tests check it against the digest's span rule.
// - Sprites: ceil of both corners, right and bottom excluded.
// - Attributes (UV in 12.4 texels, Z) are planes evaluated at the pixel centre. Z: value = (base +
//   dx·x + dy·y) >> 16, the gradients set up per triangle by exact integer division (floor) with 16
//   extra fraction bits, the result clamped to the attribute's range. The GS steps the same planes
//   with its own fraction width (SW: per pixel in 8.7; confidence low for the exact low bits, which no
//   recording covers). Model choice, stated: MODEL-PLANE-16. UV: that plane or the exact rational one
//   (make_exact_plane), the option uv_plane (docs/evidence.md R13). Gouraud colour: gouraud.hpp.
// - Back-face culling is the VU1's job on the PS2; here triangles whose screen area is ≥ 0
//   (clockwise in the y-down frame = facing away) are dropped when culling is on, as are
//   zero-area (edge-on) triangles, which cover no pixel centre anyway.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace gs {

// XY in 12.4 fixed point (pixels · 16), already minus XYOFFSET.
struct xy124 {
  std::int32_t x = 0, y = 0;
  friend constexpr bool operator==(const xy124&, const xy124&) = default;
};

// The integer pixel rectangle [x0, x1) × [y0, y1) drawing is clipped to (SCISSOR).
struct scissor {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool operator==(const scissor&) const = default;
};

// ceil(v / 16) for a 12.4 value (the first pixel centre at or after v).
constexpr int ceil_124(std::int32_t v) noexcept { return static_cast<int>((static_cast<std::int64_t>(v) + 15) >> 4); }

// floor(num / den) for den > 0.
constexpr std::int64_t floor_div(std::int64_t num, std::int64_t den) noexcept {
  return num >= 0 ? num / den : -((-num + den - 1) / den);
}

// A linear attribute over the screen, value(x, y) = floor(n / d) for n = base + dx·x + dy·y at pixel
// (x, y), clamped to [lo, hi]. Two forms (make_plane, make_exact_plane):
// - den == 0: fixed point, d = 2^16 (16 fraction bits below the attribute's unit; the value is n >> 16);
// - den > 0: exact, d = den; n / d is the attribute's rational value at the pixel centre. lift_1_64 adds
//   1/64 of the unit before the floor (uv_plane.hpp: the fixed form carries that bias in base instead).
struct plane {
  std::int64_t base = 0, dx = 0, dy = 0;
  std::int32_t lo = 0, hi = 0;
  std::int64_t den = 0;
  bool lift_1_64 = false;
  // The exact form's value from q = floor(n / den) and r = n − q·den: floor(n / den + 1/64) when lifted.
  constexpr std::int64_t lifted(std::int64_t q, std::int64_t r) const noexcept {
    return lift_1_64 && 64 * r >= 63 * den ? q + 1 : q;
  }
  // floor(n / d) before the clamp.
  constexpr std::int64_t quotient(std::int64_t n) const noexcept {
    if (den == 0) return n >> 16;
    const std::int64_t q = floor_div(n, den);
    return lifted(q, n - q * den);
  }
  constexpr std::int32_t at(int x, int y) const noexcept {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(quotient(base + dx * x + dy * y), lo, hi));
  }
};

// The plane through three vertex values a[i] (in the attribute's own fixed-point unit) at the
// three 12.4 positions; `area2` is the doubled signed area in 12.4² units (non-zero).
plane make_plane(const std::array<xy124, 3>& p, const std::array<std::int32_t, 3>& a, std::int32_t lo, std::int32_t hi);
// The same plane in exact form: den = |doubled area| (12.4² units), n / den the rational value.
plane make_exact_plane(const std::array<xy124, 3>& p, const std::array<std::int32_t, 3>& a, std::int32_t lo,
                       std::int32_t hi);

// Triangle set-up: the three edge functions oriented so the interior is positive.
struct triangle_setup {
  std::array<xy124, 3> v{};
  std::int64_t area2 = 0;  // doubled signed area in the y-down frame (12.4² units)
  bool front = false;      // counter-clockwise as seen on screen with y up (area2 < 0)
};
triangle_setup setup_triangle(const std::array<xy124, 3>& v);

// The fill rule for one pixel centre (x, y) of a triangle with non-zero area (the readable form).
bool covers(const triangle_setup& t, int x, int y);

// Calls fn(x, y) for every pixel centre the triangle covers inside `clip`, rows top to bottom,
// left to right: incremental edge functions, the same predicate as `covers`.
template <class Fn>
void rasterise_triangle(const triangle_setup& t, const scissor& clip, Fn&& fn);

// Calls fn(x, y) for every pixel of a sprite with corners a (top left) and b (bottom right).
template <class Fn>
void rasterise_sprite(xy124 a, xy124 b, const scissor& clip, Fn&& fn) {
  const int x0 = std::max(ceil_124(a.x), clip.x0), x1 = std::min(ceil_124(b.x), clip.x1);
  const int y0 = std::max(ceil_124(a.y), clip.y0), y1 = std::min(ceil_124(b.y), clip.y1);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) fn(x, y);
}

namespace raster_detail {
// Edge i runs from vertex i to vertex (i+1)%3; E(x,y) = dx·(y − y_a) − dy·(x − x_a) in 12.4² units,
// positive inside once the triangle is oriented; `bias` is 0 for top-left edges, −1 otherwise, so
// that "E + bias ≥ 0" is the fill rule.
struct edge {
  std::int64_t e0 = 0, step_x = 0, step_y = 0;  // E at pixel (0, 0), per +1 pixel in x, in y
  std::int64_t bias = 0;
};
std::array<edge, 3> edges(const triangle_setup& t);
// The pixels [x0, x1) × [y0, y1) a triangle's vertices bound, within the clip.
struct pixel_box {
  int x0, x1, y0, y1;
};
inline pixel_box bounds(const triangle_setup& t, const scissor& clip) {
  const auto [xmin, xmax] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
  const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
  return {std::max(ceil_124(xmin), clip.x0), std::min(ceil_124(xmax + 1), clip.x1), std::max(ceil_124(ymin), clip.y0),
          std::min(ceil_124(ymax + 1), clip.y1)};
}
}  // namespace raster_detail

template <class Fn>
void rasterise_triangle(const triangle_setup& t, const scissor& clip, Fn&& fn) {
  if (t.area2 == 0) return;
  const auto e = raster_detail::edges(t);
  const auto [x0, x1, y0, y1] = raster_detail::bounds(t, clip);
  for (int y = y0; y < y1; ++y) {
    std::int64_t w0 = e[0].e0 + e[0].step_x * x0 + e[0].step_y * y + e[0].bias;
    std::int64_t w1 = e[1].e0 + e[1].step_x * x0 + e[1].step_y * y + e[1].bias;
    std::int64_t w2 = e[2].e0 + e[2].step_x * x0 + e[2].step_y * y + e[2].bias;
    for (int x = x0; x < x1; ++x) {
      if ((w0 | w1 | w2) >= 0) fn(x, y);
      w0 += e[0].step_x;
      w1 += e[1].step_x;
      w2 += e[2].step_x;
    }
  }
}

}  // namespace gs
