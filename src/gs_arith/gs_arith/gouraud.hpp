// gs_arith/gouraud.hpp — Gouraud colour interpolation in 8.7 fixed point (PRIM.IIP = 1).
//
// Evidence (../shared/spec/gs-alu-facts.md, "Rasterisation and interpolation"): PCSX2 SW steps the RGBA colour in 8.7
// fixed point and clamps the stepped value at >= 0; flat shading (IIP = 0) takes the last vertex's
// colour. SW only, no hardware recording: confidence low for the exact rounding of the setup.
// The triangle set-up is option gs::gouraud_setup (docs/evidence.md R9, with the functions read):
// per_pixel (the exact plane at each pixel, truncated to whole units: DobieStation's and Play!'s float
// set-ups without their float rounding; the default, two sources), pcsx2_rows_4 / pcsx2_rows_8 (PCSX2
// SW's JIT path: each row starts from the plane at its first pixel, then truncated 16-bit lane offsets
// and vector steps of 4 or 8 pixels, gouraud_rows_at), per_pixel_level (parallel-gs: the exact plane,
// floored to a whole level after adding 1/256 level, gouraud_level_at) and plane_steps (one plane, both
// steps truncated, every pixel stepped from one reference pixel: the model's own DDA, no source does
// it). Spans (gouraud_span) step per pixel as below.
//
// The model, at value level (how to use it for "light vectors after the model's Gouraud interpolation"):
//   1. setup per primitive: a start value (8.7, signed, at a reference pixel) and a step per pixel
//      (8.7, signed). Rounding of the setup, named `toward_zero`: the exact rational gradient
//      (c1 − c0)·128 / distance is truncated toward zero (PCSX2 SW `CSetupPrim` converts its float
//      step with a truncating conversion). Truncating the step never overshoots the far endpoint.
//   2. per pixel, k steps from the start: value = start + k·step, exactly (no per-step rounding),
//   3. clamped to the 15-bit 8.7 range 0 .. 0x7FFF (255 + 127/128); the >= 0 clamp is the digest's,
//      the upper one only matters outside the primitive's own colour range.
// The result is a gs::gouraud_channel (fixed::uint<15>), the texture function's Cf input
// (gs::fragment_colour); integer_part() gives the 8-bit colour the blend and the alpha test see.
//
//   auto span = gs::gouraud_span(left, right, 16);  // 16 pixels from left to right
//   gs::fragment_colour cf = gs::gouraud_at(span, 5);  // the 6th pixel
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "fixed/integer.hpp"
#include "fixed/rounding.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/texture_function.hpp"

