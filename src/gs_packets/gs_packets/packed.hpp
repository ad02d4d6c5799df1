// gs_packets/packed.hpp — the 128-bit PACKED-mode forms of the vertex registers, and the 64-bit GS
// register values they write.
//
// PACKED layouts from PCSX2 `pcsx2/GS/GSRegs.h` `REG128_(GIFPacked, …)` (read with the search tool),
// which transcribe the GS User's Manual "PACKED mode" table, as fields of the qword's low (`lo`, bits
// 0-63) and high (`hi`, bits 64-127) 64-bit words, in `packed_layout` below. The 64-bit register values
// they write are gs_regs/drawing.hpp's tables. ADC = 1 sends XYZ to XYZF3 / XYZ3 (no drawing kick).
#pragma once

#include <cstdint>

#include "gs_packets/gif_tag.hpp"
#include "gs_regs/drawing.hpp"

namespace gs::packets {

// The PACKED qword's fields: `lo_*` in bits 0-63, `hi_*` in bits 64-127 (a field's `lo` counts from
// the start of its word). Every 32-bit lane holds one value: R / S / X / U / PRIM in lane 0, G / T / Y / V
// in lane 1, B / Q / Z (XYZ2) in lane 2, A in lane 3; XYZF2 packs Z, F and ADC into the high word.
namespace packed_layout {
using gs::regs::field;
inline constexpr field lane0{"lane0", 0, 32}, lane1{"lane1", 32, 32};  // of either word
inline constexpr field PRIM{"PRIM", 0, 11}, U{"U", 0, 14}, V{"V", 32, 14}, X{"X", 0, 16}, Y{"Y", 32, 16};
inline constexpr field hi_Z24{"Z", 4, 24}, hi_F{"F", 36, 8}, hi_ADC{"ADC", 47, 1}, A_D_ADDR{"ADDR", 0, 8};
}  // namespace packed_layout

namespace detail {
namespace L = packed_layout;
using gs::regs::encode_low_bits;
}  // namespace detail

constexpr qword packed_prim(std::uint32_t prim) noexcept { return {detail::encode_low_bits(detail::L::PRIM, prim), 0}; }
constexpr qword packed_rgba(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) noexcept {
  using namespace detail;
  return {encode_low_bits(L::lane0, r) | encode_low_bits(L::lane1, g),
          encode_low_bits(L::lane0, b) | encode_low_bits(L::lane1, a)};
}
// S, T, Q as IEEE single bit patterns.
constexpr qword packed_stq(std::uint32_t s, std::uint32_t t, std::uint32_t q) noexcept {
  using namespace detail;
  return {encode_low_bits(L::lane0, s) | encode_low_bits(L::lane1, t), encode_low_bits(L::lane0, q)};
}
constexpr qword packed_uv(std::uint32_t u, std::uint32_t v) noexcept {
  using namespace detail;
  return {encode_low_bits(L::U, u) | encode_low_bits(L::V, v), 0};
}
constexpr qword packed_xyzf2(std::uint16_t x, std::uint16_t y, std::uint32_t z24, std::uint8_t f, bool adc) noexcept {
  using namespace detail;
  return {encode_low_bits(L::X, x) | encode_low_bits(L::Y, y),
          encode_low_bits(L::hi_Z24, z24) | encode_low_bits(L::hi_F, f) | encode_low_bits(L::hi_ADC, adc)};
}
constexpr qword packed_xyz2(std::uint16_t x, std::uint16_t y, std::uint32_t z, bool adc) noexcept {
  using namespace detail;
  return {encode_low_bits(L::X, x) | encode_low_bits(L::Y, y),
          encode_low_bits(L::lane0, z) | encode_low_bits(L::hi_ADC, adc)};
}
constexpr qword packed_fog(std::uint8_t f) noexcept { return {0, detail::encode_low_bits(detail::L::hi_F, f)}; }
constexpr qword packed_ad(std::uint8_t address, std::uint64_t data) noexcept { return {data, address}; }

// A register write produced by one PACKED qword (address, value); `none` for NOP and the reserved
// descriptor 0xB. `q` is the Q of the last packed ST (in / out).
struct packed_write {
  bool none = false;
  std::uint8_t address = 0;
  std::uint64_t value = 0;
};

constexpr packed_write unpack(unsigned descriptor, const qword& d, std::uint32_t& q) noexcept {
  using namespace detail;
  namespace R = gs::regs;
  using R::decode;
  const auto w0 = decode(L::lane0, d.lo), w1 = decode(L::lane1, d.lo), w2 = decode(L::lane0, d.hi),
             w3 = decode(L::lane1, d.hi);
  switch (descriptor) {
    case desc::PRIM: return {false, 0x00, decode(L::PRIM, d.lo)};
    case desc::RGBAQ:
      return {false, 0x01,
              encode_low_bits(R::RGBAQ::R, w0) | encode_low_bits(R::RGBAQ::G, w1) | encode_low_bits(R::RGBAQ::B, w2) |
                  encode_low_bits(R::RGBAQ::A, w3) | encode_low_bits(R::RGBAQ::Q, q)};
    case desc::ST: q = static_cast<std::uint32_t>(w2); return {false, 0x02, d.lo};
    case desc::UV: return {false, 0x03, encode_low_bits(R::UV::U, w0) | encode_low_bits(R::UV::V, w1)};
    case desc::XYZF2:
    case desc::XYZF3: {
      const bool adc = descriptor == desc::XYZF3 || decode(L::hi_ADC, d.hi) != 0;
      return {false, static_cast<std::uint8_t>(adc ? 0x0C : 0x04),
              encode_low_bits(R::XYZF2::X, w0) | encode_low_bits(R::XYZF2::Y, w1) |
                  encode_low_bits(R::XYZF2::Z, decode(L::hi_Z24, d.hi)) |
                  encode_low_bits(R::XYZF2::F, decode(L::hi_F, d.hi))};
    }
    case desc::XYZ2:
    case desc::XYZ3: {
      const bool adc = descriptor == desc::XYZ3 || decode(L::hi_ADC, d.hi) != 0;
      return {false, static_cast<std::uint8_t>(adc ? 0x0D : 0x05),
              encode_low_bits(R::XYZ2::X, w0) | encode_low_bits(R::XYZ2::Y, w1) | encode_low_bits(R::XYZ2::Z, w2)};
    }
    case desc::TEX0_1:
    case desc::TEX0_2:
    case desc::CLAMP_1:
    case desc::CLAMP_2: return {false, static_cast<std::uint8_t>(descriptor), d.lo};
    case desc::FOG: return {false, 0x0A, encode_low_bits(R::FOG::F, decode(L::hi_F, d.hi))};
    case desc::A_D: return {false, static_cast<std::uint8_t>(decode(L::A_D_ADDR, d.hi)), d.lo};
    default: return {true, 0, 0};  // NOP, reserved 0xB
  }
}

}  // namespace gs::packets
