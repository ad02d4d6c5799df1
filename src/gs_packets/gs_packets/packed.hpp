// gs_packets/packed.hpp — the 128-bit PACKED-mode forms of the vertex registers, and the 64-bit GS
// register values they write.
//
// PACKED layouts from PCSX2 `pcsx2/GS/GSRegs.h` `REG128_(GIFPacked, …)` (read with the search tool),
// which transcribe the GS User's Manual "PACKED mode" table (bit 0 = bit 0 of the first 64-bit word):
//   PRIM   PRIM 0-10
//   RGBA   R 0-7, G 32-39, B 64-71, A 96-103           (Q comes from the last packed ST)
//   STQ    S 0-31, T 32-63, Q 64-95 (floats)
//   UV     U 0-13, V 32-45
//   XYZF2  X 0-15, Y 32-47, Z 68-91, F 100-107, ADC 111
//   XYZ2   X 0-15, Y 32-47, Z 64-95, ADC 111
//   FOG    F 100-107
//   A+D    DATA 0-63, ADDR 64-71
// The 64-bit register values (`REG64_(GIFReg, …)` in the same file): RGBAQ R 0-7 G 8-15 B 16-23 A 24-31
// Q 32-63; ST S 0-31 T 32-63; UV U 0-13 V 16-29; XYZF X 0-15 Y 16-31 Z 32-55 F 56-63; XYZ X 0-15 Y 16-31
// Z 32-63; FOG F 56-63; PRIM 0-10. ADC = 1 sends XYZ to XYZF3 / XYZ3 (no drawing kick).
#pragma once

#include <cstdint>

#include "gs_packets/gif_tag.hpp"

namespace gs::packets {

constexpr qword packed_prim(std::uint32_t prim) noexcept { return {prim & 0x7FFu, 0}; }
constexpr qword packed_rgba(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) noexcept {
  return {std::uint64_t{r} | (std::uint64_t{g} << 32), std::uint64_t{b} | (std::uint64_t{a} << 32)};
}
// S, T, Q as IEEE single bit patterns.
constexpr qword packed_stq(std::uint32_t s, std::uint32_t t, std::uint32_t q) noexcept {
  return {std::uint64_t{s} | (std::uint64_t{t} << 32), std::uint64_t{q}};
}
constexpr qword packed_uv(std::uint32_t u, std::uint32_t v) noexcept {
  return {std::uint64_t{u & 0x3FFFu} | (std::uint64_t{v & 0x3FFFu} << 32), 0};
}
constexpr qword packed_xyzf2(std::uint16_t x, std::uint16_t y, std::uint32_t z24, std::uint8_t f, bool adc) noexcept {
  return {std::uint64_t{x} | (std::uint64_t{y} << 32),
          (std::uint64_t{z24 & 0xFFFFFFu} << 4) | (std::uint64_t{f} << 36) | (std::uint64_t{adc} << 47)};
}
constexpr qword packed_xyz2(std::uint16_t x, std::uint16_t y, std::uint32_t z, bool adc) noexcept {
  return {std::uint64_t{x} | (std::uint64_t{y} << 32), std::uint64_t{z} | (std::uint64_t{adc} << 47)};
}
constexpr qword packed_fog(std::uint8_t f) noexcept { return {0, std::uint64_t{f} << 36}; }
constexpr qword packed_ad(std::uint8_t address, std::uint64_t data) noexcept { return {data, address}; }

// A register write produced by one PACKED qword (address, value); `none` for NOP and the reserved
// descriptor 0xB. `q` is the Q of the last packed ST (in / out).
struct packed_write {
  bool none = false;
  std::uint8_t address = 0;
  std::uint64_t value = 0;
};

constexpr packed_write unpack(unsigned descriptor, const qword& d, std::uint32_t& q) noexcept {
  const auto w0 = d.lo & 0xFFFFFFFFu, w1 = d.lo >> 32, w2 = d.hi & 0xFFFFFFFFu, w3 = d.hi >> 32;
  switch (descriptor) {
    case desc::PRIM: return {false, 0x00, d.lo & 0x7FF};
    case desc::RGBAQ:
      return {false, 0x01,
              (w0 & 0xFF) | ((w1 & 0xFF) << 8) | ((w2 & 0xFF) << 16) | ((w3 & 0xFF) << 24) | (std::uint64_t{q} << 32)};
    case desc::ST: q = static_cast<std::uint32_t>(w2); return {false, 0x02, d.lo};
    case desc::UV: return {false, 0x03, (w0 & 0x3FFF) | ((w1 & 0x3FFF) << 16)};
    case desc::XYZF2:
    case desc::XYZF3: {
      const bool adc = descriptor == desc::XYZF3 || ((d.hi >> 47) & 1) != 0;
      return {false, static_cast<std::uint8_t>(adc ? 0x0C : 0x04),
              (w0 & 0xFFFF) | ((w1 & 0xFFFF) << 16) | (((d.hi >> 4) & 0xFFFFFF) << 32) | (((d.hi >> 36) & 0xFF) << 56)};
    }
    case desc::XYZ2:
    case desc::XYZ3: {
      const bool adc = descriptor == desc::XYZ3 || ((d.hi >> 47) & 1) != 0;
      return {false, static_cast<std::uint8_t>(adc ? 0x0D : 0x05), (w0 & 0xFFFF) | ((w1 & 0xFFFF) << 16) | (w2 << 32)};
    }
    case desc::TEX0_1:
    case desc::TEX0_2:
    case desc::CLAMP_1:
    case desc::CLAMP_2: return {false, static_cast<std::uint8_t>(descriptor), d.lo};
    case desc::FOG: return {false, 0x0A, ((d.hi >> 36) & 0xFF) << 56};
    case desc::A_D: return {false, static_cast<std::uint8_t>(d.hi & 0xFF), d.lo};
    default: return {true, 0, 0};  // NOP, reserved 0xB
  }
}

}  // namespace gs::packets
