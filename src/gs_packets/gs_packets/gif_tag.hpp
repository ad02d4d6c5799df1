// gs_packets/gif_tag.hpp — the GIF tag: the 128-bit header of every GIF packet (GS User's Manual,
// "GIFtag"), as a typed struct with constexpr encode / decode.
//
// Layout (bit 0 = least significant bit of the first 64-bit word), as transcribed in PCSX2
// `pcsx2/GS/GSRegs.h` `union GIFTag` (read with the search tool) and in PCSX2's older `GifTransfer.h`:
//   word 0: NLOOP 0-14, EOP 15, (unused 16-45), PRE 46, PRIM 47-57, FLG 58-59, NREG 60-63
//   word 1: REGS — sixteen 4-bit register descriptors, descriptor i at bits 4i..4i+3.
// NREG = 0 means 16 descriptors (manual). FLG: 0 PACKED, 1 REGLIST, 2 IMAGE, 3 "disabled" (the manual;
// PCSX2 names it GIF_FLG_IMAGE2 and treats it as IMAGE) — decode_gif_tag reports it as std::nullopt.
// Bits 16-45 are not interpreted by the GIF; decode ignores them, so encode(decode(q)) clears them.
// Confidence: high (manual, PCSX2, ps2sdk `gif_tags.h` agree on NLOOP 15 bits and EOP at bit 15).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "fixed/integer.hpp"
#include "gs_regs/field.hpp"

namespace gs::packets {

// One 128-bit GIF qword, as two little-endian 64-bit words (lo = bytes 0-7).
struct qword {
  std::uint64_t lo = 0, hi = 0;
  friend constexpr bool operator==(const qword&, const qword&) = default;
};

enum class gif_flg : std::uint8_t { PACKED = 0, REGLIST = 1, IMAGE = 2 };

struct gif_tag {
  fixed::uint<15> NLOOP{};
  bool EOP = false;
  bool PRE = false;
  fixed::uint<11> PRIM{};
  gif_flg FLG = gif_flg::PACKED;
  fixed::uint<4> NREG{};                  // 0 = 16 registers
  std::array<fixed::uint<4>, 16> REGS{};  // descriptor i is REGS[i]
  friend constexpr bool operator==(const gif_tag&, const gif_tag&) = default;

  // Registers per loop: NREG with 0 read as 16.
  constexpr unsigned registers() const noexcept {
    return NREG.value() == 0 ? 16u : static_cast<unsigned>(NREG.value());
  }
};

// The tag's fields in word 0 (the layout above) and one descriptor of word 1 (REGS[i] at 4i).
namespace gif_tag_layout {
using gs::regs::field;
inline constexpr field NLOOP{"NLOOP", 0, 15}, EOP{"EOP", 15, 1}, PRE{"PRE", 46, 1}, PRIM{"PRIM", 47, 11},
    FLG{"FLG", 58, 2}, NREG{"NREG", 60, 4};
inline constexpr field fields[] = {NLOOP, EOP, PRE, PRIM, FLG, NREG};
constexpr field REGS(unsigned i) noexcept { return {"REGS", static_cast<int>(4 * i), 4}; }
}  // namespace gif_tag_layout

constexpr qword encode(const gif_tag& t) noexcept {
  namespace L = gif_tag_layout;
  using gs::regs::encode_low_bits;
  qword q;
  q.lo = encode_low_bits(L::NLOOP, t.NLOOP.value()) | encode_low_bits(L::EOP, t.EOP) | encode_low_bits(L::PRE, t.PRE) |
         encode_low_bits(L::PRIM, t.PRIM.value()) | encode_low_bits(L::FLG, static_cast<std::uint64_t>(t.FLG)) |
         encode_low_bits(L::NREG, t.NREG.value());
  for (unsigned i = 0; i < 16; ++i) q.hi |= encode_low_bits(L::REGS(i), t.REGS[i].value());
  return q;
}

// The tag of a qword; std::nullopt when FLG = 3 (disabled).
constexpr std::optional<gif_tag> decode_gif_tag(const qword& q) noexcept {
  namespace L = gif_tag_layout;
  using gs::regs::decode;
  const auto flg = decode(L::FLG, q.lo);
  if (flg == 3) return std::nullopt;
  gif_tag t;
  t.NLOOP = fixed::uint<15>::from_wrapped(decode(L::NLOOP, q.lo));
  t.EOP = decode(L::EOP, q.lo) != 0;
  t.PRE = decode(L::PRE, q.lo) != 0;
  t.PRIM = fixed::uint<11>::from_wrapped(decode(L::PRIM, q.lo));
  t.FLG = static_cast<gif_flg>(flg);
  t.NREG = fixed::uint<4>::from_wrapped(decode(L::NREG, q.lo));
  for (unsigned i = 0; i < 16; ++i) t.REGS[i] = fixed::uint<4>::from_wrapped(decode(L::REGS(i), q.hi));
  return t;
}

// PACKED register descriptors (manual "Register descriptor"; PCSX2 `GSRegs.h` `enum GIF_REG`).
namespace desc {
inline constexpr unsigned PRIM = 0x0, RGBAQ = 0x1, ST = 0x2, UV = 0x3, XYZF2 = 0x4, XYZ2 = 0x5, TEX0_1 = 0x6,
                          TEX0_2 = 0x7, CLAMP_1 = 0x8, CLAMP_2 = 0x9, FOG = 0xA, XYZF3 = 0xC, XYZ3 = 0xD, A_D = 0xE,
                          NOP = 0xF;
}  // namespace desc

}  // namespace gs::packets
