// gs_memory/fast_address.hpp — the address function tabulated once per buffer for the renderer's
// inner loops (render_options::memory_path). Not a third formulation of the layout: every entry is
// a value of formulation A (tables::unit_address, locate); what these add is how the entries are
// combined, and tests/gs_memory/fast_address_test.cpp checks each combination against the function
// itself on every coordinate it claims (exhaustive over the extent, a sweep of BW and BP).
//
// row_column_address (32- and 16-bit layouts): unit(x, y) = (row[y] + column[x]) mod the memory's
// units, row[y] = unit(0, y), column[x] = unit(x, 0) − unit(0, 0). Why a sum: in swizzle_bits.hpp's bit maps every bit
// of the block number and of the unit in the column comes from x alone or from y alone (32-bit block bx0 by0 bx1 by1
// bx2, word x0 y0 x1 x2; 16-bit block by0 bx0 by1 bx1 by2 or, 16S, by0 bx0 by2 by1 bx1, halfword x3 x0 y0 x1 x2; the Z
// layouts flip one x bit and one y bit of the block), so x's and y's bits land in disjoint bit
// positions and OR is +; the page term x/page_w·32 + y/page_h·pages_per_row·32 blocks is linear, and
// the wrap at 16384 blocks is the modulo of the sum. PSMT8/PSMT4 are not sums (the byte's
// "x ^ 4·s" depends on y), and the test shows it.
//
// texel_addresses: the byte address of each texel of a w × h region of a buffer at BP = 0 (PSMT4: and
// which nibble); at base BP the address is that + 256·BP mod 4 MiB (BP enters unit_address only as the
// added block count).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "gs_memory/address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/swizzle_tables.hpp"

namespace gs::mem {

class row_column_address {
 public:
  // Pixels [0, width) × [0, height) of the buffer at bp (blocks), bw (64-pixel units), layout l.
  row_column_address(layout l, std::uint32_t bp, std::uint32_t bw, std::uint32_t width, std::uint32_t height)
      : mask_(memory_bytes * 8 / unit_bits(l) - 1), row_(height), column_(width) {
    if (unit_bits(l) < 16)
      throw std::invalid_argument("row_column_address: PSMT8/PSMT4 addresses are not row + column");
    for (std::uint32_t y = 0; y < height; ++y) row_[y] = tables::unit_address(l, bp, bw, 0, y);
    const std::uint32_t origin = tables::unit_address(l, 0, bw, 0, 0);  // the Z layouts' block 24 of (0, 0)
    for (std::uint32_t x = 0; x < width; ++x) column_[x] = (tables::unit_address(l, 0, bw, x, 0) - origin) & mask_;
  }
  std::uint32_t unit(std::uint32_t x, std::uint32_t y) const noexcept { return (row_[y] + column_[x]) & mask_; }
  // The tables themselves, for loops that combine them in SIMD lanes (gs_simd/span_draw.hpp).
  const std::uint32_t* rows() const noexcept { return row_.data(); }
  const std::uint32_t* columns() const noexcept { return column_.data(); }
  std::uint32_t mask() const noexcept { return mask_; }

 private:
  std::uint32_t mask_;
  std::vector<std::uint32_t> row_, column_;
};

class texel_addresses {
 public:
  // Texels [0, w) × [0, h) of a texture of format p (PSMT4: one nibble; PSMT8, PSMT8H: one byte;
  // PSMCT32, PSMZ32: one word) and TBW bw.
  texel_addresses(psm p, std::uint32_t bw, std::uint32_t w, std::uint32_t h) : bits_(value_bits(p)), w_(w), at_(w * h) {
    if (bits_ != 4 && bits_ != 8 && bits_ != 32)
      throw std::invalid_argument("texel_addresses: 4-, 8- and 32-bit texels only");
    if (bits_ == 4 && upper_shift(p) != 0) throw std::invalid_argument("texel_addresses: PSMT4HL/HH are not tabulated");
    // locate at BP 0 is (page · 32 + block in page) mod 16384 blocks, page = u / pw + (v / ph) · pages
    // per row, and the block and the unit in it depend on (u mod pw, v mod ph) alone (swizzle_tables.hpp
    // unit_address_of): one page's offsets, then the page term added.
    const extent pg = page_size(layout_of(p));
    const buffer at0{{}, fixed::uint<6>::from_wrapped(bw), p};
    std::vector<std::uint32_t> in_page(pg.w * pg.h);
    for (std::uint32_t v = 0; v < pg.h; ++v)
      for (std::uint32_t u = 0; u < pg.w; ++u) {
        const location at = locate(at0, u, v);
        in_page[v * pg.w + u] = bits_ == 4 ? 2 * at.byte + at.bit / 4 : at.byte;  // PSMT4: the nibble's address
      }
    const std::uint32_t per_row = pages_per_row(layout_of(p), bw),
                        page_units = bits_ == 4 ? 2 * page_bytes : page_bytes;
    constexpr std::uint32_t pages = memory_bytes / page_bytes;  // 512: the page term wraps here
    for (std::uint32_t v = 0; v < h; ++v) {
      const std::uint32_t* row = &in_page[v % pg.h * pg.w];
      for (std::uint32_t u = 0; u < w; ++u)
        at_[v * w + u] = (u / pg.w + v / pg.h * per_row) % pages * page_units + row[u % pg.w];
    }
  }
  std::uint32_t byte(std::uint32_t u, std::uint32_t v, std::uint32_t bp) const noexcept {
    const std::uint32_t a = bits_ == 4 ? at_[v * w_ + u] / 2 : at_[v * w_ + u];
    return (a + bp * block_bytes) % memory_bytes;
  }
  // The table (byte address at BP 0 of texel v·w + u) of an 8- or 32-bit texture, and its texel bits
  // and width: byte(u, v, bp) is (table()[v·w + u] + 256·bp) mod 4 MiB.
  const std::uint32_t* table() const noexcept { return at_.data(); }
  unsigned bits() const noexcept { return bits_; }
  std::uint32_t width() const noexcept { return w_; }
  // local_memory::read_pixel of texel (u, v) of the texture at bp.
  std::uint32_t read(const local_memory& m, std::uint32_t u, std::uint32_t v, std::uint32_t bp) const noexcept {
    const std::uint32_t a = byte(u, v, bp);
    if (bits_ == 4) return (m.byte(a) >> (4 * (at_[v * w_ + u] & 1u))) & 0xFu;  // even texel: low nibble
    return bits_ == 8 ? m.byte(a) : m.words()[a / 4];
  }

 private:
  unsigned bits_;  // 4, 8 or 32
  std::uint32_t w_;
  std::vector<std::uint32_t> at_;  // byte address at BP 0 (PSMT4: 2·byte + the high-nibble bit)
};

}  // namespace gs::mem
