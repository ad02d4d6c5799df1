// gs_packets/draw.hpp — drawing one GS primitive into the modelled local memory: the vertices the
// interpreter queued, the registers of the context PRIM.CTXT selects, each pixel through
// gs::pixel_pipeline with the texel read from local memory.
//
// Units used (one implementation each, shared with the renderer): gs::setup_triangle /
// rasterise_triangle / rasterise_sprite (gs_arith/rasteriser.hpp), gs::setup_attributes (Gouraud and
// UV planes, gs_arith/attribute_setup.hpp), gs::sample (TEX1 filter), gs::mem::wrap (CLAMP),
// gs::mem::load_clut (TEX0.CLD), gs::depth_test (gs_arith/depth_test.hpp), gs::pixel_pipeline.
// Per pixel, in order: SCISSOR (the rasteriser's clip), SCANMSK, the destination-alpha test (TEST.DATE /
// DATM: the frame pixel's top bit, bit 31 or 15; PSMCT24 has none and passes), the depth test, then
// texture fetch and gs::pixel_pipeline, the frame write (FBMSK and the alpha test inside the pipeline)
// and the Z write.
// Texture coordinates: UV with PRIM.FST = 1; with FST = 0 (ST/Q, perspective texturing) a triangle's
// through gs::make_stq_sampler (gs_arith/perspective.hpp: S/Q and T/Q in float32 per pixel when Q
// differs between the vertices, per vertex and interpolated as UV with one Q; then the model options
// stq_range and stq_convert), a sprite's per vertex by gs::stq_vertex_texel.
// What the model lacks is not drawn: check_primitive names it (fog PRIM.FGE, AA1, POINT and LINE
// primitives, mip-mapping, a TEX1.LCM = 0 LOD that changes the filter within a primitive; with FST = 0
// a SPRITE whose vertices' Q differ, Q of both signs, S/Q or T/Q not finite; a CLUT load gs_memory
// refuses, a register value the decoders refuse), and draw_primitive draws nothing when the name is
// not empty.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "gs_arith/colour.hpp"
#include "gs_arith/options.hpp"
#include "gs_memory/clut_load.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/texture_buffer.hpp"

namespace gs::packets {

// PRIM.PRIM (bits 0-2) names, GS User's Manual.
inline constexpr const char* prim_names[8] = {"POINT",          "LINE",         "LINE_STRIP", "TRIANGLE",
                                              "TRIANGLE_STRIP", "TRIANGLE_FAN", "SPRITE",     "PRIM 7 (reserved)"};

// One vertex as the GS queues it on an XYZ write: the XYZ value and the current RGBAQ, ST, UV, FOG.
struct vertex {
  std::uint16_t X = 0, Y = 0;  // 12.4 primitive coordinates (XYZ2.X, XYZ2.Y)
  std::uint32_t Z = 0;
  rgba8 colour{};
  std::uint32_t Q = 0x3F800000u;  // RGBAQ.Q, IEEE single bits
  std::uint32_t S = 0, T = 0;     // ST, IEEE single bits
  std::uint16_t U = 0, V = 0;     // UV, 10.4 texels
  std::uint8_t F = 0;             // XYZF2.F / FOG.F
};

// The raw 64-bit register values one primitive draws with: PRIM holds the attribute bits in effect
// (PRIM's, or PRMODE's when PRMODECONT.AC = 0) with PRIM's type bits; the context registers are the
// ones PRIM.CTXT selects.
struct draw_registers {
  std::uint64_t PRIM = 0;
  std::uint64_t XYOFFSET = 0, TEX0 = 0, TEX1 = 0, CLAMP = 0, SCISSOR = 0, ALPHA = 0, TEST = 0, FBA = 0, FRAME = 0,
                ZBUF = 0;
  std::uint64_t TEXA = 0, DIMX = 0, DTHE = 0, COLCLAMP = 1, PABE = 0, SCANMSK = 0;
  unsigned context = 1;  // 1 or 2, for the messages
  friend bool operator==(const draw_registers&, const draw_registers&) = default;
};

// The CLUT buffer and, when the last TEX0 write's CLUT load could not be modelled, why.
struct clut_unit {
  mem::clut_state state{};
  std::string load_error;
};

// "" when the model can draw the primitive, else what it lacks, named (one line).
std::string check_primitive(const draw_registers& r, const clut_unit& clut, std::span<const vertex> v);

// Draws the primitive (2 vertices for SPRITE, 3 for the triangle types) when check_primitive accepts
// it; returns the pixels that went through gs::pixel_pipeline. Texels are read through `texture`, the
// texture page buffer (model option texture_buffer), made here when empty: the caller keeps it for a
// run of primitives with one drawing state and empties it at TEXFLUSH or a state change, as the
// renderer (one buffer per channel-fetch page), the probe's prediction and the section 3.4 proof do.
std::uint64_t draw_primitive(mem::local_memory& m, const draw_registers& r, const clut_unit& clut,
                             std::span<const vertex> v, const model_options& o,
                             std::optional<mem::texture_page_buffer>& texture);

}  // namespace gs::packets
