// gs_arith/rasteriser.cpp — triangle set-up, edge functions and attribute planes (see rasteriser.hpp).
#include "gs_arith/rasteriser.hpp"

#include <stdexcept>
#include <string>

namespace gs {

namespace {

// floor(a / b) for b of either sign.
std::int64_t floor_div_signed(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

std::int64_t cross(xy124 a, xy124 b, xy124 c) {
  return static_cast<std::int64_t>(b.x - a.x) * (c.y - a.y) - static_cast<std::int64_t>(b.y - a.y) * (c.x - a.x);
}

}  // namespace

triangle_setup setup_triangle(const std::array<xy124, 3>& v) {
  triangle_setup t;
  t.v = v;
  t.area2 = cross(v[0], v[1], v[2]);
  t.front = t.area2 < 0;
  return t;
}

namespace raster_detail {

std::array<edge, 3> edges(const triangle_setup& t) {
  // Orientation: with area2 > 0 the interior is on the positive side of each edge function as
  // defined; with area2 < 0 all three flip sign.
  const std::int64_t sign = t.area2 > 0 ? 1 : -1;
  std::array<edge, 3> e{};
  for (int i = 0; i < 3; ++i) {
    const xy124 a = t.v[i], b = t.v[(i + 1) % 3];
    const std::int64_t dx = sign * (b.x - a.x), dy = sign * (b.y - a.y);
    // E(px, py) = dx·(16·py − a.y) − dy·(16·px − a.x)
    e[i].step_x = -dy * 16;
    e[i].step_y = dx * 16;
    e[i].e0 = -dx * a.y + dy * a.x;
    // Interior towards +x (∂E/∂x > 0) is a left edge; horizontal with interior towards +y is a top edge.
    const bool top_left = e[i].step_x > 0 || (e[i].step_x == 0 && e[i].step_y > 0);
    e[i].bias = top_left ? 0 : -1;
  }
  return e;
}

}  // namespace raster_detail

bool covers(const triangle_setup& t, int x, int y) {
  for (const raster_detail::edge& e : raster_detail::edges(t)) {
    const std::int64_t w = e.e0 + e.step_x * x + e.step_y * y;
    if (w < 0 || (w == 0 && e.bias != 0)) return false;
  }
  return t.area2 != 0;
}

namespace {
// The doubled signed area det (12.4² units) and the gradient numerators of the plane through a[k] at
// p[k]: the value changes by gx / det per 12.4 unit of x and gy / det per unit of y.
struct plane_gradient {
  std::int64_t det, gx, gy;
};
plane_gradient gradient(const std::array<xy124, 3>& p, const std::array<std::int32_t, 3>& a, const char* who) {
  const std::int64_t det = cross(p[0], p[1], p[2]);
  if (det == 0) throw std::logic_error(std::string(who) + ": zero-area triangle");
  const std::int64_t da1 = a[1] - a[0], da2 = a[2] - a[0];
  const std::int64_t x1 = p[1].x - p[0].x, y1 = p[1].y - p[0].y, x2 = p[2].x - p[0].x, y2 = p[2].y - p[0].y;
  return {det, da1 * y2 - da2 * y1, da2 * x1 - da1 * x2};
}
}  // namespace

plane make_plane(const std::array<xy124, 3>& p, const std::array<std::int32_t, 3>& a, std::int32_t lo,
                 std::int32_t hi) {
  const plane_gradient g = gradient(p, a, "make_plane");
  // Per pixel ×16, kept with 16 extra fraction bits.
  constexpr std::int64_t one = std::int64_t{1} << 16;
  plane pl;
  pl.dx = floor_div_signed(g.gx * 16 * one, g.det);
  pl.dy = floor_div_signed(g.gy * 16 * one, g.det);
  // value(0,0) = a0 − gradient·(p0 in pixels), p0 in 12.4 so divide by 16.
  pl.base = a[0] * one - floor_div_signed(pl.dx * p[0].x + pl.dy * p[0].y, 16);
  pl.lo = lo;
  pl.hi = hi;
  return pl;
}

plane make_exact_plane(const std::array<xy124, 3>& p, const std::array<std::int32_t, 3>& a, std::int32_t lo,
                       std::int32_t hi) {
  const plane_gradient g = gradient(p, a, "make_exact_plane");
  // value(X, Y) = a0 + (gx·(X − X0) + gy·(Y − Y0)) / det at 12.4 position (X, Y); pixel x is at X = 16x.
  const std::int64_t sign = g.det < 0 ? -1 : 1;
  plane pl;
  pl.den = sign * g.det;
  pl.dx = sign * g.gx * 16;
  pl.dy = sign * g.gy * 16;
  pl.base = sign * (a[0] * g.det - g.gx * p[0].x - g.gy * p[0].y);
  pl.lo = lo;
  pl.hi = hi;
  return pl;
}

}  // namespace gs
