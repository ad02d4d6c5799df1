// gs_memory/swizzle_bits.hpp — formulation B of the address layout: closed bit formulas.
//
// The same layout as swizzle_tables.hpp written without the manual's tables, from the bit pattern
// the tables follow (read off the manual's section 8 figures; Play! `Source/gs/GsPixelFormats.h`
// `CPixelIndexor::BuildPageOffsetTable` builds its page-offset tables the same way: block, column,
// then a word table with the "x ^ 4 on odd half-columns" rule for PSMT8/PSMT4). Page stepping is
// Play!'s (`GetPixelAddress`): byte = BP·256 + page·8192 + offset-in-page, page = x / page_w +
// (y / page_h)·pages_per_row, wrapped at 4 MiB — a different route from PCSX2's block-number sum.
//
// Bit maps (bN = bit N of the block/column coordinate):
//   block, 32-bit and PSMT8 (8×4 blocks):  bx0 by0 bx1 by1 bx2     (LSB first)
//   block, 16-bit and PSMT4 (4×8 blocks):  by0 bx0 by1 bx1 by2
//   block, 16S:                            by0 bx0 by2 by1 bx1
//   Z formats: the non-Z block number ^ 0b11000 (the four 32×16 page quarters swapped diagonally).
//   word in a 32-bit column (8×2):         x0 y0 x1 x2
//   halfword in a 16-bit column (16×2):    x3 x0 y0 x1 x2
//   PSMT8 byte in a column (16×4): word = 32-bit word of (x ^ 4·s, y & 1), byte = 2·x3 + y1,
//     s = y1 ^ (column & 1);  PSMT4 nibble (32×4): word the same with x & 7, nibble = 2·(x3 x4) + y1.
#pragma once

#include <cstdint>

#include "gs_memory/format.hpp"

namespace gs::mem::bits {

constexpr std::uint32_t bit(std::uint32_t v, unsigned n) noexcept { return (v >> n) & 1u; }

constexpr std::uint32_t block_in_page(layout l, std::uint32_t x, std::uint32_t y) noexcept {
  const extent b = block_size(l);
  const std::uint32_t bx = x / b.w, by = y / b.h;
  std::uint32_t n = 0;
  switch (l) {
    case layout::ct32:
    case layout::z32:
    case layout::t8: n = bit(bx, 0) | bit(by, 0) << 1 | bit(bx, 1) << 2 | bit(by, 1) << 3 | bit(bx, 2) << 4; break;
    case layout::ct16:
    case layout::z16:
    case layout::t4: n = bit(by, 0) | bit(bx, 0) << 1 | bit(by, 1) << 2 | bit(bx, 1) << 3 | bit(by, 2) << 4; break;
    case layout::ct16s:
    case layout::z16s: n = bit(by, 0) | bit(bx, 0) << 1 | bit(by, 2) << 2 | bit(by, 1) << 3 | bit(bx, 1) << 4; break;
  }
  const bool z = l == layout::z32 || l == layout::z16 || l == layout::z16s;
  return z ? n ^ 0x18u : n;
}

// Word index in a 32-bit column of column pixel (x, y), x < 8, y < 2.
constexpr std::uint32_t word_in_column(std::uint32_t x, std::uint32_t y) noexcept {
  return bit(x, 0) | bit(y, 0) << 1 | (x & 6u) << 1;
}

// Offset inside the page, in units of unit_bits(l), of page pixel (x, y).
constexpr std::uint32_t unit_in_page(layout l, std::uint32_t x, std::uint32_t y) noexcept {
  const extent b = block_size(l);
  const std::uint32_t cx = x % b.w, cy = y % b.h;  // inside the block
  const std::uint32_t column = cy / column_height(l), ry = cy % column_height(l);
  const std::uint32_t block_units = block_bytes * 8 / unit_bits(l), column_units = block_units / 4;
  std::uint32_t in_column = 0;
  switch (unit_bits(l)) {
    case 32: in_column = word_in_column(cx, ry); break;
    case 16: in_column = bit(cx, 3) | (bit(cx, 0) | bit(ry, 0) << 1 | (cx & 6u) << 1) << 1; break;
    case 8: {
      const std::uint32_t s = bit(ry, 1) ^ (column & 1u);
      in_column = word_in_column((cx & 7u) ^ (s << 2), ry & 1u) * 4 + (bit(cx, 3) << 1 | bit(ry, 1));
      break;
    }
    default: {
      const std::uint32_t s = bit(ry, 1) ^ (column & 1u);
      in_column = word_in_column((cx & 7u) ^ (s << 2), ry & 1u) * 8 + (((cx >> 3) & 3u) << 1 | bit(ry, 1));
      break;
    }
  }
  return block_in_page(l, x, y) * block_units + column * column_units + in_column;
}

// The unit address of pixel (x, y) of a buffer at BP (blocks), BW (64-pixel units) wide.
constexpr std::uint32_t unit_address(layout l, std::uint32_t bp, std::uint32_t bw, std::uint32_t x,
                                     std::uint32_t y) noexcept {
  const extent pg = page_size(l);
  const std::uint32_t page = x / pg.w + (y / pg.h) * pages_per_row(l, bw);
  const std::uint32_t nibbles_per_unit = unit_bits(l) / 4;  // counted in nibbles, PSMT4's unit
  const std::uint32_t memory_units = memory_bytes * 2 / nibbles_per_unit;
  const std::uint32_t start = (bp * block_bytes + page * page_bytes) * 2 / nibbles_per_unit;
  return (start + unit_in_page(l, x % pg.w, y % pg.h)) % memory_units;
}

}  // namespace gs::mem::bits
