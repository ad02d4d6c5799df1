// gs_simd/span_draw.hpp — the span engine: a triangle pass's runs of adjacent pixels drawn in SIMD
// lanes from end to end. Per triangle the lane offsets of its U and V planes are set up once; per
// run one division per plane gives the run's first quotient and remainder; then per vector of pixels
// U and V are stepped in lanes (quotient and remainder, one carry), clamped, turned into texel
// addresses, fetched (TEX1 nearest: PSMT8 through the CLUT as 32-bit words, or 32-bit texels), sent
// through the gs_simd units (pixel_units-inl.h) and merged into the frame buffer's row. The scalar
// path (gs::attribute_walker, gs::sample, gs::pixel_pipeline) stays the reference: span_triangle
// draws exactly what it draws, checked pixel for pixel on random triangles and whole frames
// (tests/gs_simd/span_draw_test.cpp, pipeline_simd_frame).
#pragma once

#include <cstddef>
#include <cstdint>

#include "gs_arith/attribute_setup.hpp"
#include "gs_arith/depth_test.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/registers.hpp"

namespace gsdot3::simd {

// TEX1 nearest from host arrays (the renderer's nearest_host_fetch): PSMT8 indices through a CLUT
// given as 32-bit words (CSA = 0: index i is entry i), or 32-bit texels; REPEAT or CLAMP; the sides
// powers of two (wmask = width − 1, shift = log2 width), at least 4 texels. No texture at all: every
// pointer null (the texel word is 0, as PRIM.TME = 0 reads none).
// Or from the modelled GS local memory (the memory path's nearest_memory_fetch): texel i = v << shift
// | u is at byte (address[i] + base) & mask of `memory` (the memory as words, byte a = bits 8·(a % 4)
// of word a / 4; gs_memory's texel_addresses table at the texture's TBP0), an 8-bit index through
// `words` (the CLUT) or, without a CLUT, the 32-bit word at that byte.
struct nearest_texture {
  const std::uint8_t* index = nullptr;
  const std::uint32_t* words = nullptr;  // 256 CLUT entries as words, with index or memory
  const std::uint32_t* texels = nullptr;
  const std::uint32_t* memory = nullptr;
  const std::uint32_t* address = nullptr;
  std::uint32_t base = 0, mask = 0;
  std::int32_t wmask = 0, hmask = 0;
  int shift = 0;
  bool clamp = false;
  bool textured() const noexcept { return index != nullptr || texels != nullptr || memory != nullptr; }
};

// Where the frame buffer's pixel (x, y) is: word y·stride + x of `words` (row-major), or with `row`
// set word (row[y] + column[x]) & mask (a PSMCT32 / PSMZ24 buffer of the GS local memory, `words`
// the memory: gs_memory's row_column_address tables). Distinct pixels of one row have distinct words.
struct span_target {
  std::uint32_t* words = nullptr;
  std::size_t stride = 0;
  const std::uint32_t* row = nullptr;
  const std::uint32_t* column = nullptr;
  std::uint32_t mask = 0;
};

// Pixels (x0 + k, y), 0 <= k < n, of one triangle: a row's run of its fragments.
struct span_run {
  std::int32_t x0, y, n;
};

// The widest rectangle span_applies takes (its runs are drawn in chunks of a fixed size).
inline constexpr int max_run = 2048;

// Whether span_triangle draws triangle `a` (its runs within window rectangle [x0, x1) × [y0, y1), at
// most max_run wide):
// exact U and V planes (uv_plane exact) whose denominator is below 2^30 and whose values over the
// rectangle stay within ±2^30, so that every quotient and remainder fits 32-bit lanes, and a colour
// that is one value over the plane (gs::flat_colour) or a per_pixel_floor plane (the default) that
// fits the same way. Otherwise the caller walks it with gs::attribute_walker.
bool span_applies(const gs::triangle_attributes& a, int x0, int y0, int x1, int y1) noexcept;

// Colour channel i of a triangle under gouraud_setup::per_pixel_floor at window pixel (x, y) is
// c0 + floor(n / |det|) (gs::attribute_walker's walk) with this numerator n = sign(det)·(nx·px +
// ny·py)·128, (px, py) the pixel's 12.4 offset from vertex 0 where clamp_distance leaves it alone.
inline std::int64_t gouraud_numerator(const gs::triangle_attributes& a, std::size_t i, std::int64_t x,
                                      std::int64_t y) noexcept {
  const gs::gouraud_exact_plane& e = a.colour.exact;
  const std::int64_t sign = e.det < 0 ? -1 : 1;
  return sign * (e.nx[i] * ((x + a.offset_x) * 16 - e.x0) + e.ny[i] * ((y + a.offset_y) * 16 - e.y0)) * 128;
}

// The runs of one triangle drawn with `regs` into frame buffer fb: each pixel's new word is
// gs::pixel_pipeline(regs, {cf, texel, old, x, y}, o).out with cf = a.colour_at(x, y) and texel = the
// nearest texel at (a.u.at(x, y), a.v.at(x, y)). Runs are drawn in order, each after the last (a
// run's pixels are distinct); the texture is not the frame buffer. Requires span_applies.
void span_triangle(const gs::gs_registers& regs, const gs::model_options& o, const gs::triangle_attributes& a,
                   const nearest_texture& tex, const span_run* runs, std::size_t count, const span_target& fb);

// A sprite's row: pixels (x0 + k, y), k < n, of one flat colour cf with texel words texels[k], into
// the row's frame-buffer words: words[k] = gs::pixel_pipeline(regs, {cf, texels[k], words[k], x0 + k,
// y}, o).out. The texels are read before any word is written.
void span_row(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& cf,
              const std::uint32_t* texels, std::uint32_t* words, int x0, int y, std::size_t n);

// A value-level channel-fetch sprite's row (the post filter, the ILP read): the texel of pixel k is
// clut[byte `channel` of src[k]] (the CLUT as 32-bit words, CSA = 0), then as span_row. src may be
// words itself: each pixel reads its own word before it is written.
void span_channel_row(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& cf,
                      const std::uint32_t* src, unsigned channel, const std::uint32_t* clut, std::uint32_t* words,
                      int x0, int y, std::size_t n);

// A depth pass over rows of one plane (step 1's, or the later passes' test): row i is pixels (rows[i].x0
// + k, rows[i].y), k < rows[i].n, whose stored words are z[y·stride + x] (a row-major Z buffer). Pixel
// k's source depth is p.at(x, y) (a fixed-point plane, den 0, or an exact one) and d =
// gs::depth_test(test, zbuf, that depth, its word). Row i's pass bits start at word w_i of `pass`
// (w_0 = 0, w_i+1 = w_i + ceil(n_i / 64)), bit k % 64 of word w_i + k / 64 set to d.pass (all its
// words overwritten); where d.write_z, the word becomes (word & keep) | (d.z & ~keep). Rows are done in
// order. Returns how many pixels pass. Requires depth_row_applies(p, ...) on a rectangle holding them.
std::size_t depth_rows(const gs::test_reg& test, const gs::zbuf_reg& zbuf, const gs::plane& p, std::uint32_t keep,
                       const span_run* rows, std::size_t count, std::uint32_t* z, std::size_t stride,
                       std::uint64_t* pass);
// Whether the plane's numerator and quotients fit depth_rows' 32-bit lanes on the rectangle [x0, x1) ×
// [y0, y1) (as span_applies' planes).
bool depth_row_applies(const gs::plane& p, int x0, int y0, int x1, int y1) noexcept;

// The memory path's channel-fetch sprites of one page (a buffer read as PSMT8): pixel k, at window
// (x0 + x[k], y0 + y[k]), fetches byte read_base + read[k] of the local memory `memory` (as words,
// byte a = bits 8·(a % 4) of word a / 4), its texel is clut[that byte] (the CLUT as words, CSA = 0),
// and its frame-buffer word is memory[word_base + word[k]]: that word becomes gs::pixel_pipeline(regs,
// {cf, texel, old, x, y}, o).out. The caller guarantees that no pixel writes a word another pixel
// reads (each reads a byte of its own word, or of words none of them writes), so the pixels are drawn
// in lanes in any order.
void span_fetched(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& cf,
                  std::uint32_t* memory, std::uint32_t read_base, const std::uint32_t* read, const std::uint32_t* clut,
                  std::uint32_t word_base, const std::uint32_t* word, int x0, int y0, const std::int32_t* x,
                  const std::int32_t* y, std::size_t n);

}  // namespace gsdot3::simd
