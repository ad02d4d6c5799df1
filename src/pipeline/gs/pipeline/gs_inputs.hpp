// pipeline/gs_inputs.hpp — a method's textures and palettes (built once per frame, the VU1 / tool
// side) and, for the memory path and the packet stream, where they live in GS local memory, the
// host -> local transfers that put them there, and the frame buffers' layout with step 4's copy. The renderer's memory
// path runs these transfers through the packet interpreter (gs_packets), the dump writer sends the same packets: one
// upload.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "gs_arith/clut.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/fast_address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/builder.hpp"
#include "pipeline/raster.hpp"
#include "pipeline/method.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"
#include "pipeline/texture_stream.hpp"

namespace gsdot3::pipeline {

// The memory path's buffers, one layout for the renderer's memory path (render.cpp) and the GIF
// packet stream of the same frame (frame_packets.cpp): PSMCT32, FBW = ceil(width / 64), P pages each;
// the DPB at FBP 0 (step 3 draws the diffuse layer into it, as the paper's step 3 says), the LAB at
// P, the output at 2P, the Z buffer (PSMZ24) at ZBP = 3P; the textures start at block 4·32·P.
struct buffer_layout {
  std::uint32_t fbw = 0, pages = 0;
  // FRAME.FBP of the DPB, the LAB and the output, ZBUF.ZBP of the Z buffer (8 KiB pages).
  std::uint32_t dpb() const noexcept { return 0; }
  std::uint32_t lab() const noexcept { return pages; }
  std::uint32_t output() const noexcept { return 2 * pages; }
  std::uint32_t z() const noexcept { return 3 * pages; }
  std::uint32_t first_texture_block() const noexcept { return 4 * 32 * pages; }
  // Whether the four buffers fit in the GS's 4 MiB (at 512×448: 4 × 112 of the 512 pages).
  bool fits() const noexcept { return 4 * pages * gs::mem::page_bytes <= gs::mem::memory_bytes; }
  // The PSMCT32 buffer at FBP `fbp` (one of the above) as a texture / transfer buffer.
  gs::mem::buffer colour(std::uint32_t fbp) const noexcept {
    return {fixed::uint<14>::from_wrapped(32 * fbp), fixed::uint<6>::from_wrapped(fbw), gs::mem::psm::PSMCT32};
  }
};
constexpr buffer_layout buffer_layout_for(int width, int height) noexcept {
  const auto fbw = static_cast<std::uint32_t>((width + 63) / 64);
  return {fbw, fbw * static_cast<std::uint32_t>((height + 31) / 32)};
}

// Area a out to whole 64x32 pages (the z-trick's ILP sprites: their Z writes clear whole pages).
constexpr scissor whole_pages(const scissor& a) noexcept {
  return {a.x0 & ~63, a.y0 & ~31, (a.x1 + 63) & ~63, (a.y1 + 31) & ~31};
}

// The copy of the LAB into the output over `area` before step 4, a local -> local transfer (the GS's
// own copy, no pixel arithmetic): BITBLTBUF SBP = the LAB, SPSM = PSMCT32 (PSMZ32 when the LAB was
// drawn in the Z layout, z-trick-psmz32: the transfer then reads it back into PSMCT32 order, the
// paper's "unswizzle"), DBP = the output (PSMCT32), both with FBW; TRXPOS = the area's corner on both
// sides, DIR = 0; TRXREG = the area's size; then TRXDIR = 2 starts it. The renderer runs it through
// gs_memory's local_to_local, the packet stream writes it as A+D: one copy. Empty area: no copy.
struct lab_copy {
  gs::mem::bitbltbuf_reg BITBLTBUF;
  gs::mem::trxpos_reg TRXPOS;
  gs::mem::trxreg_reg TRXREG;
  static constexpr gs::mem::trxdir_reg TRXDIR{gs::mem::xdir::local_to_local};
};
std::optional<lab_copy> lab_to_output(const buffer_layout& b, const scissor& area, bool lab_in_z_layout);

// One layer's palettes of its normal map (scene.hpp's layers), by clut_slot pos .. axis_z; axis_x is
// the three-pass terms palette (clut_slot::terms).
using layer_palettes = std::array<gs::clut_buffer, 5>;

struct gs_inputs {
  const normal_map* nm = nullptr;
  std::vector<layer_palettes> layers;  // per layer of *nm
  // alpha_index: the index in every channel (the memory path's step 4 moves a LAB byte into alpha).
  gs::clut_buffer ilp, grey, alpha_index;
  std::vector<std::uint32_t> sphere;  // 64×64, four-pass only
  std::vector<std::uint32_t> spot;    // encoders.hpp's spot_map, when a light is a spot light
  // A 24-bit map read by four-pass (section 3.6's "three 8 bit normal maps", encoders.hpp's
  // component_map): axis a's pass samples component_maps[a] (every layer's, one after another)
  // through the ramp palette of slot axis_x + a. Empty otherwise: every pass samples nm's index map
  // (normal_map_count, normal_map_of).
  std::array<std::vector<std::uint8_t>, 3> component_maps;
  const texture32* diffuse = nullptr;
  // Placed (place_inputs): the textures' TBP0 / TBW / PSM (nm_at: one per normal-map texture of
  // each layer, texture_index) and each layer's palettes' CBP (palettes() order; the last three, the
  // layers' shared palettes, are layer 0's in every layer).
  std::vector<gs::mem::buffer> nm_at;
  gs::mem::buffer sphere_at, spot_at, diffuse_at;
  std::vector<std::array<std::uint32_t, 8>> cbp;
  // Uploaded (upload_inputs): the memory the texels are read from; the CLUTs above are then the
  // ones TEX0.CLD = 1 loaded back from it.
  const gs::mem::local_memory* memory = nullptr;
  // and the byte address of every texel of the textures (gs_memory/fast_address.hpp).
  std::vector<std::shared_ptr<const gs::mem::texel_addresses>> nm_texels;  // as nm_at
  std::shared_ptr<const gs::mem::texel_addresses> sphere_texels, spot_texels, diffuse_texels;
  // Streamed (the normal map and the diffuse texture do not fit beside the frame buffers with the
  // rest, texture_stream.hpp): the window's first page (0: every texture placed above), the diffuse
  // texels as the transfers send them, and the streamer (start_stream) the passes take pieces from.
  std::uint32_t window_first = 0;
  std::vector<std::uint8_t> diffuse_bytes;
  std::shared_ptr<texture_streamer> stream;
};

// The eight palettes in upload order (clut_slot: the index into palettes() and gs_inputs::cbp).
// terms: the three-pass method's terms palette, in four-pass's X slot (gs_inputs::axis[0]); no method
// uses both, and the palette page holds eight.
enum class clut_slot : std::uint8_t { pos, neg, axis_x, axis_y, axis_z, ilp, grey, alpha_index, terms = axis_x };
// Slots pos .. axis_z are the normal map's palettes (the passes that sample it load them with its
// PSM); ilp, grey and alpha_index are read with the DPB / LAB as PSMT8 or PSMT8H.
inline constexpr std::size_t normal_map_palettes = 5;
// The normal map's texture format: PSMT4 for a 4-bit map, PSMT8 for an 8-bit one and for a 24-bit
// map's index map and component maps.
gs::mem::psm index_psm(const normal_map& nm);
// The normal-map textures of a layer (1, or 3 component maps), which of them a pass through palette
// slot c samples (component map a for slot axis_x + a), texture k of layer l's texels (one byte each)
// and its index in nm_at and nm_texels.
std::size_t normal_map_count(const gs_inputs& in);
std::size_t normal_map_of(const gs_inputs& in, clut_slot c);
std::span<const std::uint8_t> normal_map_texels(const gs_inputs& in, std::size_t layer, std::size_t k);
inline std::size_t texture_index(const gs_inputs& in, std::size_t layer, std::size_t k) {
  return layer * normal_map_count(in) + k;
}
// Layer l's eight palettes in clut_slot order.
std::array<gs::clut_buffer*, 8> palettes(gs_inputs& in, std::size_t layer);
std::array<const gs::clut_buffer*, 8> palettes(const gs_inputs& in, std::size_t layer);

// The renderer's and the packet stream's inputs, for a frame frame_limits.hpp's check accepts.
gs_inputs make_inputs(const scene& s, method m, const render_options& o);
// Places the textures from block `first` on: the normal map(s) of every layer (index_psm, an even
// TBW), the sphere map and the diffuse texture (PSMCT32), then per layer one PSMCT32 page holding its
// palettes as 16×16 CSM1 images of 4 blocks each (layer 0's page all eight, the others' their five).
// When that passes the end of the 4 MiB: the sphere map and the palettes only, and the normal map(s)
// and the diffuse texture streamed through the pages after them (the window, window_first);
// texture_does_not_fit when fewer than 4 pages are left for it (one bilinear pixel fetches up to 4).
gs_inputs place_inputs(const gs_inputs& direct, std::uint32_t first);
// The streamer of a streamed input set (nothing otherwise): the triangles of ps over the drawn
// `area`, sampled as o says; the normal map and the diffuse texture as streamed textures.
void start_stream(gs_inputs& in, const prepared_scene& ps, const render_options& o, const scissor& area);
// Step 5's geometry (prepared_scene::plain) samples the diffuse texture where it is placed; with the
// textures streamed the memory path and the packet stream refuse it (std::invalid_argument, this text).
inline constexpr const char* plain_needs_resident_texture =
    "step 5 (--floor): the textures stream through a window beside the frame buffers, and step 5's geometry needs "
    "the diffuse texture resident: use a smaller --size or normal map";
// Texture k of the normal map's layer `layer`, which triangles `tris` sample.
stream_texture normal_map_stream(const gs_inputs& in, std::size_t layer, std::size_t k, triangle_range tris);
stream_texture diffuse_stream(const gs_inputs& in);
// The transfers of a placed input set (host_transfer each, the streamed textures left to their
// passes); palette entry i at gs::csm1_position(i) of its image.
void add_uploads(gs::packets::packet_builder& b, const gs_inputs& placed);
// place_inputs, add_uploads interpreted into m (gs::packets::interpreter), then every palette loaded
// back from m by TEX0 (PSMT8, CBP, CLD = 1) through gs_memory's load_clut; the textures' texel
// address tables are built meanwhile on a second thread when `parallel` (they read no memory).
gs_inputs upload_inputs(gs::mem::local_memory& m, const gs_inputs& direct, std::uint32_t first, bool parallel = false);

}  // namespace gsdot3::pipeline
