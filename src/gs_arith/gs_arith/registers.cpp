#include "gs_arith/registers.hpp"

#include "gs_arith/field_reader.hpp"
#include "gs_regs/drawing.hpp"

namespace gs {
namespace {

namespace R = gs::regs;

// R, G, B, A (bits 0-31) in rgba8's own order (R lowest), as one 32-bit field beside Q (bits 32-63).
constexpr R::field RGBA{"RGBA", R::RGBAQ::R.lo, R::RGBAQ::A.lo + R::RGBAQ::A.width};

blend_colour colour_selector(field_reader& f, R::field sel) {
  const auto v = f.take(sel);
  if (v == R::ALPHA::selector_reserved) f.fail(sel.name, v, "reserved (0 = Cs, 1 = Cd, 2 = 0)");
  return static_cast<blend_colour>(v);
}

}  // namespace

prim_reg decode_prim(std::uint64_t v) {
  field_reader f("PRIM", v);
  prim_reg r;
  const auto type = f.take(R::PRIM::PRIM);
  if (type == R::PRIM::PRIM_reserved) f.fail("PRIM", type, "reserved primitive type");
  r.PRIM = static_cast<prim_type>(type);
  r.IIP = f.bit(R::PRIM::IIP);
  r.TME = f.bit(R::PRIM::TME);
  r.FGE = f.bit(R::PRIM::FGE);
  r.ABE = f.bit(R::PRIM::ABE);
  r.AA1 = f.bit(R::PRIM::AA1);
  r.FST = f.bit(R::PRIM::FST);
  r.CTXT = f.bit(R::PRIM::CTXT);
  r.FIX = f.bit(R::PRIM::FIX);
  f.done();
  return r;
}
std::uint64_t encode(const prim_reg& r) {
  namespace P = R::PRIM;
  return place(P::PRIM, r.PRIM) | place(P::IIP, r.IIP) | place(P::TME, r.TME) | place(P::FGE, r.FGE) |
         place(P::ABE, r.ABE) | place(P::AA1, r.AA1) | place(P::FST, r.FST) | place(P::CTXT, r.CTXT) |
         place(P::FIX, r.FIX);
}

rgbaq_reg decode_rgbaq(std::uint64_t v) {
  return {rgba8::from_u32(static_cast<std::uint32_t>(R::decode(RGBA, v))),
          static_cast<std::uint32_t>(R::decode(R::RGBAQ::Q, v))};
}
std::uint64_t encode(const rgbaq_reg& r) { return place(RGBA, r.colour.to_u32()) | place(R::RGBAQ::Q, r.Q); }

tex0_reg decode_tex0(std::uint64_t v) {
  field_reader f("TEX0_1", v);
  tex0_reg r;
  namespace T = R::TEX0;
  r.TBP0 = f.uint<14>(T::TBP0);
  r.TBW = f.uint<6>(T::TBW);
  const auto psm = f.take(T::PSM);
  if (!R::is_one_of(psm, R::texture_psms)) f.fail("PSM", psm, "not a GS pixel storage format");
  r.PSM = static_cast<tex_psm>(psm);
  r.TW = f.uint<4>(T::TW);
  if (r.TW.value() > T::TW_max) f.fail("TW", r.TW.value(), "texture width is at most 2^10");
  r.TH = f.uint<4>(T::TH);
  if (r.TH.value() > T::TH_max) f.fail("TH", r.TH.value(), "texture height is at most 2^10");
  r.TCC = static_cast<tcc>(f.take(T::TCC));
  r.TFX = static_cast<tfx>(f.take(T::TFX));
  r.CBP = f.uint<14>(T::CBP);
  const auto cpsm = f.take(T::CPSM);
  if (!R::is_one_of(cpsm, T::CPSM_valid)) f.fail("CPSM", cpsm, "CLUT format must be PSMCT32, PSMCT16 or PSMCT16S");
  r.CPSM = static_cast<clut_psm>(cpsm);
  r.CSM = f.bit(T::CSM);
  r.CSA = f.uint<5>(T::CSA);
  r.CLD = f.uint<3>(T::CLD);
  f.done();
  return r;
}
std::uint64_t encode(const tex0_reg& r) {
  namespace T = R::TEX0;
  return place(T::TBP0, r.TBP0) | place(T::TBW, r.TBW) | place(T::PSM, r.PSM) | place(T::TW, r.TW) |
         place(T::TH, r.TH) | place(T::TCC, r.TCC) | place(T::TFX, r.TFX) | place(T::CBP, r.CBP) |
         place(T::CPSM, r.CPSM) | place(T::CSM, r.CSM) | place(T::CSA, r.CSA) | place(T::CLD, r.CLD);
}

alpha_reg decode_alpha(std::uint64_t v) {
  field_reader f("ALPHA_1", v);
  alpha_reg r;
  r.A = colour_selector(f, R::ALPHA::A);
  r.B = colour_selector(f, R::ALPHA::B);
  const auto c = f.take(R::ALPHA::C);
  if (c == R::ALPHA::selector_reserved) f.fail("C", c, "reserved (0 = As, 1 = Ad, 2 = FIX)");
  r.C = static_cast<blend_alpha>(c);
  r.D = colour_selector(f, R::ALPHA::D);
  r.FIX = u8::from_wrapped(f.take(R::ALPHA::FIX));
  f.done();
  return r;
}
std::uint64_t encode(const alpha_reg& r) {
  namespace A = R::ALPHA;
  return place(A::A, r.A) | place(A::B, r.B) | place(A::C, r.C) | place(A::D, r.D) | place(A::FIX, r.FIX);
}

test_reg decode_test(std::uint64_t v) {
  field_reader f("TEST_1", v);
  test_reg r;
  namespace T = R::TEST;
  r.ATE = f.bit(T::ATE);
  r.ATST = static_cast<atst>(f.take(T::ATST));
  r.AREF = u8::from_wrapped(f.take(T::AREF));
  r.AFAIL = static_cast<afail>(f.take(T::AFAIL));
  r.DATE = f.bit(T::DATE);
  r.DATM = f.bit(T::DATM);
  r.ZTE = f.bit(T::ZTE);
  r.ZTST = static_cast<ztst>(f.take(T::ZTST));
  f.done();
  return r;
}
std::uint64_t encode(const test_reg& r) {
  namespace T = R::TEST;
  return place(T::ATE, r.ATE) | place(T::ATST, r.ATST) | place(T::AREF, r.AREF) | place(T::AFAIL, r.AFAIL) |
         place(T::DATE, r.DATE) | place(T::DATM, r.DATM) | place(T::ZTE, r.ZTE) | place(T::ZTST, r.ZTST);
}

frame_reg decode_frame(std::uint64_t v) {
  field_reader f("FRAME_1", v);
  frame_reg r;
  r.FBP = f.uint<9>(R::FRAME::FBP);
  r.FBW = f.uint<6>(R::FRAME::FBW);
  const auto psm = f.take(R::FRAME::PSM);
  if (!R::is_one_of(psm, R::FRAME::PSM_valid))
    f.fail("PSM", psm, "not a frame-buffer format (PSMCT32/24/16/16S, PSMZ32/24/16/16S)");
  r.PSM = static_cast<frame_psm>(psm);
  r.FBMSK = static_cast<std::uint32_t>(f.take(R::FRAME::FBMSK));
  f.done();
  return r;
}
std::uint64_t encode(const frame_reg& r) {
  namespace F = R::FRAME;
  return place(F::FBP, r.FBP) | place(F::FBW, r.FBW) | place(F::PSM, r.PSM) | place(F::FBMSK, r.FBMSK);
}

namespace {
bool one_bit_register(std::string_view name, R::field bit, std::uint64_t v) {
  field_reader f(name, v);
  const bool b = f.bit(bit);
  f.done();
  return b;
}
}  // namespace

colclamp_reg decode_colclamp(std::uint64_t v) { return {one_bit_register("COLCLAMP", R::COLCLAMP::CLAMP, v)}; }
pabe_reg decode_pabe(std::uint64_t v) { return {one_bit_register("PABE", R::PABE::PABE, v)}; }
fba_reg decode_fba(std::uint64_t v) { return {one_bit_register("FBA_1", R::FBA::FBA, v)}; }
dthe_reg decode_dthe(std::uint64_t v) { return {one_bit_register("DTHE", R::DTHE::DTHE, v)}; }
std::uint64_t encode(const colclamp_reg& r) { return place(R::COLCLAMP::CLAMP, r.CLAMP); }
std::uint64_t encode(const pabe_reg& r) { return place(R::PABE::PABE, r.PABE); }
std::uint64_t encode(const fba_reg& r) { return place(R::FBA::FBA, r.FBA); }
std::uint64_t encode(const dthe_reg& r) { return place(R::DTHE::DTHE, r.DTHE); }

dimx_reg decode_dimx(std::uint64_t v) {
  field_reader f("DIMX", v);
  dimx_reg r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.DM[i][j] = f.uint<3>(R::DIMX::DM(i, j));
  f.done();
  return r;
}
std::uint64_t encode(const dimx_reg& r) {
  std::uint64_t v = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v |= place(R::DIMX::DM(i, j), r.DM[i][j]);
  return v;
}

zbuf_reg decode_zbuf(std::uint64_t v) {
  field_reader f("ZBUF_1", v);
  zbuf_reg r;
  r.ZBP = f.uint<9>(R::ZBUF::ZBP);
  const auto psm = f.take(R::ZBUF::PSM);
  if (!R::is_one_of(psm, R::ZBUF::PSM_valid))
    f.fail("PSM", psm, "not a Z format (0 PSMZ32, 1 PSMZ24, 2 PSMZ16, 0xA PSMZ16S)");
  r.PSM = static_cast<zbuf_psm>(psm);
  r.ZMSK = f.bit(R::ZBUF::ZMSK);
  f.done();
  return r;
}
std::uint64_t encode(const zbuf_reg& r) {
  return place(R::ZBUF::ZBP, r.ZBP) | place(R::ZBUF::PSM, r.PSM) | place(R::ZBUF::ZMSK, r.ZMSK);
}

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
