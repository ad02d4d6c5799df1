// gs_memory/swizzle_tables.hpp — formulation A of the address layout: the manual's tables.
//
// GS User's Manual section 8 draws, for each format, the arrangement of the 32 blocks in a page and
// the order of the pixels inside a block (its columns). These are those figures as tables, as PCSX2
// transcribes them (`pcsx2/GS/GSTables.cpp`: `_blockTable32`, `_blockTable32Z`, `_blockTable16`,
// `_blockTable16S`, `_blockTable16Z`, `_blockTable16SZ`, PSMT8 uses `_blockTable32`'s and PSMT4
// `_blockTable16`'s arrangement; `columnTable32/16/8/4`), with PCSX2's block-number formula
// (`pcsx2/GS/GSLocalMemory.h`, `BlockNumber32` ...): block = BP + (y / page_h)·pages_per_row·32 +
// (x / page_w)·32 + table[row][col], wrapped at 16384 blocks. Play! (`Source/gs/GsPixelFormats.cpp`)
// holds the same block tables. Formulation B (`swizzle_bits.hpp`) computes the same offsets from
// bit formulas; tests/gs_memory checks the two against each other on every coordinate of a page.
#pragma once

#include <array>
#include <cstdint>

#include "gs_memory/format.hpp"

namespace gs::mem::tables {

// Block number inside the page of block column bx, block row by.
inline constexpr std::uint8_t block32[4][8] = {{0, 1, 4, 5, 16, 17, 20, 21},
                                               {2, 3, 6, 7, 18, 19, 22, 23},
                                               {8, 9, 12, 13, 24, 25, 28, 29},
                                               {10, 11, 14, 15, 26, 27, 30, 31}};
inline constexpr std::uint8_t block32z[4][8] = {{24, 25, 28, 29, 8, 9, 12, 13},
                                                {26, 27, 30, 31, 10, 11, 14, 15},
                                                {16, 17, 20, 21, 0, 1, 4, 5},
                                                {18, 19, 22, 23, 2, 3, 6, 7}};
inline constexpr std::uint8_t block16[8][4] = {{0, 2, 8, 10},    {1, 3, 9, 11},    {4, 6, 12, 14},   {5, 7, 13, 15},
                                               {16, 18, 24, 26}, {17, 19, 25, 27}, {20, 22, 28, 30}, {21, 23, 29, 31}};
inline constexpr std::uint8_t block16s[8][4] = {{0, 2, 16, 18}, {1, 3, 17, 19}, {8, 10, 24, 26},  {9, 11, 25, 27},
                                                {4, 6, 20, 22}, {5, 7, 21, 23}, {12, 14, 28, 30}, {13, 15, 29, 31}};
inline constexpr std::uint8_t block16z[8][4] = {{24, 26, 16, 18}, {25, 27, 17, 19}, {28, 30, 20, 22}, {29, 31, 21, 23},
                                                {8, 10, 0, 2},    {9, 11, 1, 3},    {12, 14, 4, 6},   {13, 15, 5, 7}};
inline constexpr std::uint8_t block16sz[8][4] = {{24, 26, 8, 10},  {25, 27, 9, 11},  {16, 18, 0, 2}, {17, 19, 1, 3},
                                                 {28, 30, 12, 14}, {29, 31, 13, 15}, {20, 22, 4, 6}, {21, 23, 5, 7}};

// Unit index inside a block (32-bit words, 16-bit halfwords, bytes, nibbles) of pixel (x, y) of the block.
inline constexpr std::uint8_t column32[8][8] = {{0, 1, 4, 5, 8, 9, 12, 13},       {2, 3, 6, 7, 10, 11, 14, 15},
                                                {16, 17, 20, 21, 24, 25, 28, 29}, {18, 19, 22, 23, 26, 27, 30, 31},
                                                {32, 33, 36, 37, 40, 41, 44, 45}, {34, 35, 38, 39, 42, 43, 46, 47},
                                                {48, 49, 52, 53, 56, 57, 60, 61}, {50, 51, 54, 55, 58, 59, 62, 63}};
inline constexpr std::uint8_t column16[8][16] = {
    {0, 2, 8, 10, 16, 18, 24, 26, 1, 3, 9, 11, 17, 19, 25, 27},
    {4, 6, 12, 14, 20, 22, 28, 30, 5, 7, 13, 15, 21, 23, 29, 31},
    {32, 34, 40, 42, 48, 50, 56, 58, 33, 35, 41, 43, 49, 51, 57, 59},
    {36, 38, 44, 46, 52, 54, 60, 62, 37, 39, 45, 47, 53, 55, 61, 63},
    {64, 66, 72, 74, 80, 82, 88, 90, 65, 67, 73, 75, 81, 83, 89, 91},
    {68, 70, 76, 78, 84, 86, 92, 94, 69, 71, 77, 79, 85, 87, 93, 95},
    {96, 98, 104, 106, 112, 114, 120, 122, 97, 99, 105, 107, 113, 115, 121, 123},
    {100, 102, 108, 110, 116, 118, 124, 126, 101, 103, 109, 111, 117, 119, 125, 127}};
inline constexpr std::uint8_t column8[16][16] = {
    {0, 4, 16, 20, 32, 36, 48, 52, 2, 6, 18, 22, 34, 38, 50, 54},
    {8, 12, 24, 28, 40, 44, 56, 60, 10, 14, 26, 30, 42, 46, 58, 62},
    {33, 37, 49, 53, 1, 5, 17, 21, 35, 39, 51, 55, 3, 7, 19, 23},
    {41, 45, 57, 61, 9, 13, 25, 29, 43, 47, 59, 63, 11, 15, 27, 31},
    {96, 100, 112, 116, 64, 68, 80, 84, 98, 102, 114, 118, 66, 70, 82, 86},
    {104, 108, 120, 124, 72, 76, 88, 92, 106, 110, 122, 126, 74, 78, 90, 94},
    {65, 69, 81, 85, 97, 101, 113, 117, 67, 71, 83, 87, 99, 103, 115, 119},
    {73, 77, 89, 93, 105, 109, 121, 125, 75, 79, 91, 95, 107, 111, 123, 127},
    {128, 132, 144, 148, 160, 164, 176, 180, 130, 134, 146, 150, 162, 166, 178, 182},
    {136, 140, 152, 156, 168, 172, 184, 188, 138, 142, 154, 158, 170, 174, 186, 190},
    {161, 165, 177, 181, 129, 133, 145, 149, 163, 167, 179, 183, 131, 135, 147, 151},
    {169, 173, 185, 189, 137, 141, 153, 157, 171, 175, 187, 191, 139, 143, 155, 159},
    {224, 228, 240, 244, 192, 196, 208, 212, 226, 230, 242, 246, 194, 198, 210, 214},
    {232, 236, 248, 252, 200, 204, 216, 220, 234, 238, 250, 254, 202, 206, 218, 222},
    {193, 197, 209, 213, 225, 229, 241, 245, 195, 199, 211, 215, 227, 231, 243, 247},
    {201, 205, 217, 221, 233, 237, 249, 253, 203, 207, 219, 223, 235, 239, 251, 255}};
// PSMT4: columns 0 and 2 share one pattern, 1 and 3 another (offset by 128 nibbles per column), so the
// manual's figure is given for columns 0 and 1 (rows 0-7 of the block); rows 8-15 add 256.
inline constexpr std::uint16_t column4[8][32] = {
    {0, 8,  32, 40, 64, 72, 96,  104, 2, 10, 34, 42, 66, 74, 98,  106,
     4, 12, 36, 44, 68, 76, 100, 108, 6, 14, 38, 46, 70, 78, 102, 110},
    {16, 24, 48, 56, 80, 88, 112, 120, 18, 26, 50, 58, 82, 90, 114, 122,
     20, 28, 52, 60, 84, 92, 116, 124, 22, 30, 54, 62, 86, 94, 118, 126},
    {65, 73, 97,  105, 1, 9,  33, 41, 67, 75, 99,  107, 3, 11, 35, 43,
     69, 77, 101, 109, 5, 13, 37, 45, 71, 79, 103, 111, 7, 15, 39, 47},
    {81, 89, 113, 121, 17, 25, 49, 57, 83, 91, 115, 123, 19, 27, 51, 59,
     85, 93, 117, 125, 21, 29, 53, 61, 87, 95, 119, 127, 23, 31, 55, 63},
    {192, 200, 224, 232, 128, 136, 160, 168, 194, 202, 226, 234, 130, 138, 162, 170,
     196, 204, 228, 236, 132, 140, 164, 172, 198, 206, 230, 238, 134, 142, 166, 174},
    {208, 216, 240, 248, 144, 152, 176, 184, 210, 218, 242, 250, 146, 154, 178, 186,
     212, 220, 244, 252, 148, 156, 180, 188, 214, 222, 246, 254, 150, 158, 182, 190},
    {129, 137, 161, 169, 193, 201, 225, 233, 131, 139, 163, 171, 195, 203, 227, 235,
     133, 141, 165, 173, 197, 205, 229, 237, 135, 143, 167, 175, 199, 207, 231, 239},
    {145, 153, 177, 185, 209, 217, 241, 249, 147, 155, 179, 187, 211, 219, 243, 251,
     149, 157, 181, 189, 213, 221, 245, 253, 151, 159, 183, 191, 215, 223, 247, 255}};

// Block number inside the page of the block holding page pixel (x, y).
constexpr std::uint32_t block_in_page(layout l, std::uint32_t x, std::uint32_t y) noexcept {
  const extent b = block_size(l);
  const std::uint32_t bx = x / b.w, by = y / b.h;
  switch (l) {
    case layout::ct32:
    case layout::t8: return block32[by][bx];
    case layout::z32: return block32z[by][bx];
    case layout::ct16:
    case layout::t4: return block16[by][bx];
    case layout::ct16s: return block16s[by][bx];
    case layout::z16: return block16z[by][bx];
    case layout::z16s: return block16sz[by][bx];
  }
  return 0;
}

// Unit index inside its block of page pixel (x, y) (units of unit_bits(l)).
constexpr std::uint32_t unit_in_block(layout l, std::uint32_t x, std::uint32_t y) noexcept {
  const extent b = block_size(l);
  const std::uint32_t bx = x % b.w, by = y % b.h;
  switch (unit_bits(l)) {
    case 32: return column32[by][bx];
    case 16: return column16[by][bx];
    case 8: return column8[by][bx];
    default: return column4[by & 7][bx] + (by & 8 ? 256u : 0u);
  }
}

// The unit address (in units of unit_bits, from the start of memory) of pixel (x, y) of a buffer at
// BP (blocks) BW (64-pixel units) wide: PCSX2's `BlockNumber*` then the column table.
template <layout L>
constexpr std::uint32_t unit_address_of(std::uint32_t bp, std::uint32_t bw, std::uint32_t x, std::uint32_t y) noexcept {
  constexpr extent pg = page_size(L);
  const std::uint32_t block =
      (bp + (y / pg.h) * pages_per_row(L, bw) * 32 + (x / pg.w) * 32 + block_in_page(L, x % pg.w, y % pg.h)) %
      memory_blocks;
  constexpr std::uint32_t units_per_block = block_bytes * 8 / unit_bits(L);
  return block * units_per_block + unit_in_block(L, x % pg.w, y % pg.h);
}
// The same for a layout known at run time: one instance per layout, so that every page, block and
// column size is a constant of its instance (powers of two: shifts and masks, not divisions).
constexpr std::uint32_t unit_address(layout l, std::uint32_t bp, std::uint32_t bw, std::uint32_t x,
                                     std::uint32_t y) noexcept {
  switch (l) {
    case layout::ct32: return unit_address_of<layout::ct32>(bp, bw, x, y);
    case layout::z32: return unit_address_of<layout::z32>(bp, bw, x, y);
    case layout::ct16: return unit_address_of<layout::ct16>(bp, bw, x, y);
    case layout::ct16s: return unit_address_of<layout::ct16s>(bp, bw, x, y);
    case layout::z16: return unit_address_of<layout::z16>(bp, bw, x, y);
    case layout::z16s: return unit_address_of<layout::z16s>(bp, bw, x, y);
    case layout::t8: return unit_address_of<layout::t8>(bp, bw, x, y);
    case layout::t4: return unit_address_of<layout::t4>(bp, bw, x, y);
  }
  return 0;
}

}  // namespace gs::mem::tables