namespace gs {

// A per-pixel step in 8.7. A span's step |(c1 − c0)·128 / n| <= 32640 fits 16 bits signed; a thin
// triangle's plane can be far steeper (up to 255·128·16·131070 / 1 < 2^37), so steps carry 40 bits.
using gouraud_step = fixed::sint<40>;
// A start value in 8.7: 0 .. 32640 at a vertex; a prestep to a reference pixel may leave that range
// (|prestep| < 2^53 for 12.4 coordinates).
using gouraud_start = fixed::sint<56>;
// Pixel distances are clamped to ±2^16 (the GS's coordinate space is 4096 pixels), so that
// start + k·step stays below 2^62 and never overflows.
constexpr std::int64_t clamp_distance(std::int64_t k) noexcept { return k < -65536 ? -65536 : k > 65536 ? 65536 : k; }

// The 8.7 value of an 8-bit vertex colour channel.
constexpr gouraud_start gouraud_value(u8 c) noexcept { return gouraud_start::from_wrapped(c.value() << 7); }

// trunc(num / den) for den != 0, in 64-bit (callers keep |num| < 2^62).
constexpr std::int64_t divide_toward_zero(std::int64_t num, std::int64_t den) noexcept { return num / den; }

// Step per pixel from c0 to c1 over `pixels` pixels (>= 1; 0 or less gives step 0).
constexpr gouraud_step gouraud_gradient(u8 c0, u8 c1, int pixels) noexcept {
  if (pixels <= 0) return gouraud_step{};
  return gouraud_step::from_wrapped(divide_toward_zero((c1.value() - c0.value()) * 128, pixels));
}

// start + k·step, clamped to 0 .. 0x7FFF.
constexpr gouraud_channel gouraud_at(gouraud_start start, gouraud_step step, std::int64_t k) noexcept {
  return gouraud_channel::from_saturated(start.value() + clamp_distance(k) * step.value());
}

// A span (line or scanline) from colour c0 at pixel 0 to c1 at pixel `pixels`.
struct gouraud_span_setup {
  std::array<gouraud_start, 4> start;  // r, g, b, a
  std::array<gouraud_step, 4> step;
};

constexpr gouraud_span_setup gouraud_span(rgba8 c0, rgba8 c1, int pixels) noexcept {
  const std::array<u8, 4> a{c0.r, c0.g, c0.b, c0.a}, b{c1.r, c1.g, c1.b, c1.a};
  gouraud_span_setup s{};
  for (int i = 0; i < 4; ++i) {
    s.start[i] = gouraud_value(a[i]);
    s.step[i] = gouraud_gradient(a[i], b[i], pixels);
  }
  return s;
}

constexpr fragment_colour gouraud_at(const gouraud_span_setup& s, std::int64_t k) noexcept {
  return {gouraud_at(s.start[0], s.step[0], k), gouraud_at(s.start[1], s.step[1], k),
          gouraud_at(s.start[2], s.step[2], k), gouraud_at(s.start[3], s.step[3], k)};
}

// A triangle vertex: XY in 12.4 fixed point (after XYOFFSET), colour from RGBAQ.
struct gouraud_vertex {
  std::int32_t x16, y16;  // 0 .. 65535 (16 bits, units of 1/16 pixel)
  rgba8 c;
};

// The exact rational plane through the three vertices, per channel: at 12.4 offset (px, py) from
// vertex 0 the value is c0 + (nx·px + ny·py)·128 / det 8.7 units (|nx|, |ny| < 2^25, |det| < 2^33).
struct gouraud_exact_plane {
  std::int64_t x0 = 0, y0 = 0, det = 1;  // vertex 0 in 12.4 (clamped to 0..65535), twice the area
  std::array<std::int64_t, 6> xy{};      // the three vertices in 12.4 (clamped), for the row starts
  std::array<gouraud_start, 4> c0{};
  std::array<std::int64_t, 4> nx{}, ny{};
};

// The exact plane at 12.4 offset (px, py) from vertex 0, truncated toward zero to whole 8.7 units
// from vertex 0's value (|px|, |py| <= 2^21 keep every product below 2^62).
constexpr std::int64_t exact_plane_units(const gouraud_exact_plane& e, int i, std::int64_t px,
                                         std::int64_t py) noexcept {
  return e.c0[i].value() + divide_toward_zero((e.nx[i] * px + e.ny[i] * py) * 128, e.det);
}

// A triangle's colour plane: the value at reference pixel (x_ref, y_ref) and the steps per pixel in x
// and in y, each truncated toward zero from the exact rational plane through the three vertices
// (gouraud_setup::plane_steps), and that exact plane (gouraud_setup::per_pixel).
struct gouraud_plane {
  std::int32_t x_ref, y_ref;
  std::array<gouraud_start, 4> base;
  std::array<gouraud_step, 4> dx, dy;
  gouraud_exact_plane exact;
  std::int64_t clip_x0 = 0;      // SCISSOR's left in this pixel space (pcsx2_rows' row start)
  std::int64_t lane_origin = 0;  // the frame's pixel 0 in this pixel space (pcsx2_rows' vectors align there)
};

// Empty for a degenerate (zero-area) triangle. Pixel centres are at integer coordinates.
constexpr std::optional<gouraud_plane> gouraud_triangle(const gouraud_vertex& v0, const gouraud_vertex& v1,
                                                        const gouraud_vertex& v2, std::int32_t x_ref,
                                                        std::int32_t y_ref) noexcept {
  // Coordinates are taken as 16-bit 12.4 values (clamped to 0..65535), so |nx|, |ny| < 2^25,
  // |px|, |py| <= 2^20 and every product below stays under 2^62; dx, dy < 2^36, base < 2^54.
  auto c16 = [](std::int64_t v) { return v < 0 ? 0 : v > 65535 ? 65535 : v; };
  const std::int64_t x0 = c16(v0.x16), y0 = c16(v0.y16);
  const std::int64_t ax = c16(v1.x16) - x0, ay = c16(v1.y16) - y0, bx = c16(v2.x16) - x0, by = c16(v2.y16) - y0;
  const std::int64_t det = ax * by - bx * ay;  // twice the area in (1/16 pixel)^2
  if (det == 0) return std::nullopt;
  const std::array<u8, 4> c0{v0.c.r, v0.c.g, v0.c.b, v0.c.a}, c1{v1.c.r, v1.c.g, v1.c.b, v1.c.a},
      c2{v2.c.r, v2.c.g, v2.c.b, v2.c.a};
  const std::int64_t px = clamp_distance(x_ref) * 16 - x0, py = clamp_distance(y_ref) * 16 - y0;
  gouraud_plane p{x_ref, y_ref, {}, {}, {}, {x0, y0, det, {x0, y0, ax + x0, ay + y0, bx + x0, by + y0}, {}, {}, {}}};
  for (int i = 0; i < 4; ++i) {
    const std::int64_t d1 = c1[i].value() - c0[i].value(), d2 = c2[i].value() - c0[i].value();
    // dC per 1/16 pixel: gx = (d1·by − d2·ay) / det, gy = (d2·ax − d1·bx) / det.
    const std::int64_t nx = d1 * by - d2 * ay, ny = d2 * ax - d1 * bx;
    p.exact.c0[i] = gouraud_value(c0[i]);
    p.exact.nx[i] = nx, p.exact.ny[i] = ny;
    p.dx[i] = gouraud_step::from_wrapped(divide_toward_zero(nx * 128 * 16, det));
    p.dy[i] = gouraud_step::from_wrapped(divide_toward_zero(ny * 128 * 16, det));
    p.base[i] = gouraud_start::from_wrapped(exact_plane_units(p.exact, i, px, py));
  }
  return p;
}

// The fragment colour at pixel (x, y): base + (x − x_ref)·dx + (y − y_ref)·dy, clamped.
constexpr fragment_colour gouraud_at(const gouraud_plane& p, std::int32_t x, std::int32_t y) noexcept {
  auto ch = [&](int i) {
    const std::int64_t v = p.base[i].value() + clamp_distance(std::int64_t{x} - p.x_ref) * p.dx[i].value() +
                           clamp_distance(std::int64_t{y} - p.y_ref) * p.dy[i].value();
    return gouraud_channel::from_saturated(v);
  };
  return {ch(0), ch(1), ch(2), ch(3)};
}

// The fragment colour at pixel (x, y) under gouraud_setup::per_pixel: the exact plane there, truncated
// toward zero to whole 8.7 units from vertex 0's value, clamped (the start value's formula of
// gouraud_triangle, evaluated at every pixel; equal to gouraud_at at the reference pixel).
constexpr fragment_colour gouraud_exact_at(const gouraud_plane& p, std::int32_t x, std::int32_t y) noexcept {
  const std::int64_t px = clamp_distance(x) * 16 - p.exact.x0, py = clamp_distance(y) * 16 - p.exact.y0;
  auto ch = [&](int i) { return gouraud_channel::from_saturated(exact_plane_units(p.exact, i, px, py)); };
  return {ch(0), ch(1), ch(2), ch(3)};
}

// The exact plane of channel i at pixel (x, y) as the fraction num / den of 8.7 units, den > 0.
struct plane_fraction {
  std::int64_t num, den;
};
constexpr plane_fraction exact_plane_fraction(const gouraud_exact_plane& e, int i, std::int64_t x,
                                              std::int64_t y) noexcept {
  const std::int64_t px = clamp_distance(x) * 16 - e.x0, py = clamp_distance(y) * 16 - e.y0;
  const std::int64_t num = e.c0[i].value() * e.det + (e.nx[i] * px + e.ny[i] * py) * 128;
  return e.det < 0 ? plane_fraction{-num, -e.det} : plane_fraction{num, e.det};
}

// gouraud_setup::per_pixel_level (parallel-gs gs/shaders/ubershader.comp compute_combined_color: the
// barycentric colour floor(255·(c0 + (c1 − c0)·i + (c2 − c0)·j) + 1/256), a whole level): the exact plane
// at the pixel plus 1/256 level (half an 8.7 unit), floored to a whole level, in 8.7: 128·floor((2P + 1)/256). Its
// float barycentrics (i, j from integer edge functions times an approximate reciprocal of the area,
// gs/shaders/intersect.h evaluate_coverage_single) are taken as exact: ~2^-24 relative, below the bias.
constexpr fragment_colour gouraud_level_at(const gouraud_plane& p, std::int32_t x, std::int32_t y) noexcept {
  auto ch = [&](int i) {
    const auto f = exact_plane_fraction(p.exact, i, x, y);
    return gouraud_channel::from_saturated(128 * floor_div(2 * f.num + f.den, 256 * f.den));
  };
  return {ch(0), ch(1), ch(2), ch(3)};
}

// PCSX2 SW's row start (GSRasterizer.cpp DrawTriangleSection): the least pixel at or right of the
// triangle's left edge on row y, ceil(x_edge), and not left of `clip_x0` (SCISSOR's left, in the same
// pixel space). Exact here (PCSX2 walks the edge in float). A row the triangle does not reach gives x.
constexpr std::int64_t gouraud_row_start(const gouraud_exact_plane& e, std::int64_t x, std::int64_t y,
                                         std::int64_t clip_x0) noexcept {
  const std::int64_t y16 = clamp_distance(y) * 16;
  std::int64_t best = -1;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t xa = e.xy[2 * k], ya = e.xy[2 * k + 1], xb = e.xy[(2 * k + 2) % 6], yb = e.xy[(2 * k + 3) % 6];
    if (y16 < (ya < yb ? ya : yb) || y16 > (ya < yb ? yb : ya)) continue;
    std::int64_t num = xa * (yb - ya) + (y16 - ya) * (xb - xa), den = 16 * (yb - ya);
    if (ya == yb) num = xa < xb ? xa : xb, den = 16;
    if (den < 0) num = -num, den = -den;
    const std::int64_t start = -floor_div(-num, den);  // ceil
    if (best < 0 || start < best) best = start;
  }
  if (best < 0) return x;
  return best < clip_x0 ? clip_x0 : best;
}

