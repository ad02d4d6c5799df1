// gs_memory/address.hpp — where pixel (x, y) of a buffer lives in local memory.
//
// A buffer is a base pointer BP in 256-byte blocks (as TEX0.TBP0, BITBLTBUF.DBP and TEX0.CBP count;
// FRAME.FBP and ZBUF.ZBP count 8 KiB pages = 32 blocks, see from_page), a width BW in 64-pixel units
// (TBW, FBW, DBW) and a storage format. The model's layout is formulation A (the manual's tables,
// swizzle_tables.hpp); tests/gs_memory checks it against formulation B (swizzle_bits.hpp) and the
// channel-fetch mapping of gs-memory-facts. Coordinates are 11-bit (0..2047) as the GS's.
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_memory/format.hpp"
#include "gs_memory/swizzle_tables.hpp"

namespace gs::mem {

struct buffer {
  fixed::uint<14> BP{};  // blocks
  fixed::uint<6> BW{};   // 64-pixel units
  psm PSM = psm::PSMCT32;
  friend constexpr bool operator==(const buffer&, const buffer&) = default;
};

// FRAME.FBP / ZBUF.ZBP (pages) as a block base pointer.
constexpr fixed::uint<14> from_page(fixed::uint<9> page) noexcept {
  return fixed::uint<14>::from_wrapped(static_cast<std::uint32_t>(page.value()) * 32u);
}

// The bits of one pixel value: value_bits(PSM) bits starting at bit `bit` of byte `byte`, little-endian
// across bytes (the GS memory holds 32-bit words as the EE does, least significant byte first).
struct location {
  std::uint32_t byte = 0;  // 0 .. 4 MiB - 1
  unsigned bit = 0;        // 0, or 4 for the high nibble of a byte (PSMT4 odd texels, PSMT4HH)
  unsigned bits = 32;
  constexpr std::uint32_t page() const noexcept { return byte / page_bytes; }
  constexpr std::uint32_t block() const noexcept { return byte / block_bytes; }
  constexpr std::uint32_t column() const noexcept { return byte / column_bytes % 4; }
  friend constexpr bool operator==(const location&, const location&) = default;
};

// The location of a unit address (in unit_bits(layout) units) for format p.
constexpr location location_of_unit(psm p, std::uint32_t unit) noexcept {
  const layout l = layout_of(p);
  location at{};
  at.bits = value_bits(p);
  switch (unit_bits(l)) {
    case 32: at.byte = unit * 4; break;
    case 16: at.byte = unit * 2; break;
    case 8: at.byte = unit; break;
    default:
      at.byte = unit / 2;
      at.bit = (unit & 1u) * 4;
      break;  // even texel = low nibble
  }
  if (const unsigned s = upper_shift(p); s != 0) {  // bits 24.. of the 32-bit word
    at.byte += s / 8;
    at.bit = s % 8;
  }
  return at;
}

constexpr location locate(const buffer& b, std::uint32_t x, std::uint32_t y) noexcept {
  const layout l = layout_of(b.PSM);
  return location_of_unit(b.PSM, tables::unit_address(l, static_cast<std::uint32_t>(b.BP.value()),
                                                      static_cast<std::uint32_t>(b.BW.value()), x, y));
}

}  // namespace gs::mem
