// gs_regs/drawing.hpp — the field tables of the GS general-purpose (drawing and transfer) registers,
// written once here: every decoder and encoder of gs_arith, gs_memory, gs_packets, gs_cost and the
// pipeline takes its bit positions from these (gs_regs/field.hpp's decode / encode / mask).
//
// Evidence: the GS User's Manual's register descriptions as digested in ../shared/spec/gs-alu-facts.md,
// checked against an independent implementation read with the search tool: PCSX2 `pcsx2/GS/GSRegs.h`,
// its `REG64_(GIFReg, NAME)` unions (GIFRegPRIM, GIFRegRGBAQ, GIFRegST, GIFRegUV, GIFRegXYZ, GIFRegXYZF,
// GIFRegTEX0, GIFRegTEX1, GIFRegTEXA, GIFRegTEXCLUT, GIFRegCLAMP, GIFRegXYOFFSET, GIFRegSCISSOR,
// GIFRegALPHA, GIFRegTEST, GIFRegFRAME, GIFRegZBUF, GIFRegFBA, GIFRegPABE, GIFRegCOLCLAMP, GIFRegDTHE,
// GIFRegDIMX, GIFRegPRMODECONT, GIFRegBITBLTBUF, GIFRegTRXPOS, GIFRegTRXREG, GIFRegTRXDIR), whose
// padding members give the same gaps. Confidence: high (two sources agree field by field).
// Each register's `fields` lists all its fields; bits outside them are reserved (0).
#pragma once

#include <cstdint>

#include "gs_regs/field.hpp"

