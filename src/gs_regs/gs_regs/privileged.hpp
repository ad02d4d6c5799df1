// gs_regs/privileged.hpp — the field tables of the GS privileged registers the dumps write and the
// display decoder reads: PMODE, SMODE1, SMODE2, SYNCV, DISPFB1/2 (DISPFB), DISPLAY1/2 (DISPLAY).
//
// Evidence: the GS User's Manual (privileged registers), ../shared/spec/gs-alu-facts.md, and PCSX2
// `pcsx2/GS/GSRegs.h` read with the search tool: `REG64_(GSReg, NAME)` (GSRegPMODE, GSRegSMODE1,
// GSRegSMODE2, GSRegSYNCV, GSRegDISPFB, GSRegDISPLAY) with the same widths and padding. Confidence:
// high for the positions; the values written (gs_packets/video_mode.hpp) carry their own evidence.
#pragma once

#include <cstdint>

#include "gs_regs/field.hpp"

namespace gs::regs {

namespace PMODE {
inline constexpr field EN1{"EN1", 0, 1}, EN2{"EN2", 1, 1}, CRTMD{"CRTMD", 2, 3}, MMOD{"MMOD", 5, 1}, AMOD{"AMOD", 6, 1},
    SLBG{"SLBG", 7, 1}, ALP{"ALP", 8, 8};
inline constexpr field fields[] = {EN1, EN2, CRTMD, MMOD, AMOD, SLBG, ALP};
}  // namespace PMODE

namespace SMODE1 {
inline constexpr field RC{"RC", 0, 3}, LC{"LC", 3, 7}, T1248{"T1248", 10, 2}, SLCK{"SLCK", 12, 1}, CMOD{"CMOD", 13, 2},
    EX{"EX", 15, 1}, PRST{"PRST", 16, 1}, SINT{"SINT", 17, 1}, XPCK{"XPCK", 18, 1}, PCK2{"PCK2", 19, 2},
    SPML{"SPML", 21, 4}, GCONT{"GCONT", 25, 1}, PHS{"PHS", 26, 1}, PVS{"PVS", 27, 1}, PEHS{"PEHS", 28, 1},
    PEVS{"PEVS", 29, 1}, CLKSEL{"CLKSEL", 30, 2}, NVCK{"NVCK", 32, 1}, SLCK2{"SLCK2", 33, 1}, VCKSEL{"VCKSEL", 34, 2},
    VHP{"VHP", 36, 1};
inline constexpr field fields[] = {RC,    LC,  T1248, SLCK, CMOD, EX,     PRST, SINT,  XPCK,   PCK2, SPML,
                                   GCONT, PHS, PVS,   PEHS, PEVS, CLKSEL, NVCK, SLCK2, VCKSEL, VHP};
}  // namespace SMODE1

namespace SMODE2 {
inline constexpr field INT{"INT", 0, 1}, FFMD{"FFMD", 1, 1}, DPMS{"DPMS", 2, 2};
inline constexpr field fields[] = {INT, FFMD, DPMS};
}  // namespace SMODE2

namespace SYNCV {
inline constexpr field VFP{"VFP", 0, 10}, VFPE{"VFPE", 10, 10}, VBP{"VBP", 20, 12}, VBPE{"VBPE", 32, 10},
    VDP{"VDP", 42, 11}, VS{"VS", 53, 11};
inline constexpr field fields[] = {VFP, VFPE, VBP, VBPE, VDP, VS};
}  // namespace SYNCV

namespace DISPFB {
inline constexpr field FBP{"FBP", 0, 9}, FBW{"FBW", 9, 6}, PSM{"PSM", 15, 5}, DBX{"DBX", 32, 11}, DBY{"DBY", 43, 11};
inline constexpr field fields[] = {FBP, FBW, PSM, DBX, DBY};
// The formats the read circuits display: PSMCT32, PSMCT24, PSMCT16, PSMCT16S.
inline constexpr std::uint64_t PSM_valid[] = {0x0, 0x1, 0x2, 0xA};
}  // namespace DISPFB

namespace DISPLAY {
inline constexpr field DX{"DX", 0, 12}, DY{"DY", 12, 11}, MAGH{"MAGH", 23, 4}, MAGV{"MAGV", 27, 2}, DW{"DW", 32, 12},
    DH{"DH", 44, 11};
inline constexpr field fields[] = {DX, DY, MAGH, MAGV, DW, DH};
}  // namespace DISPLAY

}  // namespace gs::regs
