// probe/packets.hpp — probe_design() as GIF packets and as one PCSX2 GS dump (gs_packets' writer).
//
// The stream: XYOFFSET_1 = 0, PRMODECONT = 1, ZBUF_1 (ZMSK = 1: no Z writes); the texture as an
// IMAGE transfer (BITBLTBUF, TRXPOS, TRXREG, TRXDIR = host -> local); then per draw the A+D writes of
// the registers that differ from the previous draw (all of them for the first), a TEXFLUSH when the
// draw asks for one, and its vertices as PACKED RGBAQ, UV, XYZ2. Draws that share a state are sent
// as vertices only, so nothing reaches the GS between the section 3.4 copies but their vertices.
//
// The dump: state version 8 with zeroed memory, the privileged registers that display the frame
// (PMODE, SMODE2, DISPFB1, DISPLAY1), the stream as one PATH3 transfer, then a vsync.
#pragma once

#include <cstdint>
#include <vector>

#include "gs_packets/dump.hpp"
#include "gs_packets/builder.hpp"

namespace gsdot3::probe {

// The privileged registers, at their offsets in the dump's 8 KiB block (the GS's 0x12000000 space;
// bit fields as DobieStation `gsregisters.cpp` GS_REGISTERS::write64_privileged decodes them):
//   PMODE    0x0000  EN1 0, EN2 1, CRTMD 2-4, MMOD 5, AMOD 6, SLBG 7, ALP 8-15
//   SMODE2   0x0020  INT 0, FFMD 1, DPMS 2-3
//   DISPFB1  0x0070  FBP 0-8 (2048 words), FBW 9-14, PSM 15-19, DBX 32-42, DBY 43-53
//   DISPLAY1 0x0080  DX 0-11, DY 12-22, MAGH 23-26, MAGV 27-28, DW 32-43, DH 44-54 (width, height − 1)
// Read circuit 1 only (EN1, CRTMD = 1 as the manual asks, MMOD = 1: ALP = 0xFF, no merge with
// circuit 2), 640×448 PSMCT32 at FBP 0; NTSC interlaced (SMODE2 INT = 1, FFMD = 0: each field reads every
// other line); DISPLAY1 MAGH = 3 (4 VCK per pixel), DW = 2559, DH = 447, DX = 636, DY = 50 (the NTSC
// picture origin homebrew commonly uses; a runner that shows another origin still reads the same
// frame buffer).
struct display_registers {
  std::uint64_t PMODE, SMODE2, DISPFB1, DISPLAY1;
};
display_registers probe_display();

gs::packets::packet_builder probe_packets();
gs::dump::gs_dump probe_dump();

}  // namespace gsdot3::probe
