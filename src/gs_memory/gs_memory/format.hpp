// gs_memory/format.hpp — the geometry of each pixel storage format: page, block and column sizes.
//
// GS User's Manual section 8 (as transcribed in PCSX2 `pcsx2/GS/GSLocalMemory.h`, the `BlockNumber*`
// functions, and Play! `Source/gs/GsPixelFormats.h`, the `STORAGEPSM*` structs; the two agree):
// a page is 8 KiB = 32 blocks of 256 B, a block is 4 columns of 64 B. In pixels a page is 64×32
// (32-bit formats), 64×64 (16-bit), 128×64 (8-bit), 128×128 (4-bit); a block is 8×8, 16×8, 16×16,
// 32×16; a column is a block's width by 2, 2, 4, 4 rows. PSMCT24/PSMZ24 and the PSMT8H/PSMT4HL/
// PSMT4HH "upper" formats use the 32-bit layout. Confidence: high (manual + two emulators agree).
#pragma once

#include <cstdint>

#include "gs_arith/registers.hpp"

namespace gs::mem {

using psm = tex_psm;  // every storage format of the manual, with TEX0.PSM's codes

inline constexpr std::uint32_t memory_bytes = 4u << 20;  // 4 MiB
inline constexpr std::uint32_t page_bytes = 8192;
inline constexpr std::uint32_t block_bytes = 256;
inline constexpr std::uint32_t column_bytes = 64;
inline constexpr std::uint32_t memory_blocks = memory_bytes / block_bytes;  // 16384: TBP0/DBP/CBP wrap here

// The address layout a format uses (the upper formats and the 24-bit ones share the 32-bit layout).
enum class layout : std::uint8_t { ct32, z32, ct16, ct16s, z16, z16s, t8, t4 };

constexpr layout layout_of(psm p) noexcept {
  switch (p) {
    case psm::PSMCT32:
    case psm::PSMCT24:
    case psm::PSMT8H:
    case psm::PSMT4HL:
    case psm::PSMT4HH: return layout::ct32;
    case psm::PSMZ32:
    case psm::PSMZ24: return layout::z32;
    case psm::PSMCT16: return layout::ct16;
    case psm::PSMCT16S: return layout::ct16s;
    case psm::PSMZ16: return layout::z16;
    case psm::PSMZ16S: return layout::z16s;
    case psm::PSMT8: return layout::t8;
    case psm::PSMT4: return layout::t4;
  }
  return layout::ct32;
}

// Bits per storage unit of the layout (what one address step covers).
constexpr unsigned unit_bits(layout l) noexcept {
  switch (l) {
    case layout::ct32:
    case layout::z32: return 32;
    case layout::ct16:
    case layout::ct16s:
    case layout::z16:
    case layout::z16s: return 16;
    case layout::t8: return 8;
    case layout::t4: return 4;
  }
  return 32;
}

struct extent {
  std::uint32_t w, h;
  friend constexpr bool operator==(const extent&, const extent&) = default;
};

constexpr extent page_size(layout l) noexcept {
  switch (unit_bits(l)) {
    case 32: return {64, 32};
    case 16: return {64, 64};
    case 8: return {128, 64};
    default: return {128, 128};
  }
}

constexpr extent block_size(layout l) noexcept {
  switch (unit_bits(l)) {
    case 32: return {8, 8};
    case 16: return {16, 8};
    case 8: return {16, 16};
    default: return {32, 16};
  }
}

constexpr std::uint32_t column_height(layout l) noexcept { return unit_bits(l) >= 16 ? 2 : 4; }

// Pages per row of a buffer BW (in 64-pixel units) wide: PSMT8/PSMT4 pages are 128 wide, so BW/2
// (rounded down, as PCSX2's `BlockNumber8`'s `bw >> 1` and Play!'s `m_nWidth * 64 / PAGEWIDTH` both do).
constexpr std::uint32_t pages_per_row(layout l, std::uint32_t bw) noexcept { return bw * 64 / page_size(l).w; }

// The bits of a pixel value the format stores.
constexpr unsigned value_bits(psm p) noexcept {
  switch (p) {
    case psm::PSMCT32:
    case psm::PSMZ32: return 32;
    case psm::PSMCT24:
    case psm::PSMZ24: return 24;
    case psm::PSMCT16:
    case psm::PSMCT16S:
    case psm::PSMZ16:
    case psm::PSMZ16S: return 16;
    case psm::PSMT8:
    case psm::PSMT8H: return 8;
    case psm::PSMT4:
    case psm::PSMT4HL:
    case psm::PSMT4HH: return 4;
  }
  return 32;
}

// Where in its 32-bit word an upper format's value sits: PSMT8H bits 24-31, PSMT4HL 24-27, PSMT4HH
// 28-31 (manual section 8; PCSX2 `ReadPixel8H`/`ReadPixel4HL`/`ReadPixel4HH` shift by 24 and 28).
constexpr unsigned upper_shift(psm p) noexcept {
  return p == psm::PSMT4HH ? 28u : (p == psm::PSMT8H || p == psm::PSMT4HL) ? 24u : 0u;
}

}  // namespace gs::mem
