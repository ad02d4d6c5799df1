// gs_memory/overlay.hpp — how one format's page lies over another's: for each pixel of a page read
// in format `view`, the pixel of format `base` (same page, same memory) whose bits it reads, and
// where in that pixel's storage unit. With base PSMCT32 and view PSMT8 this is section 3.3's
// "the DPB read as an 8-bit texture": texel (u, v) is byte `bit / 8` (R, G, B, A) of pixel (x, y).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gs_memory/address.hpp"
#include "gs_memory/format.hpp"

namespace gs::mem {

struct overlay_cell {
  std::uint32_t x = 0, y = 0;  // the base-format pixel
  unsigned bit = 0;            // first bit of the view pixel inside the base pixel's storage unit
};

// One page (the view format's page extent, row-major) of `view` over the page of `base` at block 0.
inline std::vector<overlay_cell> page_overlay(psm base, psm view) {
  const layout lb = layout_of(base), lv = layout_of(view);
  const extent pb = page_size(lb), pv = page_size(lv);
  const unsigned ub = unit_bits(lb);
  // Which base pixel owns each nibble of the page (a nibble is the smallest unit of any format).
  std::vector<overlay_cell> owner(page_bytes * 2);
  const buffer bb{fixed::uint<14>{}, fixed::uint<6>::from_wrapped(pb.w / 64), base};
  for (std::uint32_t y = 0; y < pb.h; ++y)
    for (std::uint32_t x = 0; x < pb.w; ++x) {
      const location at = locate(bb, x, y);
      const std::uint32_t start = (at.byte * 8 + at.bit - upper_shift(base)) / 4;  // the whole unit
      for (unsigned n = 0; n < ub / 4; ++n) owner[start + n] = {x, y, n * 4};
    }
  std::vector<overlay_cell> cells(static_cast<std::size_t>(pv.w) * pv.h);
  const buffer bv{fixed::uint<14>{}, fixed::uint<6>::from_wrapped(pv.w / 64), view};
  for (std::uint32_t v = 0; v < pv.h; ++v)
    for (std::uint32_t u = 0; u < pv.w; ++u) {
      const location at = locate(bv, u, v);
      cells[static_cast<std::size_t>(v) * pv.w + u] = owner[(at.byte * 8 + at.bit) / 4];
    }
  return cells;
}

// zsigma(x, y): the PSMZ32 pixel whose word is PSMCT32 pixel (x, y)'s, in the same page. The two
// formats' pages hold the same blocks with the four 32x16 quarters swapped along the diagonals, so the
// map is x ^ 32, y ^ 16 (its own inverse); tests/gs_memory checks it against page_overlay and locate.
// Section 3.4's z-trick draws the DPB in PSMZ32 and reads it back through the PSMCT32 layout with it.
constexpr std::array<int, 2> zsigma(int x, int y) noexcept { return {x ^ 32, y ^ 16}; }

}  // namespace gs::mem
