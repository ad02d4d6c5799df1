#include "gs_memory/memory_registers.hpp"

#include <cstdio>
#include <string>
#include <string_view>

namespace gs::mem {
namespace {

std::string hex(std::uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(v));
  return buf;
}

// Reads fields of a register value; done() checks that no bit outside them is set.
class fields {
 public:
  fields(std::string_view reg, std::uint64_t v) : reg_(reg), v_(v) {}
  template <int N>
  fixed::uint<N> uint(int lo) {
    used_ |= ((std::uint64_t{1} << N) - 1) << lo;
    return fixed::uint<N>::from_wrapped((v_ >> lo) & ((std::uint64_t{1} << N) - 1));
  }
  psm format(std::string_view field, int lo) {
    const auto v = static_cast<std::uint64_t>(uint<6>(lo).value());
    for (const psm p : {psm::PSMCT32, psm::PSMCT24, psm::PSMCT16, psm::PSMCT16S, psm::PSMT8, psm::PSMT8H, psm::PSMT4,
                        psm::PSMT4HL, psm::PSMT4HH, psm::PSMZ32, psm::PSMZ24, psm::PSMZ16, psm::PSMZ16S})
      if (static_cast<std::uint64_t>(p) == v) return p;
    throw register_error(std::string(reg_) + "." + std::string(field) + " = " + hex(v) +
                         ": not a GS pixel storage format");
  }
  void done() const {
    if ((v_ & ~used_) != 0)
      throw register_error(std::string(reg_) + " = " + hex(v_) + ": reserved bits " + hex(v_ & ~used_) + " must be 0");
  }

 private:
  std::string_view reg_;
  std::uint64_t v_;
  std::uint64_t used_ = 0;
};

template <int N>
std::uint64_t bits(fixed::uint<N> v) {
  return static_cast<std::uint64_t>(v.value());
}
template <typename E>
std::uint64_t bits(E e) {
  return static_cast<std::uint64_t>(e);
}

}  // namespace

bitbltbuf_reg decode_bitbltbuf(std::uint64_t v) {
  fields f("BITBLTBUF", v);
  bitbltbuf_reg r;
  r.SBP = f.uint<14>(0);
  r.SBW = f.uint<6>(16);
  r.SPSM = f.format("SPSM", 24);
  r.DBP = f.uint<14>(32);
  r.DBW = f.uint<6>(48);
  r.DPSM = f.format("DPSM", 56);
  f.done();
  return r;
}
std::uint64_t encode(const bitbltbuf_reg& r) {
  return bits(r.SBP) | bits(r.SBW) << 16 | bits(r.SPSM) << 24 | bits(r.DBP) << 32 | bits(r.DBW) << 48 |
         bits(r.DPSM) << 56;
}

trxpos_reg decode_trxpos(std::uint64_t v) {
  fields f("TRXPOS", v);
  trxpos_reg r;
  r.SSAX = f.uint<11>(0);
  r.SSAY = f.uint<11>(16);
  r.DSAX = f.uint<11>(32);
  r.DSAY = f.uint<11>(48);
  r.DIR = f.uint<2>(59);
  f.done();
  return r;
}
std::uint64_t encode(const trxpos_reg& r) {
  return bits(r.SSAX) | bits(r.SSAY) << 16 | bits(r.DSAX) << 32 | bits(r.DSAY) << 48 | bits(r.DIR) << 59;
}

trxreg_reg decode_trxreg(std::uint64_t v) {
  fields f("TRXREG", v);
  trxreg_reg r;
  r.RRW = f.uint<12>(0);
  r.RRH = f.uint<12>(32);
  f.done();
  return r;
}
std::uint64_t encode(const trxreg_reg& r) { return bits(r.RRW) | bits(r.RRH) << 32; }

trxdir_reg decode_trxdir(std::uint64_t v) {
  fields f("TRXDIR", v);
  trxdir_reg r;
  r.XDIR = static_cast<xdir>(f.uint<2>(0).value());
  f.done();
  return r;
}
std::uint64_t encode(const trxdir_reg& r) { return bits(r.XDIR); }

clamp_reg decode_clamp(std::uint64_t v) {
  fields f("CLAMP_1", v);
  clamp_reg r;
  r.WMS = static_cast<wrap_mode>(f.uint<2>(0).value());
  r.WMT = static_cast<wrap_mode>(f.uint<2>(2).value());
  r.MINU = f.uint<10>(4);
  r.MAXU = f.uint<10>(14);
  r.MINV = f.uint<10>(24);
  r.MAXV = f.uint<10>(34);
  f.done();
  return r;
}
std::uint64_t encode(const clamp_reg& r) {
  return bits(r.WMS) | bits(r.WMT) << 2 | bits(r.MINU) << 4 | bits(r.MAXU) << 14 | bits(r.MINV) << 24 |
         bits(r.MAXV) << 34;
}

texclut_reg decode_texclut(std::uint64_t v) {
  fields f("TEXCLUT", v);
  texclut_reg r;
  r.CBW = f.uint<6>(0);
  r.COU = f.uint<6>(6);
  r.COV = f.uint<10>(12);
  f.done();
  return r;
}
std::uint64_t encode(const texclut_reg& r) { return bits(r.CBW) | bits(r.COU) << 6 | bits(r.COV) << 12; }

}  // namespace gs::mem
