// gs_arith/registers.hpp — the GS registers the pixel pipeline reads, decoded from their 64-bit values.
//
// Bit layouts from the GS User's Manual (as transcribed in PCSX2 `GSRegs.h`):
//   PRIM     PRIM:3 IIP:1 TME:1 FGE:1 ABE:1 AA1:1 FST:1 CTXT:1 FIX:1
//   RGBAQ    R:8 G:8 B:8 A:8 Q:32 (IEEE single)
//   TEX0_1   TBP0:14 TBW:6 PSM:6 TW:4 TH:4 TCC:1 TFX:2 CBP:14 CPSM:4 CSM:1 CSA:5 CLD:3
//   ALPHA_1  A:2 B:2 C:2 D:2 _:24 FIX:8 _:24
//   TEST_1   ATE:1 ATST:3 AREF:8 AFAIL:2 DATE:1 DATM:1 ZTE:1 ZTST:2
//   FRAME_1  FBP:9 _:7 FBW:6 _:2 PSM:6 _:2 FBMSK:32
//   COLCLAMP CLAMP:1   PABE PABE:1   FBA_1 FBA:1   DTHE DTHE:1
//   DIMX     DM00:3 _:1 DM01:3 _:1 ... DM33:3 _:1 (row i = y & 3 in bits 16·i .. 16·i + 15)
//   ZBUF_1   ZBP:9 _:15 PSM:4 _:4 ZMSK:1 _:31 (PSM 0 PSMZ32, 1 PSMZ24, 2 PSMZ16, 0xA PSMZ16S; struct in
//            depth_test.hpp). PCSX2 `pcsx2/GS/GSRegs.h` `REG64_(GIFReg, ZBUF)` (GIFRegZBUF) has ZBP:9,
//            _PAD1:15, then PSM:6 _PAD2:2 with the manual's "PSM:4, _PAD2:4" kept as a comment (its
//            GIFRegHandlerZBUF ORs 0x30 into PSM, so 6 bits hold the Z format's full code); its
//            `GSState.h` ZBUF_REG_MASK 0x10F0001FF keeps bits 0-8, 24-27 and 32: the 4-bit field.
// Decoding is strict: a set padding bit, a reserved selector (ALPHA A/B/C/D = 3, PRIM = 7), an
// unknown PSM/CPSM, or TW/TH > 10 throws gs::register_error naming the register and the field.
// encode() is the exact inverse on every value decode() accepts.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fixed/integer.hpp"
#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/alpha_test.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/depth_test.hpp"
#include "gs_arith/dither.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/texture_function.hpp"

