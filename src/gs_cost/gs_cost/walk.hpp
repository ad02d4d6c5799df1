// gs_cost/walk.hpp — one primitive walked as the GS pipeline walks it (jbit, constants.hpp): two-row
// bands top to bottom, each band's blocks (8x2, or 4x2 textured, aligned to multiples of the block
// size) left to right. Counted on the way: the pixels covered (the rasteriser of gs_arith, the
// renderer's and the interpreter's, with SCISSOR), the blocks touched, the changes of the frame / Z
// page pair (gs_memory's swizzle: the page of the block's first covered pixel in each buffer), and the
// texture misses (the texel leaving the page or quarter page of the last one, in pixel order within
// each block).
//
// A band's blocks are those of the hull of its two rows' spans (a triangle's rows are each one span);
// the texel of a pixel is the top-left texel of its footprint (u >> 4 nearest, (u - 8) >> 4 bilinear)
// through CLAMP, from the UV plane through the vertices (uv_plane.hpp make_uv_plane, under the default
// uv_plane and uv_convert), not the renderer's full attribute set-up: the page it falls in, not its value, is what
// is counted.
// The page state carries over from one primitive to the next (the GS keeps its page open).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "gs_cost/constants.hpp"
#include "gs_packets/draw.hpp"

namespace gs::cost {

// The decoded drawing state a walk needs (register fields as the GS User's Manual lays them out,
// transcribed in PCSX2 GSRegs.h; decoded leniently: a value the model's strict decoders refuse still
// walks, with its bits as they are).
struct draw_mode {
  unsigned prim = 0;  // PRIM.PRIM
  bool textured = false, bilinear = false, blend_reads_dst = false, fst = false;
  bool z_read = false, z_write = false;
  std::uint32_t frame_psm = 0, z_psm = 0x30, tex_psm = 0;
};
draw_mode decode_mode(const packets::draw_registers& r);

struct page_state {
  std::optional<std::uint32_t> frame, z, texture;  // the open pages (texture: page or quarter index)
};

struct walk_counts {
  std::uint64_t pixels = 0;
  std::uint64_t blocks = 0;
  std::uint64_t page_breaks = 0;     // changes of the (frame page, Z page) pair, the first one included
  std::uint64_t texture_misses = 0;  // changes of the texture unit, the first one included
  friend constexpr bool operator==(const walk_counts&, const walk_counts&) = default;
};

// Walks one primitive (2 vertices for SPRITE, 3 for the triangle types; others walk nothing).
walk_counts walk_primitive(const packets::draw_registers& r, std::span<const packets::vertex> v, page_state& pages,
                           texture_unit unit);

}  // namespace gs::cost