// x86 packssdw (a 32-bit lane saturated to 16 bits signed) and paddw (16-bit wrap).
constexpr std::int64_t saturate16(std::int64_t v) noexcept { return v < -32768 ? -32768 : v > 32767 ? 32767 : v; }
constexpr std::int64_t wrap16(std::int64_t v) noexcept { return ((v + 32768) & 0xFFFF) - 32768; }

// gouraud_setup::pcsx2_rows_4 / pcsx2_rows_8, PCSX2 SW's JIT path (read at 0361ab3c / 02f831f3):
// GSRasterizer::DrawTriangleSection sets each row's start colour in float from the plane at the row's
// first pixel `left` (edge.c + dedge.c·dy + dscan.c·prestep); GSSetupPrimCodeGenerator.all.cpp Color()
// truncates (cvttps2dq) the colour step of one vector, dscan.c · lanes, and each lane's offset dscan.c ·
// (lane − skip), and saturates both to 16 bits (packssdw); CDrawScanline / the JIT scanline convert the
// row start with truncation, add the lane offsets (16-bit), and per further vector add the step and
// clamp at >= 0 (add16, max_i16). skip = left mod lanes in frame pixels (the vector is aligned). The float plane is
// taken as exact here. At pixel x: n = the vectors after the first, m = x − left − n·lanes.
constexpr std::int64_t gouraud_rows_units(const gouraud_exact_plane& e, int i, std::int64_t x, std::int64_t y,
                                          int lanes, std::int64_t clip_x0, std::int64_t lane_origin = 0) noexcept {
  const std::int64_t left = gouraud_row_start(e, x, y, clip_x0);
  const auto f = exact_plane_fraction(e, i, left, y);
  const std::int64_t start = f.num / f.den;  // the truncating conversion of the row's start value
  const std::int64_t skip = (left - lane_origin) - floor_div(left - lane_origin, lanes) * lanes;
  const std::int64_t n = x < left - skip ? 0 : (x - (left - skip)) / lanes;
  const std::int64_t m = x - left - n * lanes;
  const std::int64_t g2048 = e.nx[i] * 2048;  // the x gradient · det, 8.7 units per pixel
  const std::int64_t step = saturate16(divide_toward_zero(g2048 * lanes, e.det));
  std::int64_t v = wrap16(start + saturate16(divide_toward_zero(g2048 * m, e.det)));
  if (n == 0) return v;
  if (step >= 0 && v + n * step <= 32767 && (n - 1) * step <= 32767) {  // max(0, ·) per step, no wrap
    const std::int64_t a = v + n * step, b = (n - 1) * step;
    return a > b ? a : b;
  }
  if (step < 0 && v + step >= -32768) {
    const std::int64_t a = v + clamp_distance(n) * step;
    return a > 0 ? a : 0;
  }
  for (std::int64_t k = 0; k < n; ++k) v = wrap16(v + step) < 0 ? 0 : wrap16(v + step);
  return v;
}
constexpr fragment_colour gouraud_rows_at(const gouraud_plane& p, std::int32_t x, std::int32_t y, int lanes) noexcept {
  auto ch = [&](int i) {
    return gouraud_channel::from_saturated(gouraud_rows_units(p.exact, i, x, y, lanes, p.clip_x0, p.lane_origin));
  };
  return {ch(0), ch(1), ch(2), ch(3)};
}

