// gs_simd/span_rows.cpp — see span_draw.hpp: the sprites' rows (span_row, span_channel_row) and the
// memory path's fetched pixels (span_fetched), per target (Highway foreach_target.h over
// pixel_units-inl.h).
#include "gs_simd/span_draw.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gs_simd/span_rows.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include <algorithm>

#include "gs_simd/pixel_units-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace gsdot3::simd::HWY_NAMESPACE {

void span_row_lanes(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& c,
                    const std::uint32_t* texels, std::uint32_t* words, int x0, int y, std::size_t n) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const rgba_v cf = flat(c);
  const V iota = hn::Iota(d, 0), yv = set(y);
  const auto* t = reinterpret_cast<const std::int32_t*>(texels);
  auto* row = reinterpret_cast<std::int32_t*>(words);
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes) {
    const V x = hn::Add(set(x0 + static_cast<std::int32_t>(k)), iota);
    hn::StoreU(pixel_pipeline(regs, o, hn::LoadU(d, t + k), cf, hn::LoadU(d, row + k), x, yv), d, row + k);
  }
  if (k == n) return;
  const V x = hn::Add(set(x0 + static_cast<std::int32_t>(k)), iota);
  alignas(64) std::int32_t tex[HWY_MAX_BYTES / 4] = {};
  for (std::size_t j = 0; j < n - k; ++j) tex[j] = t[k + j];
  part_vector(row + k, n - k, [&](V dst) { return pixel_pipeline(regs, o, hn::Load(d, tex), cf, dst, x, yv); });
}

void span_channel_row_lanes(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& c,
                            const std::uint32_t* src, unsigned channel, const std::uint32_t* clut, std::uint32_t* words,
                            int x0, int y, std::size_t n) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const rgba_v cf = flat(c);
  const V iota = hn::Iota(d, 0), yv = set(y);
  const auto* s = reinterpret_cast<const std::int32_t*>(src);
  const auto* table = reinterpret_cast<const std::int32_t*>(clut);
  auto* row = reinterpret_cast<std::int32_t*>(words);
  const int shift = static_cast<int>(8 * channel);
  auto texel = [&](V word) { return hn::GatherIndex(d, table, hn::And(hn::ShiftRightSame(word, shift), set(0xFF))); };
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes) {
    const V x = hn::Add(set(x0 + static_cast<std::int32_t>(k)), iota);
    const V t = texel(hn::LoadU(d, s + k));  // before the store: s may be row
    hn::StoreU(pixel_pipeline(regs, o, t, cf, hn::LoadU(d, row + k), x, yv), d, row + k);
  }
  if (k == n) return;
  const V x = hn::Add(set(x0 + static_cast<std::int32_t>(k)), iota);
  alignas(64) std::int32_t part[HWY_MAX_BYTES / 4] = {};
  for (std::size_t j = 0; j < n - k; ++j) part[j] = s[k + j];
  const V t = texel(hn::Load(d, part));
  part_vector(row + k, n - k, [&](V dst) { return pixel_pipeline(regs, o, t, cf, dst, x, yv); });
}

// The texels and old words are looked up with scalar loads into a chunk and the new words stored
// the same way: lane gathers and scatters of them were slower on the AMD EPYC (AVX-512) of 2026-12-07.
void span_fetched_lanes(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& c,
                        std::uint32_t* memory, std::uint32_t read_base, const std::uint32_t* read,
                        const std::uint32_t* clut, std::uint32_t word_base, const std::uint32_t* word, int x0, int y0,
                        const std::int32_t* x, const std::int32_t* y, std::size_t n) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const rgba_v cf = flat(c);
  std::uint32_t* page = memory + word_base;
  constexpr std::size_t chunk = 256;
  alignas(64) std::int32_t texel[chunk], old[chunk];
  for (std::size_t first = 0; first < n; first += chunk) {
    const std::size_t m = std::min(chunk, n - first);
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t b = read_base + read[first + k];
      texel[k] = static_cast<std::int32_t>(clut[memory_byte(memory, b)]);
      old[k] = static_cast<std::int32_t>(page[word[first + k]]);
    }
    const std::size_t padded = (m + lanes - 1) / lanes * lanes;
    for (std::size_t k = m; k < padded; ++k) texel[k] = old[k] = 0;
    for (std::size_t k = 0; k < padded; k += lanes) {
      V px, py;  // the last part vector's through a copy (the positions are read up to n)
      if (k + lanes <= m) {
        px = hn::LoadU(d, x + first + k), py = hn::LoadU(d, y + first + k);
      } else {
        alignas(64) std::int32_t cx[HWY_MAX_BYTES / 4] = {}, cy[HWY_MAX_BYTES / 4] = {};
        for (std::size_t j = 0; k + j < m; ++j) cx[j] = x[first + k + j], cy[j] = y[first + k + j];
        px = hn::Load(d, cx), py = hn::Load(d, cy);
      }
      px = hn::Add(px, set(x0)), py = hn::Add(py, set(y0));
      hn::Store(pixel_pipeline(regs, o, hn::Load(d, texel + k), cf, hn::Load(d, old + k), px, py), d, old + k);
    }
    for (std::size_t k = 0; k < m; ++k) page[word[first + k]] = static_cast<std::uint32_t>(old[k]);
  }
}

}  // namespace gsdot3::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace gsdot3::simd {

HWY_EXPORT(span_row_lanes);
HWY_EXPORT(span_channel_row_lanes);
HWY_EXPORT(span_fetched_lanes);

void span_row(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& cf,
              const std::uint32_t* texels, std::uint32_t* words, int x0, int y, std::size_t n) {
  HWY_DYNAMIC_DISPATCH(span_row_lanes)(regs, o, cf, texels, words, x0, y, n);
}

void span_channel_row(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& cf,
                      const std::uint32_t* src, unsigned channel, const std::uint32_t* clut, std::uint32_t* words,
                      int x0, int y, std::size_t n) {
  HWY_DYNAMIC_DISPATCH(span_channel_row_lanes)(regs, o, cf, src, channel, clut, words, x0, y, n);
}

void span_fetched(const gs::gs_registers& regs, const gs::model_options& o, const gs::fragment_colour& cf,
                  std::uint32_t* memory, std::uint32_t read_base, const std::uint32_t* read, const std::uint32_t* clut,
                  std::uint32_t word_base, const std::uint32_t* word, int x0, int y0, const std::int32_t* x,
                  const std::int32_t* y, std::size_t n) {
  HWY_DYNAMIC_DISPATCH(span_fetched_lanes)
  (regs, o, cf, memory, read_base, read, clut, word_base, word, x0, y0, x, y, n);
}

}  // namespace gsdot3::simd
#endif  // HWY_ONCE
