// pipeline/texture_stream.hpp — textures bigger than the GS memory beside the frame buffers, streamed
// as a PS2 game streams them: each pass uploads the pieces of its texture it needs, when it needs
// them, into a window of free pages, and draws its triangles over one screen rectangle (SCISSOR_1)
// per set of pieces. One description for the renderer's memory path (render.cpp runs the uploads
// through the packet interpreter and draws with the piece's TEX0) and the dump writer
// (frame_packets.cpp writes the same transfers, TEX0 and SCISSOR_1), so the dump replays bit for bit.
//
// A cell is one page of the texel grid: texels [pw·c, pw·c + pw) × [ph·r, ph·r + ph) of a PSM with
// pages pw × ph (PSMT4 128 × 128, PSMT8 128 × 64, PSMCT32 64 × 32). With TEX0 TBP0 = B and TBW, texel
// (u, v) is at page (B/32 + u/pw + (v/ph)·w) mod 512, w = TBW·64/pw pages per row of pages, at the offset
// inside the page that (u mod pw, v mod ph) gives (gs_memory's locate: the page term is linear, the
// swizzle is within the page; the memory wraps at 4 MiB, gs_memory/fast_address.hpp). So a cell can be
// put in any page by a page-sized host -> local transfer there, and TBW may be chosen per piece
// (TBW·64 below the texture's width is only a smaller page stride of the same address function):
// a piece picks w and B so that the cells its pixels fetch land in distinct pages of the window.
//
// Why the pieces give the unsplit pass's frame bit for bit (tests/pipeline/texture_stream_test.cpp
// checks it against the value path, which reads the host arrays):
// 1. the pieces' rectangles partition the drawn area (a k-d split of it), so every fragment of the
//    pass is drawn in exactly one piece, and within a piece in the pass's triangle order; a fragment
//    only reads and writes its own pixel's frame and Z words, so the order of the pieces changes
//    nothing and the scissor cuts no fragment's value (the rasteriser and the UV planes are the
//    unsplit pass's: SCISSOR_1 is a per-pixel test after them). Except under gouraud_setup
//    pcsx2_rows_4 / _8: PCSX2 starts a row's Gouraud colour at max(the triangle's left edge, SCISSOR's
//    left) (gs_arith/gouraud.hpp gouraud_row_start), so there the pieces are whole rows of the drawn
//    area, cut along y only: their left is the drawn area's, left of every triangle's edge
//    (band_renderer::drawn_area: a pixel left of every vertex), so no row start moves. A row too big
//    for the window is split by triangles instead: pieces over the same row drawing consecutive
//    ranges of the pass's triangles, in order, so each pixel's fragments keep the pass's order;
// 2. a piece's cell set holds every cell any of its fragments fetches: it is found by the same UV
//    planes (gs::setup_attributes), rasteriser and gs::sample footprint (nearest or the 2 × 2 of
//    bilinear) with REPEAT wrapping, over every triangle pixel in the rectangle (a superset: the
//    depth test is not applied); cells map to distinct pages, and each is uploaded there unless that
//    page still holds that cell of that texture, so every fetch reads the texel the host array has.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "gs_arith/attribute_setup.hpp"
#include "gs_arith/bilinear.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_memory/fast_address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/builder.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/raster.hpp"

namespace gsdot3::pipeline {

// What cannot be streamed (more cells under one pixel than the window has pages): the CLI reports
// it as a one-line error with exit 2.
struct texture_does_not_fit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whether a triangle's pixels (within a pixel of its vertices' bounding box) can be in rectangle r.
bool may_cover(const prepared_triangle& t, const scissor& r);

// A streamed texture: its texels row-major, one byte each for PSMT4 and PSMT8 indices, four for
// PSMCT32 (host_transfer packs PSMT4's), and an id that tells textures apart in the window.
struct stream_texture {
  int id = 0;
  const char* name = "";  // for messages: "normal map", "diffuse texture"
  gs::mem::psm PSM = gs::mem::psm::PSMT8;
  int width = 0, height = 0;
  std::span<const std::uint8_t> texels;
  std::optional<triangle_range> triangles;  // the triangles that sample it (a layer's); nullopt: every one
};