namespace gs {

struct register_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

enum class prim_type : std::uint8_t {
  POINT = 0,
  LINE = 1,
  LINE_STRIP = 2,
  TRIANGLE = 3,
  TRIANGLE_STRIP = 4,
  TRIANGLE_FAN = 5,
  SPRITE = 6,
};

struct prim_reg {
  prim_type PRIM = prim_type::POINT;
  bool IIP = false, TME = false, FGE = false, ABE = false, AA1 = false, FST = false, CTXT = false, FIX = false;
  friend constexpr bool operator==(const prim_reg&, const prim_reg&) = default;
};

struct rgbaq_reg {
  rgba8 colour{};
  std::uint32_t Q = 0;  // IEEE single-precision bits
  friend constexpr bool operator==(const rgbaq_reg&, const rgbaq_reg&) = default;
};

// TEX0.PSM: every texture storage format of the GS manual.
enum class tex_psm : std::uint8_t {
  PSMCT32 = 0x00,
  PSMCT24 = 0x01,
  PSMCT16 = 0x02,
  PSMCT16S = 0x0A,
  PSMT8 = 0x13,
  PSMT4 = 0x14,
  PSMT8H = 0x1B,
  PSMT4HL = 0x24,
  PSMT4HH = 0x2C,
  PSMZ32 = 0x30,
  PSMZ24 = 0x31,
  PSMZ16 = 0x32,
  PSMZ16S = 0x3A,
};
// TEX0.CPSM: the CLUT entry formats.
enum class clut_psm : std::uint8_t { PSMCT32 = 0x0, PSMCT16 = 0x2, PSMCT16S = 0xA };

struct tex0_reg {
  fixed::uint<14> TBP0{};
  fixed::uint<6> TBW{};
  tex_psm PSM = tex_psm::PSMCT32;
  fixed::u4 TW{}, TH{};
  tcc TCC = tcc::RGB;
  tfx TFX = tfx::MODULATE;
  fixed::uint<14> CBP{};
  clut_psm CPSM = clut_psm::PSMCT32;
  bool CSM = false;  // 0 = CSM1, 1 = CSM2
  fixed::u5 CSA{};
  u3 CLD{};  // CLUT load control: not interpreted by the model
  friend constexpr bool operator==(const tex0_reg&, const tex0_reg&) = default;
};

struct frame_reg {
  fixed::uint<9> FBP{};
  fixed::uint<6> FBW{};
  frame_psm PSM = frame_psm::PSMCT32;
  std::uint32_t FBMSK = 0;
  friend constexpr bool operator==(const frame_reg&, const frame_reg&) = default;
};

struct colclamp_reg {
  bool CLAMP = true;
  friend constexpr bool operator==(const colclamp_reg&, const colclamp_reg&) = default;
};
struct pabe_reg {
  bool PABE = false;
  friend constexpr bool operator==(const pabe_reg&, const pabe_reg&) = default;
};
struct fba_reg {
  bool FBA = false;
  friend constexpr bool operator==(const fba_reg&, const fba_reg&) = default;
};
struct dthe_reg {
  bool DTHE = false;
  friend constexpr bool operator==(const dthe_reg&, const dthe_reg&) = default;
};

prim_reg decode_prim(std::uint64_t v);
rgbaq_reg decode_rgbaq(std::uint64_t v);
tex0_reg decode_tex0(std::uint64_t v);
alpha_reg decode_alpha(std::uint64_t v);
test_reg decode_test(std::uint64_t v);
frame_reg decode_frame(std::uint64_t v);
colclamp_reg decode_colclamp(std::uint64_t v);
pabe_reg decode_pabe(std::uint64_t v);
fba_reg decode_fba(std::uint64_t v);
dthe_reg decode_dthe(std::uint64_t v);
dimx_reg decode_dimx(std::uint64_t v);
zbuf_reg decode_zbuf(std::uint64_t v);  // named "ZBUF_1" in errors

std::uint64_t encode(const prim_reg& r);
std::uint64_t encode(const rgbaq_reg& r);
std::uint64_t encode(const tex0_reg& r);
std::uint64_t encode(const alpha_reg& r);
std::uint64_t encode(const test_reg& r);
std::uint64_t encode(const frame_reg& r);
std::uint64_t encode(const colclamp_reg& r);
std::uint64_t encode(const pabe_reg& r);
std::uint64_t encode(const fba_reg& r);
std::uint64_t encode(const dthe_reg& r);
std::uint64_t encode(const dimx_reg& r);
std::uint64_t encode(const zbuf_reg& r);

// The register state one pixel sees. Defaults are the neutral values `gsdot3 alu` documents: every
// register 0 (no texture, no blend, no alpha test, PSMCT32, FBMSK = 0, no FBA, no dither) except
// COLCLAMP = 1.
struct gs_registers {
  prim_reg PRIM;
  rgbaq_reg RGBAQ;
  tex0_reg TEX0_1;
  alpha_reg ALPHA_1{blend_colour::Cs, blend_colour::Cs, blend_alpha::As, blend_colour::Cs, u8{}};  // value 0
  test_reg TEST_1;
  frame_reg FRAME_1;
  colclamp_reg COLCLAMP;
  pabe_reg PABE;
  fba_reg FBA_1;
  dthe_reg DTHE;
  dimx_reg DIMX;
  friend bool operator==(const gs_registers&, const gs_registers&) = default;
};

// The register mnemonics `gsdot3 alu --reg` accepts, in manual order.
inline constexpr std::string_view register_names[] = {"PRIM",     "RGBAQ", "TEX0_1", "ALPHA_1", "TEST_1", "FRAME_1",
                                                      "COLCLAMP", "PABE",  "FBA_1",  "DTHE",    "DIMX"};

// Decodes VALUE into register NAME of `regs`; throws register_error for an unknown name or a bad value.
void set_register(gs_registers& regs, std::string_view name, std::uint64_t value);
// The 64-bit value of register NAME (throws register_error for an unknown name).
std::uint64_t register_value(const gs_registers& regs, std::string_view name);

}  // namespace gs
