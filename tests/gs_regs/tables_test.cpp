// The field tables of src/gs_regs against the GS User's Manual's layouts (../shared/spec/gs-alu-facts.md;
// PCSX2 `pcsx2/GS/GSRegs.h` GIFReg* / GSReg* unions agree). Each expected word below is written from the
// manual's bit positions by hand (hex literals), not from the table, then decoded field by field.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>

#include "gs_regs/drawing.hpp"
#include "gs_regs/privileged.hpp"

namespace {

using namespace gs::regs;

// Fields of one register are disjoint and inside 64 bits.
bool well_formed(std::span<const field> fields) {
  std::uint64_t seen = 0;
  for (const field& f : fields) {
    if (f.width < 1 || f.lo < 0 || f.lo + f.width > 64) return false;
    if ((seen & mask(f)) != 0) return false;
    seen |= mask(f);
  }
  return true;
}

TEST(RegisterTables, FieldsAreDisjointAndFitIn64Bits) {
  using table = std::span<const field>;
  for (const table r : std::initializer_list<table>{
           PRIM::fields,    RGBAQ::fields,    ST::fields,      UV::fields,         XYZ2::fields,   XYZF2::fields,
           TEX0::fields,    TEX1::fields,     TEXA::fields,    TEXCLUT::fields,    CLAMP::fields,  XYOFFSET::fields,
           SCISSOR::fields, ALPHA::fields,    TEST::fields,    FRAME::fields,      ZBUF::fields,   FBA::fields,
           PABE::fields,    COLCLAMP::fields, DTHE::fields,    PRMODECONT::fields, DIMX::fields,   BITBLTBUF::fields,
           TRXPOS::fields,  TRXREG::fields,   TRXDIR::fields,  PMODE::fields,      SMODE1::fields, SMODE2::fields,
           SYNCV::fields,   DISPFB::fields,   DISPLAY::fields, SCANMSK::fields})
    EXPECT_TRUE(well_formed(r));
}

// The used bits of each register, from the manual: every bit not listed is reserved.
TEST(RegisterTables, MasksMatchTheManual) {
  EXPECT_EQ(mask(PRIM::fields), 0x7FFu);
  EXPECT_EQ(mask(RGBAQ::fields), ~std::uint64_t{0});
  EXPECT_EQ(mask(UV::fields), 0x3FFF3FFFu);
  EXPECT_EQ(mask(XYZF2::fields), ~std::uint64_t{0});
  EXPECT_EQ(mask(TEX0::fields), 0xFFFFFFFFFFFFFFFFu);
  EXPECT_EQ(mask(TEX1::fields), 0x00000FFF001803FDu);
  EXPECT_EQ(mask(TEXA::fields), 0x000000FF000080FFu);
  EXPECT_EQ(mask(TEXCLUT::fields), 0x3FFFFFu);
  EXPECT_EQ(mask(CLAMP::fields), 0x00000FFFFFFFFFFFu);
  EXPECT_EQ(mask(XYOFFSET::fields), 0x0000FFFF0000FFFFu);
  EXPECT_EQ(mask(SCISSOR::fields), 0x07FF07FF07FF07FFu);
  EXPECT_EQ(mask(SCANMSK::fields), 0x3u);
  EXPECT_EQ(mask(ALPHA::fields), 0x000000FF000000FFu);
  EXPECT_EQ(mask(TEST::fields), 0x7FFFFu);
  EXPECT_EQ(mask(FRAME::fields), 0xFFFFFFFF3F3F01FFu);
  EXPECT_EQ(mask(ZBUF::fields), 0x000000010F0001FFu);
  EXPECT_EQ(mask(DIMX::fields), 0x7777777777777777u);
  EXPECT_EQ(mask(BITBLTBUF::fields), 0x3F3F3FFF3F3F3FFFu);
  EXPECT_EQ(mask(TRXPOS::fields), 0x1FFF07FF07FF07FFu);
  EXPECT_EQ(mask(TRXREG::fields), 0x00000FFF00000FFFu);
  EXPECT_EQ(mask(PMODE::fields), 0xFFFFu);
  EXPECT_EQ(mask(SMODE1::fields), 0x1FFFFFFFFFu);
  EXPECT_EQ(mask(SMODE2::fields), 0xFu);
  EXPECT_EQ(mask(SYNCV::fields), ~std::uint64_t{0});
  EXPECT_EQ(mask(DISPFB::fields), 0x003FFFFF000FFFFFu);
  EXPECT_EQ(mask(DISPLAY::fields), 0x007FFFFF1FFFFFFFu);
}

// FRAME: FBP 0:9, FBW 16:6, PSM 24:6, FBMSK 32:32 (FBP 0x1AB, FBW 10, PSMCT16S 0x0A, FBMSK 0x80000001).
TEST(RegisterTables, FrameDecodesAHandWrittenWord) {
  constexpr std::uint64_t w = 0x80000001'0A0A01ABu;
  static_assert(decode(FRAME::FBP, w) == 0x1AB && decode(FRAME::FBW, w) == 10 && decode(FRAME::PSM, w) == 0x0A &&
                decode(FRAME::FBMSK, w) == 0x80000001u);
  static_assert((encode(FRAME::FBP, 0x1AB) | encode(FRAME::FBW, 10) | encode(FRAME::PSM, 0x0A) |
                 encode(FRAME::FBMSK, 0x80000001u)) == w);
}

// TEX0: TBP0 0:14, TBW 14:6, PSM 20:6, TW 26:4, TH 30:4, TCC 34, TFX 35:2, CBP 37:14, CPSM 51:4,
// CSM 55, CSA 56:5, CLD 61:3. TH straddles bit 32; the word is PSMT8 (0x13) 256x256 (TW = TH = 8).
TEST(RegisterTables, Tex0DecodesAHandWrittenWord) {
  // TBP0 0x100, TBW 4, PSM 0x13, TW 8, TH 8, TCC 1, TFX 1, CBP 0x3000, CPSM 0, CSM 0, CSA 0, CLD 1.
  constexpr std::uint64_t w = 0x2006000E'21310100u;
  EXPECT_EQ(decode(TEX0::TBP0, w), 0x100u);
  EXPECT_EQ(decode(TEX0::TBW, w), 4u);
  EXPECT_EQ(decode(TEX0::PSM, w), 0x13u);
  EXPECT_EQ(decode(TEX0::TW, w), 8u);
  EXPECT_EQ(decode(TEX0::TH, w), 8u);
  EXPECT_EQ(decode(TEX0::TCC, w), 1u);
  EXPECT_EQ(decode(TEX0::TFX, w), 1u);
  EXPECT_EQ(decode(TEX0::CBP, w), 0x3000u);
  EXPECT_EQ(decode(TEX0::CPSM, w), 0u);
  EXPECT_EQ(decode(TEX0::CSA, w), 0u);
  EXPECT_EQ(decode(TEX0::CLD, w), 1u);
}

// Transfer and display registers, one hand-written word each.
TEST(RegisterTables, TransferAndDisplayDecodeHandWrittenWords) {
  // TRXPOS: SSAX 0:11, SSAY 16:11, DSAX 32:11, DSAY 48:11, DIR 59:2 (DSAX 2, DSAY 1, DIR 3).
  constexpr std::uint64_t trxpos = 0x1801000200000000u;
  EXPECT_EQ(decode(TRXPOS::DSAX, trxpos), 2u);
  EXPECT_EQ(decode(TRXPOS::DSAY, trxpos), 1u);
  EXPECT_EQ(decode(TRXPOS::DIR, trxpos), 3u);
  // DISPFB: FBP 0:9, FBW 9:6, PSM 15:5, DBX 32:11, DBY 43:11 (FBP 5, FBW 10, PSMCT16S, DBX 3, DBY 2).
  constexpr std::uint64_t dispfb = 0x0000100300051405u;
  EXPECT_EQ(decode(DISPFB::FBP, dispfb), 5u);
  EXPECT_EQ(decode(DISPFB::FBW, dispfb), 10u);
  EXPECT_EQ(decode(DISPFB::PSM, dispfb), 0xAu);
  EXPECT_EQ(decode(DISPFB::DBX, dispfb), 3u);
  EXPECT_EQ(decode(DISPFB::DBY, dispfb), 2u);
  // DISPLAY: DX 0:12, DY 12:11, MAGH 23:4, MAGV 27:2, DW 32:12, DH 44:11 (DW 2559, DH 447, MAGH 4).
  constexpr std::uint64_t display = 0x001BF9FF02000000u;
  EXPECT_EQ(decode(DISPLAY::DW, display), 2559u);
  EXPECT_EQ(decode(DISPLAY::DH, display), 447u);
  EXPECT_EQ(decode(DISPLAY::MAGH, display), 4u);
  EXPECT_EQ(decode(DISPLAY::MAGV, display), 0u);
}

TEST(RegisterTables, EncodeRejectsAValueWiderThanTheField) {
  EXPECT_THROW((void)encode(FRAME::FBP, 0x200), std::out_of_range);
  EXPECT_EQ(encode(FRAME::FBP, 0x1FF), 0x1FFu);
  EXPECT_TRUE(is_one_of(0x13, texture_psms));
  EXPECT_FALSE(is_one_of(0x13, FRAME::PSM_valid));
}

}  // namespace
