// gs_arith/clut.hpp — CLUT lookup of PSMT8, PSMT4 and PSMT8H indices into 32-bit palettes (CSM1).
//
// The CLUT buffer holds up to 256 32-bit entries in index order. With TEX0.CSM = 0 (CSM1) a 256-entry
// palette is stored in local memory as a 16×16 PSMCT32 image whose entries go in 8×2 blocks: index i
// sits at raster position (i & ~0x18) | ((i & 0x08) << 1) | ((i & 0x10) >> 1) — bits 3 and 4 swapped,
// so entries 8..15 are on the second row under 0..7, and 16..23 to the right of 0..7.
// Evidence: PCSX2 GSClut.cpp `WriteCLUT_T32_I8_CSM1` loads each group of 16 entries from the block
// offset `clutTableT32I8[(i << 4) & 0x70] | ((i << 4) & 0x80)` (groups 0..7 from words 0, 64, 16, 80,
// 32, 96, 48, 112 of the PSMCT32 blocks: rows 0-1 left, rows 0-1 right, rows 2-3 left, ...), and the
// 8×2 order inside a group is `clutTableT32I4` = the PSMCT32 column order, i.e. raster order
// (tests/gs_arith checks csm1_position against that derivation). A 16-entry palette is an 8×2 image,
// raster order = index order, loaded at entry 16·(CSA & 15). Confidence: medium-high (SW tables; no
// HW recording here).
// PSMT8 with CSA != 0: PCSX2 reads group g of 16 entries from min(16·g + 16·CSA, 240) (SW, from game
// behaviour, confidence low); the model follows it.
#pragma once

#include <array>
#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_arith/colour.hpp"

namespace gs {

using fixed::u4;
using fixed::u5;

using clut_buffer = std::array<rgba8, 256>;  // entry order

// Raster position in the 16×16 CSM1 image of palette index i (an involution: bits 3 and 4 swap).
constexpr unsigned csm1_position(u8 index) noexcept {
  const unsigned i = static_cast<unsigned>(index.value());
  return (i & ~0x18u) | ((i & 0x08u) << 1) | ((i & 0x10u) >> 1);
}

// The CLUT buffer after loading a 256-entry CSM1 palette (PSMT8 / PSMT8H) from its 16×16 image.
constexpr clut_buffer load_csm1_t8(const std::array<rgba8, 256>& image) noexcept {
  clut_buffer buf{};
  for (unsigned i = 0; i < 256; ++i) buf[i] = image[csm1_position(u8::from_wrapped(i))];
  return buf;
}

// The CLUT buffer after loading a 16-entry palette (PSMT4) from its 8×2 image at CSA.
constexpr clut_buffer load_csm1_t4(clut_buffer buf, const std::array<rgba8, 16>& image, u5 CSA) noexcept {
  const unsigned base = (static_cast<unsigned>(CSA.value()) & 15u) << 4;
  for (unsigned i = 0; i < 16; ++i) buf[base + i] = image[i];
  return buf;
}

// PSMT8 (and PSMT8H) index lookup.
constexpr rgba8 clut_t8(const clut_buffer& buf, u8 index, u5 CSA = u5{}) noexcept {
  const unsigned group = static_cast<unsigned>(index.value()) & 0xF0u;
  const unsigned offset = (static_cast<unsigned>(CSA.value()) & 15u) << 4;
  const unsigned start = group + offset < 240u ? group + offset : 240u;
  return buf[start + (static_cast<unsigned>(index.value()) & 15u)];
}

// PSMT4 index lookup: entry 16·(CSA & 15) + index.
constexpr rgba8 clut_t4(const clut_buffer& buf, u4 index, u5 CSA) noexcept {
  return buf[((static_cast<unsigned>(CSA.value()) & 15u) << 4) | static_cast<unsigned>(index.value())];
}

// PSMT8H: the index is the top byte (the alpha byte) of a 32-bit word.
constexpr u8 t8h_index(std::uint32_t word) noexcept { return u8::from_wrapped(word >> 24); }

}  // namespace gs