struct cell_upload {
  std::uint32_t page;  // the window page the cell is transferred into
  int c, r;            // the cell: column and row of pages of the texel grid
};
// One piece of a pass: upload `uploads`, then draw the pass's triangles of `triangles` with
// SCISSOR_1 = area and TEX0 TBP0 / TBW / PSM = at.
struct stream_piece {
  scissor area;
  triangle_range triangles;
  gs::mem::buffer at;
  std::vector<cell_upload> uploads;
  // Whether triangle i (t) is drawn in this piece: in the range, and its pixels can reach the area.
  bool draws(std::uint32_t i, const prepared_triangle& t) const {
    return i >= triangles.first && i < triangles.end && may_cover(t, area);
  }
};

class texture_streamer {
 public:
  // The drawn area's triangles (ps, their UV planes under `model`'s set-up and uv_convert), sampled with
  // `filter`; the window is
  // pages [first_page, end_page).
  texture_streamer(const prepared_scene& ps, const gs::model_options& model, gs::bilinear_mode filter, scissor area,
                   std::uint32_t first_page, std::uint32_t end_page);
  // The pieces of the next pass that draws texture t, the window's contents updated. Throws
  // texture_does_not_fit when a pixel alone fetches more cells than the window holds.
  std::vector<stream_piece> next_pass(const stream_texture& t);
  // Texel addresses for a piece's TEX0 (built once per TBW, gs_memory/fast_address.hpp).
  const gs::mem::texel_addresses& addresses(const stream_texture& t, const gs::mem::buffer& at);
  std::uint32_t window_pages() const noexcept { return end_ - first_; }

 private:
  struct leaf {
    scissor area;
    triangle_range triangles;
    std::vector<std::array<int, 2>> cells;  // (c, r), sorted
  };
  const std::vector<leaf>& leaves(const stream_texture& t);
  void split(const stream_texture& t, const scissor& a, triangle_range range, const std::vector<std::uint32_t>& tris,
             std::vector<leaf>& out);
  std::vector<std::array<int, 2>> cells_in(const stream_texture& t, const scissor& a,
                                           const std::vector<std::uint32_t>& tris) const;
  bool placeable(const stream_texture& t, const std::vector<std::array<int, 2>>& cells) const;
  stream_piece place(const stream_texture& t, const leaf& l);

  const prepared_scene& ps_;
  std::vector<gs::triangle_attributes> uv_;
  gs::bilinear_mode filter_;
  bool rows_only_;  // pieces are whole rows of the drawn area (PCSX2's row set-ups start a row at SCISSOR's left)
  scissor area_;
  std::uint32_t first_, end_;
  std::map<int, std::vector<leaf>> leaves_;  // per texture id
  std::map<int, int> passes_;                // passes drawn per texture id (the piece order alternates)
  struct resident {
    int id = -1, c = 0, r = 0;
  };
  std::array<resident, 512> window_{};                 // what each page of the memory holds (only the window is used)
  std::map<std::array<int, 3>, std::uint32_t> where_;  // (id, c, r) -> the page holding that cell
  std::map<std::array<std::uint32_t, 3>, std::unique_ptr<const gs::mem::texel_addresses>> tables_;
};

// A host -> local transfer of a w × h image into buffer b: BITBLTBUF (DBP, DBW, DPSM), TRXPOS = 0,
// TRXREG (RRW, RRH), TRXDIR = 0 as A+D writes, then the pixels as IMAGE data. `data` holds them as
// stream_texture does (one byte a PSMT4 or PSMT8 index, four a PSMCT32 texel); a PSMT4 image is
// sent two texels to a byte, the first in the low nibble (gs_memory/transfer.hpp; an even count).
void host_transfer(gs::packets::packet_builder& out, const gs::mem::buffer& b, int w, int h,
                   std::span<const std::uint8_t> data);
// Packets run into local memory through gs_packets' interpreter (std::logic_error on what it does not model).
void interpret(gs::mem::local_memory& m, const gs::packets::packet_builder& b);

// The page-sized host -> local transfers of a piece (BITBLTBUF DBP = the page, DBW = one page's width,
// DPSM; TRXPOS = 0; TRXREG = the cell's size; TRXDIR = 0; then the cell's texels as IMAGE data).
void add_piece_uploads(gs::packets::packet_builder& b, const stream_texture& t, const stream_piece& p);
// The same run into local memory through gs_packets' interpreter (the renderer's memory path).
void upload_piece(gs::mem::local_memory& m, const stream_texture& t, const stream_piece& p);

}  // namespace gsdot3::pipeline