// gouraud_setup::per_pixel_floor: the exact plane at (x, y) floored to whole 8.7 units, clamped.
constexpr fragment_colour gouraud_floor_at(const gouraud_plane& p, std::int32_t x, std::int32_t y) noexcept {
  auto ch = [&](int i) {
    const auto f = exact_plane_fraction(p.exact, i, x, y);
    return gouraud_channel::from_saturated(floor_div(f.num, f.den));
  };
  return {ch(0), ch(1), ch(2), ch(3)};
}

// The fragment colour at pixel (x, y) under the set-up in force.
constexpr fragment_colour gouraud_colour(const gouraud_plane& p, std::int32_t x, std::int32_t y,
                                         gouraud_setup s) noexcept {
  switch (s) {
    case gouraud_setup::per_pixel: return gouraud_exact_at(p, x, y);
    case gouraud_setup::plane_steps: return gouraud_at(p, x, y);
    case gouraud_setup::pcsx2_rows_4: return gouraud_rows_at(p, x, y, 4);
    case gouraud_setup::pcsx2_rows_8: return gouraud_rows_at(p, x, y, 8);
    case gouraud_setup::per_pixel_level: return gouraud_level_at(p, x, y);
    case gouraud_setup::per_pixel_floor: return gouraud_floor_at(p, x, y);
  }
  return gouraud_exact_at(p, x, y);
}

// PRIM.IIP = 0: the whole primitive takes the last vertex's colour.
constexpr fragment_colour flat_shading(rgba8 last_vertex) noexcept { return fragment_colour::flat(last_vertex); }

}  // namespace gs
