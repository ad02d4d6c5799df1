// pipeline/span_batch.hpp — the renderer's pixels collected into batches for the SIMD pixel pipeline
// (gs_simd/pixel_span.hpp; render_options::simd, `--scalar` turns it off). A batch holds pixels of one
// register set whose frame-buffer words are distinct: the renderer flushes it at the end of every
// triangle and every sprite (the rasteriser visits a pixel of one primitive once), so no pixel of a
// batch reads a word another pixel of the same batch writes. The old word is read when the pixel is
// added and the new one written when the batch is flushed, in the order the pixels were added.
// Pixels come one at a time (add: any frame-buffer layout) or as a run of adjacent pixels of one row
// whose words are adjacent too (add_row: the value path's row-major buffers).
#pragma once

#include <algorithm>
#include <cstdint>

#include "gs_simd/pixel_span.hpp"

namespace gsdot3::pipeline::detail {

class span_batch {
 public:
  span_batch(const gs::gs_registers& regs, const gs::model_options& o) : regs_(regs), o_(o) {}
  span_batch(const span_batch&) = delete;
  span_batch& operator=(const span_batch&) = delete;
  ~span_batch() { flush(); }

  void add(std::uint32_t& word, gs::rgba8 texel, const gs::fragment_colour& cf, int x, int y) {
    const std::size_t i = b_.n++;
    set(i, word, texel.to_u32(), cf, x, y);
    if (b_.n == simd::pixel_batch::capacity) flush();
  }
  // Pixels (x0 + k, y) for k = 0, 1, ..., whose words are words[k]: produce(put) calls put(texel, cf)
  // once per pixel in that order, the texel as its 32-bit word (rgba8::to_u32); the batch is flushed
  // whenever it fills.
  template <class Produce>
  void add_row(std::uint32_t* words, int x0, int y, Produce&& produce) {
    int k = 0;
    std::size_t n = b_.n;  // the batch's count kept local between flushes
    produce([&](std::uint32_t texel, const gs::fragment_colour& cf) {
      set(n, words[k], texel, cf, x0 + k, y);
      ++k;
      if (++n == simd::pixel_batch::capacity) b_.n = n, flush(), n = 0;
    });
    b_.n = n;
  }
  void flush() {
    if (b_.n == 0) return;
    simd::pixel_pipeline(regs_, o_, b_);
    for (std::size_t i = 0; i < b_.n; ++i) *word_[i] = b_.out[i];
    b_.n = 0;
  }

 private:
  void set(std::size_t i, std::uint32_t& word, std::uint32_t texel, const gs::fragment_colour& cf, int x, int y) {
    word_[i] = &word;
    b_.texel[i] = texel;
    b_.cf[0][i] = cf.r.value(), b_.cf[1][i] = cf.g.value(), b_.cf[2][i] = cf.b.value(), b_.cf[3][i] = cf.a.value();
    b_.dst[i] = word;
    b_.x[i] = static_cast<std::uint32_t>(x), b_.y[i] = static_cast<std::uint32_t>(y);
  }
  const gs::gs_registers& regs_;
  const gs::model_options& o_;
  simd::pixel_batch b_;
  std::uint32_t* word_[simd::pixel_batch::capacity] = {};
};

}  // namespace gsdot3::pipeline::detail
