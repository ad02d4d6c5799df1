#include "gs_arith/registers.hpp"

#include "gs_arith/field_reader.hpp"

namespace gs {
namespace {

using field_bits::bits;

blend_colour colour_selector(field_reader& f, std::string_view name, int lo) {
  const auto v = f.take(lo, 2);
  if (v == 3) f.fail(name, v, "reserved (0 = Cs, 1 = Cd, 2 = 0)");
  return static_cast<blend_colour>(v);
}

bool is_tex_psm(std::uint64_t v) {
  switch (v) {
    case 0x00:
    case 0x01:
    case 0x02:
    case 0x0A:
    case 0x13:
    case 0x14:
    case 0x1B:
    case 0x24:
    case 0x2C:
    case 0x30:
    case 0x31:
    case 0x32:
    case 0x3A: return true;
    default: return false;
  }
}

bool is_frame_psm(std::uint64_t v) {
  switch (v) {
    case 0x00:
    case 0x01:
    case 0x02:
    case 0x0A:
    case 0x30:
    case 0x31:
    case 0x32:
    case 0x3A: return true;
    default: return false;
  }
}

}  // namespace

prim_reg decode_prim(std::uint64_t v) {
  field_reader f("PRIM", v);
  prim_reg r;
  const auto type = f.take(0, 3);
  if (type == 7) f.fail("PRIM", type, "reserved primitive type");
  r.PRIM = static_cast<prim_type>(type);
  r.IIP = f.bit(3);
  r.TME = f.bit(4);
  r.FGE = f.bit(5);
  r.ABE = f.bit(6);
  r.AA1 = f.bit(7);
  r.FST = f.bit(8);
  r.CTXT = f.bit(9);
  r.FIX = f.bit(10);
  f.done();
  return r;
}
std::uint64_t encode(const prim_reg& r) {
  return bits(r.PRIM) | bits(r.IIP) << 3 | bits(r.TME) << 4 | bits(r.FGE) << 5 | bits(r.ABE) << 6 | bits(r.AA1) << 7 |
         bits(r.FST) << 8 | bits(r.CTXT) << 9 | bits(r.FIX) << 10;
}

rgbaq_reg decode_rgbaq(std::uint64_t v) {
  return {rgba8::from_u32(static_cast<std::uint32_t>(v)), static_cast<std::uint32_t>(v >> 32)};
}
std::uint64_t encode(const rgbaq_reg& r) { return r.colour.to_u32() | std::uint64_t{r.Q} << 32; }

tex0_reg decode_tex0(std::uint64_t v) {
  field_reader f("TEX0_1", v);
  tex0_reg r;
  r.TBP0 = f.uint<14>(0);
  r.TBW = f.uint<6>(14);
  const auto psm = f.take(20, 6);
  if (!is_tex_psm(psm)) f.fail("PSM", psm, "not a GS pixel storage format");
  r.PSM = static_cast<tex_psm>(psm);
  r.TW = f.uint<4>(26);
  if (r.TW.value() > 10) f.fail("TW", r.TW.value(), "texture width is at most 2^10");
  r.TH = f.uint<4>(30);
  if (r.TH.value() > 10) f.fail("TH", r.TH.value(), "texture height is at most 2^10");
  r.TCC = static_cast<tcc>(f.take(34, 1));
  r.TFX = static_cast<tfx>(f.take(35, 2));
  r.CBP = f.uint<14>(37);
  const auto cpsm = f.take(51, 4);
  if (cpsm != 0x0 && cpsm != 0x2 && cpsm != 0xA)
    f.fail("CPSM", cpsm, "CLUT format must be PSMCT32, PSMCT16 or PSMCT16S");
  r.CPSM = static_cast<clut_psm>(cpsm);
  r.CSM = f.bit(55);
  r.CSA = f.uint<5>(56);
  r.CLD = f.uint<3>(61);
  f.done();
  return r;
}
std::uint64_t encode(const tex0_reg& r) {
  return bits(r.TBP0) | bits(r.TBW) << 14 | bits(r.PSM) << 20 | bits(r.TW) << 26 | bits(r.TH) << 30 |
         bits(r.TCC) << 34 | bits(r.TFX) << 35 | bits(r.CBP) << 37 | bits(r.CPSM) << 51 | bits(r.CSM) << 55 |
         bits(r.CSA) << 56 | bits(r.CLD) << 61;
}

alpha_reg decode_alpha(std::uint64_t v) {
  field_reader f("ALPHA_1", v);
  alpha_reg r;
  r.A = colour_selector(f, "A", 0);
  r.B = colour_selector(f, "B", 2);
  const auto c = f.take(4, 2);
  if (c == 3) f.fail("C", c, "reserved (0 = As, 1 = Ad, 2 = FIX)");
  r.C = static_cast<blend_alpha>(c);
  r.D = colour_selector(f, "D", 6);
  r.FIX = u8::from_wrapped(f.take(32, 8));
  f.done();
  return r;
}
std::uint64_t encode(const alpha_reg& r) {
  return bits(r.A) | bits(r.B) << 2 | bits(r.C) << 4 | bits(r.D) << 6 | static_cast<std::uint64_t>(r.FIX.value()) << 32;
}

test_reg decode_test(std::uint64_t v) {
  field_reader f("TEST_1", v);
  test_reg r;
  r.ATE = f.bit(0);
  r.ATST = static_cast<atst>(f.take(1, 3));
  r.AREF = u8::from_wrapped(f.take(4, 8));
  r.AFAIL = static_cast<afail>(f.take(12, 2));
  r.DATE = f.bit(14);
  r.DATM = f.bit(15);
  r.ZTE = f.bit(16);
  r.ZTST = static_cast<ztst>(f.take(17, 2));
  f.done();
  return r;
}
std::uint64_t encode(const test_reg& r) {
  return bits(r.ATE) | bits(r.ATST) << 1 | static_cast<std::uint64_t>(r.AREF.value()) << 4 | bits(r.AFAIL) << 12 |
         bits(r.DATE) << 14 | bits(r.DATM) << 15 | bits(r.ZTE) << 16 | bits(r.ZTST) << 17;
}

frame_reg decode_frame(std::uint64_t v) {
  field_reader f("FRAME_1", v);
  frame_reg r;
  r.FBP = f.uint<9>(0);
  r.FBW = f.uint<6>(16);
  const auto psm = f.take(24, 6);
  if (!is_frame_psm(psm)) f.fail("PSM", psm, "not a frame-buffer format (PSMCT32/24/16/16S, PSMZ32/24/16/16S)");
  r.PSM = static_cast<frame_psm>(psm);
  r.FBMSK = static_cast<std::uint32_t>(f.take(32, 32));
  f.done();
  return r;
}
std::uint64_t encode(const frame_reg& r) {
  return bits(r.FBP) | bits(r.FBW) << 16 | bits(r.PSM) << 24 | std::uint64_t{r.FBMSK} << 32;
}

namespace {
bool one_bit_register(std::string_view name, std::uint64_t v) {
  field_reader f(name, v);
  const bool b = f.bit(0);
  f.done();
  return b;
}
}  // namespace

colclamp_reg decode_colclamp(std::uint64_t v) { return {one_bit_register("COLCLAMP", v)}; }
pabe_reg decode_pabe(std::uint64_t v) { return {one_bit_register("PABE", v)}; }
fba_reg decode_fba(std::uint64_t v) { return {one_bit_register("FBA_1", v)}; }
dthe_reg decode_dthe(std::uint64_t v) { return {one_bit_register("DTHE", v)}; }
std::uint64_t encode(const colclamp_reg& r) { return bits(r.CLAMP); }
std::uint64_t encode(const pabe_reg& r) { return bits(r.PABE); }
std::uint64_t encode(const fba_reg& r) { return bits(r.FBA); }
std::uint64_t encode(const dthe_reg& r) { return bits(r.DTHE); }

dimx_reg decode_dimx(std::uint64_t v) {
  field_reader f("DIMX", v);
  dimx_reg r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.DM[i][j] = f.uint<3>(16 * i + 4 * j);
  f.done();
  return r;
}
std::uint64_t encode(const dimx_reg& r) {
  std::uint64_t v = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v |= bits(r.DM[i][j]) << (16 * i + 4 * j);
  return v;
}

zbuf_reg decode_zbuf(std::uint64_t v) {
  field_reader f("ZBUF_1", v);
  zbuf_reg r;
  r.ZBP = f.uint<9>(0);
  const auto psm = f.take(24, 4);
  if (psm != 0x0 && psm != 0x1 && psm != 0x2 && psm != 0xA)
    f.fail("PSM", psm, "not a Z format (0 PSMZ32, 1 PSMZ24, 2 PSMZ16, 0xA PSMZ16S)");
  r.PSM = static_cast<zbuf_psm>(psm);
  r.ZMSK = f.bit(32);
  f.done();
  return r;
}
std::uint64_t encode(const zbuf_reg& r) { return bits(r.ZBP) | bits(r.PSM) << 24 | bits(r.ZMSK) << 32; }

void set_register(gs_registers& regs, std::string_view name, std::uint64_t value) {
  if (name == "PRIM")
    regs.PRIM = decode_prim(value);
  else if (name == "RGBAQ")
    regs.RGBAQ = decode_rgbaq(value);
  else if (name == "TEX0_1")
    regs.TEX0_1 = decode_tex0(value);
  else if (name == "ALPHA_1")
    regs.ALPHA_1 = decode_alpha(value);
  else if (name == "TEST_1")
    regs.TEST_1 = decode_test(value);
  else if (name == "FRAME_1")
    regs.FRAME_1 = decode_frame(value);
  else if (name == "COLCLAMP")
    regs.COLCLAMP = decode_colclamp(value);
  else if (name == "PABE")
    regs.PABE = decode_pabe(value);
  else if (name == "FBA_1")
    regs.FBA_1 = decode_fba(value);
  else if (name == "DTHE")
    regs.DTHE = decode_dthe(value);
  else if (name == "DIMX")
    regs.DIMX = decode_dimx(value);
  else {
    std::string known;
    for (auto n : register_names) known += (known.empty() ? "" : ", ") + std::string(n);
    throw register_error("unknown register '" + std::string(name) + "' (known: " + known + ")");
  }
}

std::uint64_t register_value(const gs_registers& regs, std::string_view name) {
  if (name == "PRIM") return encode(regs.PRIM);
  if (name == "RGBAQ") return encode(regs.RGBAQ);
  if (name == "TEX0_1") return encode(regs.TEX0_1);
  if (name == "ALPHA_1") return encode(regs.ALPHA_1);
  if (name == "TEST_1") return encode(regs.TEST_1);
  if (name == "FRAME_1") return encode(regs.FRAME_1);
  if (name == "COLCLAMP") return encode(regs.COLCLAMP);
  if (name == "PABE") return encode(regs.PABE);
  if (name == "FBA_1") return encode(regs.FBA_1);
  if (name == "DTHE") return encode(regs.DTHE);
  if (name == "DIMX") return encode(regs.DIMX);
  throw register_error("unknown register '" + std::string(name) + "'");
}

}  // namespace gs
