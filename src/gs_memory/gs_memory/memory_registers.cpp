#include "gs_memory/memory_registers.hpp"

#include <string_view>

#include "gs_arith/field_reader.hpp"
#include "gs_regs/drawing.hpp"

namespace gs::mem {
namespace {

// Reads fields of a register value (gs_arith/field_reader.hpp), and the transfer registers' PSM fields.
class fields : public field_reader {
 public:
  using field_reader::field_reader;
  psm format(regs::field f) {
    const auto v = static_cast<std::uint64_t>(uint<6>(f).value());
    for (const psm p : {psm::PSMCT32, psm::PSMCT24, psm::PSMCT16, psm::PSMCT16S, psm::PSMT8, psm::PSMT8H, psm::PSMT4,
                        psm::PSMT4HL, psm::PSMT4HH, psm::PSMZ32, psm::PSMZ24, psm::PSMZ16, psm::PSMZ16S})
      if (static_cast<std::uint64_t>(p) == v) return p;
    fail(f.name, v, "not a GS pixel storage format");
  }
};

namespace R = gs::regs;

}  // namespace

bitbltbuf_reg decode_bitbltbuf(std::uint64_t v) {
  fields f("BITBLTBUF", v);
  bitbltbuf_reg r;
  namespace B = R::BITBLTBUF;
  r.SBP = f.uint<14>(B::SBP);
  r.SBW = f.uint<6>(B::SBW);
  r.SPSM = f.format(B::SPSM);
  r.DBP = f.uint<14>(B::DBP);
  r.DBW = f.uint<6>(B::DBW);
  r.DPSM = f.format(B::DPSM);
  f.done();
  return r;
}
std::uint64_t encode(const bitbltbuf_reg& r) {
  namespace B = R::BITBLTBUF;
  return place(B::SBP, r.SBP) | place(B::SBW, r.SBW) | place(B::SPSM, r.SPSM) | place(B::DBP, r.DBP) |
         place(B::DBW, r.DBW) | place(B::DPSM, r.DPSM);
}

trxpos_reg decode_trxpos(std::uint64_t v) {
  fields f("TRXPOS", v);
  trxpos_reg r;
  namespace P = R::TRXPOS;
  r.SSAX = f.uint<11>(P::SSAX);
  r.SSAY = f.uint<11>(P::SSAY);
  r.DSAX = f.uint<11>(P::DSAX);
  r.DSAY = f.uint<11>(P::DSAY);
  r.DIR = f.uint<2>(P::DIR);
  f.done();
  return r;
}
std::uint64_t encode(const trxpos_reg& r) {
  namespace P = R::TRXPOS;
  return place(P::SSAX, r.SSAX) | place(P::SSAY, r.SSAY) | place(P::DSAX, r.DSAX) | place(P::DSAY, r.DSAY) |
         place(P::DIR, r.DIR);
}

trxreg_reg decode_trxreg(std::uint64_t v) {
  fields f("TRXREG", v);
  trxreg_reg r;
  r.RRW = f.uint<12>(R::TRXREG::RRW);
  r.RRH = f.uint<12>(R::TRXREG::RRH);
  f.done();
  return r;
}
std::uint64_t encode(const trxreg_reg& r) { return place(R::TRXREG::RRW, r.RRW) | place(R::TRXREG::RRH, r.RRH); }

trxdir_reg decode_trxdir(std::uint64_t v) {
  fields f("TRXDIR", v);
  trxdir_reg r;
  r.XDIR = static_cast<xdir>(f.uint<2>(R::TRXDIR::XDIR).value());
  f.done();
  return r;
}
std::uint64_t encode(const trxdir_reg& r) { return place(R::TRXDIR::XDIR, r.XDIR); }

clamp_reg decode_clamp(std::uint64_t v) {
  fields f("CLAMP_1", v);
  clamp_reg r;
  namespace C = R::CLAMP;
  r.WMS = static_cast<wrap_mode>(f.uint<2>(C::WMS).value());
  r.WMT = static_cast<wrap_mode>(f.uint<2>(C::WMT).value());
  r.MINU = f.uint<10>(C::MINU);
  r.MAXU = f.uint<10>(C::MAXU);
  r.MINV = f.uint<10>(C::MINV);
  r.MAXV = f.uint<10>(C::MAXV);
  f.done();
  return r;
}
std::uint64_t encode(const clamp_reg& r) {
  namespace C = R::CLAMP;
  return place(C::WMS, r.WMS) | place(C::WMT, r.WMT) | place(C::MINU, r.MINU) | place(C::MAXU, r.MAXU) |
         place(C::MINV, r.MINV) | place(C::MAXV, r.MAXV);
}

texclut_reg decode_texclut(std::uint64_t v) {
  fields f("TEXCLUT", v);
  texclut_reg r;
  r.CBW = f.uint<6>(R::TEXCLUT::CBW);
  r.COU = f.uint<6>(R::TEXCLUT::COU);
  r.COV = f.uint<10>(R::TEXCLUT::COV);
  f.done();
  return r;
}
std::uint64_t encode(const texclut_reg& r) {
  return place(R::TEXCLUT::CBW, r.CBW) | place(R::TEXCLUT::COU, r.COU) | place(R::TEXCLUT::COV, r.COV);
}

}  // namespace gs::mem
