// pipeline/memory_steps.hpp — how each step of the paper's section 3.1 is modelled on the two storage
// paths (render.cpp), for the report's memory section. "register level": every value the step
// writes comes out of the gs_arith / gs_memory units fed with the step's register values (pixel
// pipeline, depth test, address functions, transfers, CLUT loads); "value level": the step's
// result is computed directly from the values (the same numbers, no GS unit in between).
#pragma once

#include <array>
#include <string_view>

namespace gsdot3::pipeline {

struct memory_step {
  std::string_view step, does, memory_path, value_path;
};

inline constexpr std::array<memory_step, 10> memory_steps{{
    {"1",
     "Z buffer and the ambient colour into the LAB: the LAB cleared, Z cleared (Z = 0, ZTST = ALWAYS), every "
     "triangle with TEST_1 ZTE = 1, ZTST = GEQUAL, ZBUF_1 PSMZ24, ZMSK = 0",
     "register level: Z at ZBP = 3P in local memory (PSMZ24 layout), gs::depth_test; the clears before it (the "
     "frame program's sprites over the frame) are the memory's state, stored directly",
     "register level for the depth test (gs::depth_test on a row-major Z array); the clears are fills"},
    {"2.1", "clear the DPB to 0x00808080 (explicit, or section 3.4's Z-buffer clear during 2.6)",
     "register level: a flat sprite, or the ILP sprites' Z writes (ZBUF = the DPB in PSMZ24, ZTST = ALWAYS)",
     "value level: a fill"},
    {"2.2", "COLCLAMP = 0 for 2.3 and 2.4", "register level", "register level"},
    {"2.3", "the signed multiplications into R, G, B of the DPB (two-pass: also n'_a via PSMT8H)",
     "register level: the normal map, palettes and sphere map uploaded by transfers / CLUT loads, texels read "
     "through the address functions, ZTST = GEQUAL against the Z buffer in memory",
     "register level for the pixel pipeline; textures and palettes read from host arrays"},
    {"2.4", "the post filter R += G, R += B",
     "register level: channel-fetch sprites reading the DPB as PSMT8 (TBW = 2·FBW, CLAMP_1 REGION_REPEAT)",
     "value level: the byte taken from the pixel's own word"},
    {"2.5", "COLCLAMP = 1", "register level", "register level"},
    {"2.6", "ILP[sum] × light colour added into the LAB",
     "register level: the DPB read as PSMT8 through the ILP loaded from memory by TEX0.CLD",
     "value level for the texel read (the pixel's own byte), register level for the blend"},
    {"3", "the DPB cleared to zero and the diffuse layer drawn into it",
     "register level: a flat sprite, the diffuse texture uploaded by a transfer, ZTST = GEQUAL in memory",
     "register level for the pixel pipeline (into a separate array); the clear is a fill"},
    {"4",
     "diffuse × LAB per channel: the LAB copied into the output, each LAB channel moved into the output's alpha, "
     "Cs·Ad writing that channel",
     "register level: the copy is a local -> local transfer (TRXDIR = 2), the channel move a channel-fetch sprite",
     "value level for the copy and the channel move, register level for the multiply"},
    {"5",
     "non-normal-mapped geometry (--floor) into the output: Gouraud × the diffuse texture (MODULATE), ZTST = "
     "GEQUAL, ZMSK = 0",
     "register level: the diffuse texture read from memory, Z tested and written at ZBP in memory",
     "register level for the pixel pipeline and the depth test; the texture read from a host array"},
}};

}  // namespace gsdot3::pipeline
