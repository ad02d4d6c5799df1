// pipeline/frame_packets.hpp — a method's whole frame as the GIF packet stream the GS receives
// (issue 15): the frame program (frame_program.hpp) encoded, the program render.cpp executes, with
// pass_table.hpp's register sets and vertex values, over the memory path's buffers. `gsdot3 dump`
// writes it as a PCSX2 GS dump; tests/pipeline replays it and compares with the renderer.
//
// The stream (context 1 throughout, PRMODECONT.AC = 1, XYOFFSET_1 = 2048.0 in both axes):
// 1. environment: PRMODECONT, XYOFFSET_1, SCISSOR_1 (the frame), DTHE = 0, PABE = 0, FBA_1 = 0;
// 2. uploads (gs_inputs.hpp: BITBLTBUF, TRXPOS, TRXREG, TRXDIR + IMAGE), then TEXFLUSH; a normal map
//    and diffuse texture that do not fit beside the frame buffers are streamed instead: each pass
//    drawing them is written per piece (texture_stream.hpp) as its page uploads, TEXFLUSH,
//    SCISSOR_1 = the piece's rectangle, TEX0_1 with the piece's TBP0 / TBW and the triangles that
//    reach the rectangle;
// 3. clears, as flat sprites over the frame: the DPB to 0x00808080, the LAB to 0, and the output
//    and the Z buffer to 0 by one sprite (ZTST = ALWAYS, ZMSK = 0);
// 4. step 1 (Z and ambient: TRIANGLE, ZTST = GEQUAL, Z written), per light steps 2.1-2.6, step 3
//    (the DPB cleared to 0 over the sprite area, the diffuse layer drawn into it), step 4, and step 5
//    when the scene has non-normal-mapped geometry (its triangles, Gouraud × the diffuse texture,
//    MODULATE, ZTST = GEQUAL, ZMSK = 0, SCISSOR_1 the frame). Each pass
//    writes FRAME_1, ALPHA_1, COLCLAMP, TEST_1, ZBUF_1 (gs_arith's encoders) and its texture's
//    TEX0_1, TEX1_1, CLAMP_1. Triangle passes: PACKED {RGBAQ, UV, XYZ2}
//    per vertex with PRE = 1 (PRIM.IIP = 1 for the Gouraud passes, FST = 1), ZTST = GEQUAL with
//    ZMSK = 1 after step 1. Sprite passes: the flat colour by A+D RGBAQ, PACKED {UV, XYZ2, UV, XYZ2}
//    per sprite, drawn 1:1 (UV = the texel at the top-left pixel, 12.4) with SCISSOR_1 = the
//    renderer's sprite area (the drawn triangles' bounding rectangle) and ZTST = ALWAYS, ZMSK = 1.
//    A texture read from a buffer drawn before is preceded by TEXFLUSH. The post filter, the ILP
//    read and step 4's channel move are gs_memory's channel-fetch sprites per page (TEX0_1 PSMT8 at
//    the page, TBW = 2·FBW, TW = 7, TH = 6; CLAMP_1 REGION_REPEAT); step 4's copy of the LAB into
//    the output is the renderer's local -> local transfer (gs_inputs.hpp's lab_to_output: BITBLTBUF,
//    TRXPOS, TRXREG, then TRXDIR = 2, as A+D writes).
// Memory: gs_inputs.hpp's buffer_layout, the renderer's memory path's: the DPB (and in step 3 the
// diffuse layer) at FBP 0, the LAB at P, the output at 2P, the Z buffer (PSMZ24) at ZBP = 3P, the
// textures after them. With draw_buffers::one the output is each light's DPB and then the LAB, and
// the free alphas are those of the buffer at FBP 0, of the Z buffer's words and of the output
// (frame_program.cpp; docs/dumps.md).
// The z-trick DPB clears (section 3.4, render_options::dpb_clear): FRAME_1.PSM = PSMZ32 for the buffer
// frame_program.hpp's in_z_layout names; the ILP sprites over whole pages with ZBUF_1 = the DPB
// (PSMZ24, ZMSK = 0), ZTST = ALWAYS and Z = 0x00808080; a Z-layout source's channel-fetch tiles drawn at
// gs::mem::zsigma of the pixel they fetch; two-pass's PSMT8H read of a Z-layout DPB per page, a sprite
// per 32x16 quarter (gif_stream.hpp's t8h_quarters); the LAB copy with SPSM = PSMZ32 (z-trick-psmz32).
// Not written (frame_limits.hpp says why, before anything is built): frames wider or taller than 1023
// pixels (a sprite's UV is 10.4: at most 1023.9375).
#pragma once

#include <cstdint>
#include <vector>

#include "gs_packets/dump.hpp"
#include "gs_packets/packetiser.hpp"
#include "gs_packets/video_mode.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct frame_packets {
  std::vector<std::uint8_t> gif;  // the stream (GIF PATH3), little-endian qwords
  buffer_layout buffers;
  // Privileged registers so the displayed frame is the output buffer: PMODE (circuit 1, ALP = 0xFF),
  // DISPFB1 (FBP, FBW, PSMCT32); DISPLAY1 (from the frame size) and the video mode: frame_dump.
  std::uint64_t PMODE = 0, DISPFB1 = 0;
  int width = 0, height = 0;
  std::size_t triangles = 0, sprites = 0;  // primitives written
};

// Throws std::invalid_argument for what is not written (above) or whose buffers do not fit in the
// 4 MiB, texture_does_not_fit when the textures cannot stream beside them.
frame_packets build_frame_packets(const scene& s, const prepared_scene& ps, method m, const render_options& o);

// The privileged-register block of a dump (8 KiB, the GS's 0x12000000..0x12001FFF) with PMODE at
// 0x0000, DISPFB1 at 0x0070, DISPLAY1 at 0x0080 (GS User's Manual register map; the same offsets in
// ps2sdk and Linux's arch/mips/include/asm/mach-ps2/gs-registers.h, read with the search tool).
inline constexpr std::uint32_t PMODE_offset = 0x0000, DISPFB1_offset = 0x0070, DISPLAY1_offset = 0x0080;

// How the dump packs the frame: the video mode its privileged registers set (gs_packets/video_mode.hpp;
// NTSC by default) and the largest GIF packet (gs_packets/packetiser.hpp; 1 MiB by default).
struct dump_layout {
  gs::packets::video_mode video = gs::packets::video_mode::ntsc;
  std::size_t max_packet_bytes = gs::packets::default_max_packet_bytes;
};

// The frame as a PCSX2 GS dump (new layout, state version 8: gs_packets/state.hpp): serial
// "gsdot3", no screenshot, a zeroed state blob (memory 0, PRMODECONT.AC = 1, Q = 1.0), the
// privileged registers above plus SMODE1, SMODE2, SYNCV and DISPLAY1 for the video mode; packets: the
// stream cut into GIF packets of at most max_packet_bytes (split_gif_packets: whole primitives, EOP on
// each packet's last tag), one PATH3 transfer (path index 2) each, then a registers packet and a vsync
// (field 0), as PCSX2's GSDumpBase::VSync writes them.
gs::dump::gs_dump frame_dump(const frame_packets& fp, const dump_layout& layout = {});

}  // namespace gsdot3::pipeline
