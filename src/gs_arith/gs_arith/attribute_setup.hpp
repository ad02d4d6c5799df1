// gs_arith/attribute_setup.hpp — a triangle's per-pixel attributes as the model sets them up: the
// Gouraud colour plane (gs::gouraud_triangle) and the UV planes (gs::make_uv_plane). The renderer
// (pipeline/band_renderer.hpp attributes()) and the packet interpreter (gs_packets/draw.cpp) both call
// this, so a frame drawn from packets matches the renderer's bit for bit.
//
// Model choices, stated (no recording decides them; gs_arith/gouraud.hpp and rasteriser.hpp give
// the evidence and confidence of each plane's rounding):
// - The colour plane's reference pixel is the triangle's top-left pixel: min over the vertices of
//   ceil(x), and of ceil(y), in window pixels (under gouraud_setup::plane_steps the truncated steps'
//   error grows with distance from it; the other set-ups do not use it).
// - gouraud_triangle works in the GS's unsigned 16-bit 12.4 primitive space: window coordinates plus
//   `offset` whole pixels (XYOFFSET's whole-pixel part; the renderer's 2048), so that vertices left
//   of or above the window are not clamped.
// - U and V are 12.4 texel planes clamped to ±2^20 (MODEL-PLANE-16, rasteriser.hpp), converted to
//   the texel coordinate under the options uv_plane and uv_convert (uv_plane.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "gs_arith/colour.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/texture_function.hpp"
#include "gs_arith/uv_plane.hpp"

namespace gs {

struct triangle_attributes {
  gouraud_plane colour{};
  plane u, v;
  std::int32_t offset_x = 0, offset_y = 0;  // window pixel + offset = gouraud_triangle's pixel
  gouraud_setup setup = gouraud_setup::per_pixel_floor;
  // Cf at window pixel (x, y).
  constexpr fragment_colour colour_at(int x, int y) const noexcept {
    return gouraud_colour(colour, x + offset_x, y + offset_y, setup);
  }
};

// uv16[k] = {U, V} of vertex k in 12.4 texels. A zero-area triangle gives default (zero) planes.
// clip_x0: SCISSOR's left window pixel (gouraud_setup::pcsx2_rows starts a row there at the latest).
inline triangle_attributes setup_attributes(const triangle_setup& t, const std::array<rgba8, 3>& c,
                                            const std::array<std::array<std::int32_t, 2>, 3>& uv16,
                                            std::int32_t offset_x, std::int32_t offset_y, gouraud_setup setup,
                                            uv_rule uv, std::int32_t clip_x0 = 0) {
  triangle_attributes a;
  a.offset_x = offset_x;
  a.offset_y = offset_y;
  a.setup = setup;
  if (t.area2 == 0) return a;
  std::array<gouraud_vertex, 3> gv{};
  int x_ref = 1 << 16, y_ref = 1 << 16;
  for (std::size_t k = 0; k < 3; ++k) {
    gv[k] = {t.v[k].x + offset_x * 16, t.v[k].y + offset_y * 16, c[k]};
    x_ref = std::min(x_ref, ceil_124(t.v[k].x));
    y_ref = std::min(y_ref, ceil_124(t.v[k].y));
  }
  // gouraud_triangle clamps XY to 0..65535; empty only for zero area there.
  if (const auto g = gouraud_triangle(gv[0], gv[1], gv[2], x_ref + offset_x, y_ref + offset_y)) a.colour = *g;
  a.colour.clip_x0 = clip_x0 + offset_x;
  a.colour.lane_origin = offset_x;
  a.u = make_uv_plane(t.v, {uv16[0][0], uv16[1][0], uv16[2][0]}, uv);
  a.v = make_uv_plane(t.v, {uv16[0][1], uv16[1][1], uv16[2][1]}, uv);
  return a;
}

}  // namespace gs