namespace gs::regs {

namespace PRIM {
inline constexpr field PRIM{"PRIM", 0, 3}, IIP{"IIP", 3, 1}, TME{"TME", 4, 1}, FGE{"FGE", 5, 1}, ABE{"ABE", 6, 1},
    AA1{"AA1", 7, 1}, FST{"FST", 8, 1}, CTXT{"CTXT", 9, 1}, FIX{"FIX", 10, 1};
inline constexpr field fields[] = {PRIM, IIP, TME, FGE, ABE, AA1, FST, CTXT, FIX};
inline constexpr std::uint64_t PRIM_reserved = 7;  // primitive type 7 is reserved
}  // namespace PRIM

namespace RGBAQ {
inline constexpr field R{"R", 0, 8}, G{"G", 8, 8}, B{"B", 16, 8}, A{"A", 24, 8}, Q{"Q", 32, 32};
inline constexpr field fields[] = {R, G, B, A, Q};
}  // namespace RGBAQ

namespace ST {
inline constexpr field S{"S", 0, 32}, T{"T", 32, 32};
inline constexpr field fields[] = {S, T};
}  // namespace ST

namespace UV {
inline constexpr field U{"U", 0, 14}, V{"V", 16, 14};
inline constexpr field fields[] = {U, V};
}  // namespace UV

namespace XYZ2 {
inline constexpr field X{"X", 0, 16}, Y{"Y", 16, 16}, Z{"Z", 32, 32};
inline constexpr field fields[] = {X, Y, Z};
}  // namespace XYZ2

// PRMODE: PRIM's attribute bits (IIP to FIX) without the primitive type, used while PRMODECONT.AC = 0.
namespace PRMODE {
inline constexpr field fields[] = {PRIM::IIP, PRIM::TME, PRIM::FGE,  PRIM::ABE,
                                   PRIM::AA1, PRIM::FST, PRIM::CTXT, PRIM::FIX};
}  // namespace PRMODE

namespace FOG {
inline constexpr field F{"F", 56, 8};
inline constexpr field fields[] = {F};
}  // namespace FOG

namespace XYZF2 {
inline constexpr field X{"X", 0, 16}, Y{"Y", 16, 16}, Z{"Z", 32, 24}, F{"F", 56, 8};
inline constexpr field fields[] = {X, Y, Z, F};
}  // namespace XYZF2

// The pixel storage formats a texture may have (TEX0.PSM): PSMCT32/24/16/16S, PSMT8/8H/4/4HL/4HH,
// PSMZ32/24/16/16S.
inline constexpr std::uint64_t texture_psms[] = {0x00, 0x01, 0x02, 0x0A, 0x13, 0x14, 0x1B,
                                                 0x24, 0x2C, 0x30, 0x31, 0x32, 0x3A};

namespace TEX0 {
inline constexpr field TBP0{"TBP0", 0, 14}, TBW{"TBW", 14, 6}, PSM{"PSM", 20, 6}, TW{"TW", 26, 4}, TH{"TH", 30, 4},
    TCC{"TCC", 34, 1}, TFX{"TFX", 35, 2}, CBP{"CBP", 37, 14}, CPSM{"CPSM", 51, 4}, CSM{"CSM", 55, 1}, CSA{"CSA", 56, 5},
    CLD{"CLD", 61, 3};
inline constexpr field fields[] = {TBP0, TBW, PSM, TW, TH, TCC, TFX, CBP, CPSM, CSM, CSA, CLD};
inline constexpr int TW_max = 10, TH_max = 10;                  // texture sides are at most 2^10
inline constexpr std::uint64_t CPSM_valid[] = {0x0, 0x2, 0xA};  // PSMCT32, PSMCT16, PSMCT16S
}  // namespace TEX0

// TEX2: TEX0's PSM and CLUT fields at TEX0's positions (writing it changes only those of TEX0).
namespace TEX2 {
inline constexpr field fields[] = {TEX0::PSM, TEX0::CBP, TEX0::CPSM, TEX0::CSM, TEX0::CSA, TEX0::CLD};
}  // namespace TEX2

namespace TEX1 {
inline constexpr field LCM{"LCM", 0, 1}, MXL{"MXL", 2, 3}, MMAG{"MMAG", 5, 1}, MMIN{"MMIN", 6, 3}, MTBA{"MTBA", 9, 1},
    L{"L", 19, 2}, K{"K", 32, 12};
inline constexpr field fields[] = {LCM, MXL, MMAG, MMIN, MTBA, L, K};
}  // namespace TEX1

namespace TEXA {
inline constexpr field TA0{"TA0", 0, 8}, AEM{"AEM", 15, 1}, TA1{"TA1", 32, 8};
inline constexpr field fields[] = {TA0, AEM, TA1};
}  // namespace TEXA

namespace TEXCLUT {
inline constexpr field CBW{"CBW", 0, 6}, COU{"COU", 6, 6}, COV{"COV", 12, 10};
inline constexpr field fields[] = {CBW, COU, COV};
}  // namespace TEXCLUT

namespace CLAMP {
inline constexpr field WMS{"WMS", 0, 2}, WMT{"WMT", 2, 2}, MINU{"MINU", 4, 10}, MAXU{"MAXU", 14, 10},
    MINV{"MINV", 24, 10}, MAXV{"MAXV", 34, 10};
inline constexpr field fields[] = {WMS, WMT, MINU, MAXU, MINV, MAXV};
}  // namespace CLAMP

namespace XYOFFSET {
inline constexpr field OFX{"OFX", 0, 16}, OFY{"OFY", 32, 16};
inline constexpr field fields[] = {OFX, OFY};
}  // namespace XYOFFSET

namespace SCISSOR {
inline constexpr field SCAX0{"SCAX0", 0, 11}, SCAX1{"SCAX1", 16, 11}, SCAY0{"SCAY0", 32, 11}, SCAY1{"SCAY1", 48, 11};
inline constexpr field fields[] = {SCAX0, SCAX1, SCAY0, SCAY1};
}  // namespace SCISSOR

namespace SCANMSK {
inline constexpr field MSK{"MSK", 0, 2};
inline constexpr field fields[] = {MSK};
inline constexpr std::uint64_t MSK_reserved = 1;  // 0 normal, 2 odd rows off, 3 even rows off
}  // namespace SCANMSK

namespace ALPHA {
inline constexpr field A{"A", 0, 2}, B{"B", 2, 2}, C{"C", 4, 2}, D{"D", 6, 2}, FIX{"FIX", 32, 8};
inline constexpr field fields[] = {A, B, C, D, FIX};
inline constexpr std::uint64_t selector_reserved = 3;  // A, B, C, D = 3 is reserved
}  // namespace ALPHA

namespace TEST {
inline constexpr field ATE{"ATE", 0, 1}, ATST{"ATST", 1, 3}, AREF{"AREF", 4, 8}, AFAIL{"AFAIL", 12, 2},
    DATE{"DATE", 14, 1}, DATM{"DATM", 15, 1}, ZTE{"ZTE", 16, 1}, ZTST{"ZTST", 17, 2};
inline constexpr field fields[] = {ATE, ATST, AREF, AFAIL, DATE, DATM, ZTE, ZTST};
}  // namespace TEST

namespace FRAME {
inline constexpr field FBP{"FBP", 0, 9}, FBW{"FBW", 16, 6}, PSM{"PSM", 24, 6}, FBMSK{"FBMSK", 32, 32};
inline constexpr field fields[] = {FBP, FBW, PSM, FBMSK};
// PSMCT32/24/16/16S and PSMZ32/24/16/16S: the formats a frame buffer may have.
inline constexpr std::uint64_t PSM_valid[] = {0x00, 0x01, 0x02, 0x0A, 0x30, 0x31, 0x32, 0x3A};
}  // namespace FRAME

namespace ZBUF {
inline constexpr field ZBP{"ZBP", 0, 9}, PSM{"PSM", 24, 4}, ZMSK{"ZMSK", 32, 1};
inline constexpr field fields[] = {ZBP, PSM, ZMSK};
// PSMZ32/24/16/16S as the 4-bit field holds them (the format's low nibble).
inline constexpr std::uint64_t PSM_valid[] = {0x0, 0x1, 0x2, 0xA};
}  // namespace ZBUF

// The one-bit registers: the bit is bit 0, the rest reserved.
namespace FBA {
inline constexpr field FBA{"FBA", 0, 1};
inline constexpr field fields[] = {FBA};
}  // namespace FBA
namespace PABE {
inline constexpr field PABE{"PABE", 0, 1};
inline constexpr field fields[] = {PABE};
}  // namespace PABE
namespace COLCLAMP {
inline constexpr field CLAMP{"CLAMP", 0, 1};
inline constexpr field fields[] = {CLAMP};
}  // namespace COLCLAMP
namespace DTHE {
inline constexpr field DTHE{"DTHE", 0, 1};
inline constexpr field fields[] = {DTHE};
}  // namespace DTHE
namespace PRMODECONT {
inline constexpr field AC{"AC", 0, 1};
inline constexpr field fields[] = {AC};
}  // namespace PRMODECONT

// DIMX: the 4x4 dither matrix, DMij (row i, column j) 3 bits at 16i + 4j.
namespace DIMX {
constexpr field DM(int i, int j) { return {"DM", 16 * i + 4 * j, 3}; }
inline constexpr field fields[] = {DM(0, 0), DM(0, 1), DM(0, 2), DM(0, 3), DM(1, 0), DM(1, 1), DM(1, 2), DM(1, 3),
                                   DM(2, 0), DM(2, 1), DM(2, 2), DM(2, 3), DM(3, 0), DM(3, 1), DM(3, 2), DM(3, 3)};
}  // namespace DIMX

namespace BITBLTBUF {
inline constexpr field SBP{"SBP", 0, 14}, SBW{"SBW", 16, 6}, SPSM{"SPSM", 24, 6}, DBP{"DBP", 32, 14}, DBW{"DBW", 48, 6},
    DPSM{"DPSM", 56, 6};
inline constexpr field fields[] = {SBP, SBW, SPSM, DBP, DBW, DPSM};
}  // namespace BITBLTBUF

namespace TRXPOS {
inline constexpr field SSAX{"SSAX", 0, 11}, SSAY{"SSAY", 16, 11}, DSAX{"DSAX", 32, 11}, DSAY{"DSAY", 48, 11},
    DIR{"DIR", 59, 2};
inline constexpr field fields[] = {SSAX, SSAY, DSAX, DSAY, DIR};
}  // namespace TRXPOS

namespace TRXREG {
inline constexpr field RRW{"RRW", 0, 12}, RRH{"RRH", 32, 12};
inline constexpr field fields[] = {RRW, RRH};
}  // namespace TRXREG

namespace TRXDIR {
inline constexpr field XDIR{"XDIR", 0, 2};
inline constexpr field fields[] = {XDIR};
}  // namespace TRXDIR

}  // namespace gs::regs
