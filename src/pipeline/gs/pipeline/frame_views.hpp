// pipeline/frame_views.hpp — where render.cpp's frame buffers keep pixel (x, y): row-major vectors (the
// value path) or PSMCT32 / PSMZ24 buffers in the modelled GS local memory (the memory path). Internal
// to render.cpp. And the fragments a triangle pass draws, as positions and runs along a row.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gs_memory/fast_address.hpp"
#include "gs_memory/swizzle_tables.hpp"
#include "gs_simd/span_draw.hpp"
#include "pipeline/prepare.hpp"

namespace gsdot3::pipeline::detail {

// Value-level row loops, each over two distinct rows (restrict, so that the compiler vectorises them).
inline void low_bytes(const std::uint32_t* __restrict s, std::uint8_t* __restrict d, int n) {
  for (int k = 0; k < n; ++k) d[k] = static_cast<std::uint8_t>(s[k] & 0xFFu);
}
inline void opaque(const std::uint32_t* __restrict s, std::uint32_t* __restrict d, int n) {
  for (int k = 0; k < n; ++k) d[k] = s[k] | 0xFF000000u;
}
inline void byte_into_alpha(const std::uint32_t* __restrict s, std::uint32_t* __restrict d, int n, unsigned shift) {
  for (int k = 0; k < n; ++k) d[k] = (d[k] & 0x00FFFFFFu) | (((s[k] >> shift) & 0xFFu) << 24);
}

// Where a frame buffer's pixel (x, y) is: a row-major frame-sized vector (value level, row_view), or
// a PSMCT32 buffer in the modelled GS local memory (render_options::memory_path, memory_view: `words`
// is the 4 MiB memory, FBP·32 = bp, FBW = bw; the address is gs_memory's PSMCT32 layout). The passes
// are templates over the view, so the value-level path is compiled as before.
struct row_view {
  std::uint32_t* words = nullptr;
  int width = 0;
  std::uint32_t& operator()(int x, int y) const noexcept {
    return words[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};
// With `address` set (gs_memory's row_column_address of the same layout, equal to unit_address on
// every pixel: tests/gs_memory/fast_address_test.cpp) the address is looked up, else computed.
struct memory_view {
  std::uint32_t* words = nullptr;
  std::uint32_t bp = 0, bw = 0;  // blocks, 64-pixel units
  bool z = false;                // the buffer is drawn in PSMZ32 (section 3.4's z-trick modes)
  const gs::mem::row_column_address* address = nullptr;
  constexpr gs::mem::layout layout() const noexcept { return z ? gs::mem::layout::z32 : gs::mem::layout::ct32; }
  std::uint32_t& operator()(int x, int y) const noexcept {
    const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
    return words[address ? address->unit(ux, uy) : gs::mem::tables::unit_address(layout(), bp, bw, ux, uy)];
  }
  // The word of (x, y) (its index in `words`), and the first word of its page: with bp on a whole
  // page, a 32-bit layout's 8 KiB page is 2048 words in a row (fill_band, fetch_pages).
  std::uint32_t word_of(int x, int y) const noexcept { return static_cast<std::uint32_t>(&(*this)(x, y) - words); }
  std::uint32_t page_of(int x, int y) const noexcept { return word_of(x, y) / 2048 * 2048; }
  // f(x, word of (x, y)) for x0 <= x < x1: the tables' pointers and row read once, outside the loop
  // (through operator() every store of f's makes the compiler load them again).
  template <class F>
  void row(int y, int x0, int x1, F&& f) const {
    if (address == nullptr) {
      for (int x = x0; x < x1; ++x) f(x, (*this)(x, y));
      return;
    }
    const std::uint32_t r = address->rows()[y], m = address->mask();
    const std::uint32_t* column = address->columns();
    std::uint32_t* w = words;
    for (int x = x0; x < x1; ++x) f(x, w[(r + column[x]) & m]);
  }
};

// The span engine's view of a frame buffer (gs_simd/span_draw.hpp); a memory_view's needs `address`.
inline simd::span_target span_target_of(const row_view& v) noexcept {
  return {v.words, static_cast<std::size_t>(v.width)};
}
inline simd::span_target span_target_of(const memory_view& v) noexcept {
  return {v.words, 0, v.address->rows(), v.address->columns(), v.address->mask()};
}

// The Z buffer (ZBUF_1, PSMZ24): row-major on the value path, at ZBP in the modelled local memory on
// the memory path (the word of PSMZ24 pixel (x, y): memory_view in the Z layout). A write keeps the
// word's top byte (PSMZ24 stores bits 0-23).
struct z_view {
  row_view rows;
  memory_view memory;
  bool in_memory = false;
  std::uint32_t& operator()(int x, int y) const noexcept { return in_memory ? memory(x, y) : rows(x, y); }
  std::uint32_t read(int x, int y) const noexcept { return (*this)(x, y); }
  static constexpr std::uint32_t kept_bits = 0xFF000000u;  // a write's: the 24-bit depth leaves the top byte
  void write(int x, int y, std::uint32_t z) const noexcept {
    std::uint32_t& w = (*this)(x, y);
    w = (w & kept_bits) | (z & ~kept_bits);
  }
};

struct fragment {
  std::int32_t tri;
  std::int16_t x, y;
};
// Fragments (x0 + k, y), k < n, of one triangle: the cached fragments' runs along a row.
using run = simd::span_run;

// Triangles r's records of v (fragments, runs), which `at` indexes per triangle: v[at[t], at[t + 1]).
template <class T>
std::span<const T> of(const std::vector<T>& v, const std::vector<std::size_t>& at, triangle_range r) {
  return std::span<const T>(v).subspan(at[r.first], at[r.end] - at[r.first]);
}

}  // namespace gsdot3::pipeline::detail
