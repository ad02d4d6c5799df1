// gs_memory/memory_registers.hpp — the GS registers of transfers and texture wrapping, decoded from
// their 64-bit values.
//
// Bit layouts from the GS User's Manual (as transcribed in PCSX2 `pcsx2/GS/GSRegs.h`, the
// `REG64_(GIFReg, BITBLTBUF)`, `CLAMP`, `TRXPOS`, `TRXREG`, `TRXDIR` structs):
//   BITBLTBUF SBP:14 _:2 SBW:6 _:2 SPSM:6 _:2 DBP:14 _:2 DBW:6 _:2 DPSM:6 _:2
//   TRXPOS    SSAX:11 _:5 SSAY:11 _:5 DSAX:11 _:5 DSAY:11 DIR:2 _:3
//   TRXREG    RRW:12 _:20 RRH:12 _:20
//   TRXDIR    XDIR:2 _:62           (0 host->local, 1 local->host, 2 local->local, 3 off)
//   CLAMP_1   WMS:2 WMT:2 MINU:10 MAXU:10 MINV:10 MAXV:10 _:20
//   TEXCLUT   CBW:6 COU:6 COV:10 _:42 (CSM2's CLUT position: width in 64 pixels, x in 16 pixels, y)
// Decoding is strict as gs_arith/registers.hpp's: a set padding bit or an unknown PSM throws
// gs::register_error naming the register and field. encode() is the exact inverse.
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_arith/registers.hpp"
#include "gs_memory/format.hpp"

namespace gs::mem {

struct bitbltbuf_reg {
  fixed::uint<14> SBP{};
  fixed::uint<6> SBW{};
  psm SPSM = psm::PSMCT32;
  fixed::uint<14> DBP{};
  fixed::uint<6> DBW{};
  psm DPSM = psm::PSMCT32;
  friend constexpr bool operator==(const bitbltbuf_reg&, const bitbltbuf_reg&) = default;
};

struct trxpos_reg {
  fixed::uint<11> SSAX{}, SSAY{}, DSAX{}, DSAY{};
  fixed::uint<2> DIR{};  // pixel order of local->local transfers (not used by host->local)
  friend constexpr bool operator==(const trxpos_reg&, const trxpos_reg&) = default;
};

struct trxreg_reg {
  fixed::uint<12> RRW{}, RRH{};
  friend constexpr bool operator==(const trxreg_reg&, const trxreg_reg&) = default;
};

enum class xdir : std::uint8_t { host_to_local = 0, local_to_host = 1, local_to_local = 2, deactivated = 3 };
struct trxdir_reg {
  xdir XDIR = xdir::host_to_local;
  friend constexpr bool operator==(const trxdir_reg&, const trxdir_reg&) = default;
};

// CLAMP_1.WMS / WMT.
enum class wrap_mode : std::uint8_t { REPEAT = 0, CLAMP = 1, REGION_CLAMP = 2, REGION_REPEAT = 3 };
struct clamp_reg {
  wrap_mode WMS = wrap_mode::REPEAT, WMT = wrap_mode::REPEAT;
  fixed::uint<10> MINU{}, MAXU{}, MINV{}, MAXV{};  // REGION_REPEAT: MINU/MINV = mask, MAXU/MAXV = fix
  friend constexpr bool operator==(const clamp_reg&, const clamp_reg&) = default;
};

struct texclut_reg {
  fixed::uint<6> CBW{}, COU{};
  fixed::uint<10> COV{};
  friend constexpr bool operator==(const texclut_reg&, const texclut_reg&) = default;
};

bitbltbuf_reg decode_bitbltbuf(std::uint64_t v);
trxpos_reg decode_trxpos(std::uint64_t v);
trxreg_reg decode_trxreg(std::uint64_t v);
trxdir_reg decode_trxdir(std::uint64_t v);
clamp_reg decode_clamp(std::uint64_t v);
texclut_reg decode_texclut(std::uint64_t v);

std::uint64_t encode(const bitbltbuf_reg& r);
std::uint64_t encode(const trxpos_reg& r);
std::uint64_t encode(const trxreg_reg& r);
std::uint64_t encode(const trxdir_reg& r);
std::uint64_t encode(const clamp_reg& r);
std::uint64_t encode(const texclut_reg& r);

}  // namespace gs::mem
