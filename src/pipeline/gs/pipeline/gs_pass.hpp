// pipeline/gs_pass.hpp — one GS drawing pass: the register state, the texture it samples, and the
// per-pixel chain, all through the gs_arith model (register level):
//   texture:  gs::sample (TEX1 nearest / bilinear lerp16_4) of gs::clut_t8 / clut_t4 look-ups (PSMT8,
//             PSMT8H, PSMT4)
//             or of 32-bit texels (PSMCT32/24)
//   colour:   gs::gouraud_at (PRIM.IIP = 1, 8.7)  or  gs::fragment_colour::flat (sprites, RGBAQ)
//   pixel:    gs::pixel_pipeline (TFX/TCC, alpha test, blend, dither, COLCLAMP, FBA, FBMSK write)
// The methods leave the alpha test, PABE, FBA and dither off (PSMCT32 targets). The depth test is
// ZTST = GEQUAL (larger Z is nearer), with ZMSK set in every pass after the first (band_renderer.hpp,
// through gs::depth_test).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "gs_arith/bilinear.hpp"
#include "gs_arith/clut.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "gs_methods/pass_registers.hpp"
#include "gs_memory/fast_address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_simd/span_draw.hpp"

namespace gsdot3::pipeline {

using gs_methods::pass_regs;  // gs_methods/pass_registers.hpp

// One pixel: the new frame-buffer word. Always inlined and flattened, so that with the pass's
// registers as a compile-time constant the compiler folds gs::pixel_pipeline down to that pass
// (g++ also does it through the callers' flatten; clang needs it here).
[[gnu::always_inline, gnu::flatten]] inline std::uint32_t gs_pixel(const gs::gs_registers& r, gs::rgba8 texel,
                                                                   const gs::fragment_colour& cf, std::uint32_t old,
                                                                   int x, int y, const gs::model_options& o) noexcept {
  return gs::pixel_pipeline(r, {cf, texel, old, static_cast<unsigned>(x), static_cast<unsigned>(y)}, o).out;
}

// A texture as TEX0/TEX1/CLAMP_1 describe it: PSMT8 or PSMT4 indices through a CLUT (CSA = 0, so a
// 4-bit index i is entry i as the 8-bit index i is), or 32-bit texels;
// power-of-two sizes; CLAMP_1.WMS/WMT = REPEAT or CLAMP; TEX1.MMAG = NEAREST or LINEAR.
struct texture_ref {
  int width = 0, height = 0;
  const std::uint8_t* index = nullptr;  // PSMT8 / PSMT4 indices, one a byte (with clut)
  const gs::clut_buffer* clut = nullptr;
  const std::uint32_t* texels = nullptr;  // PSMCT32 / PSMCT24 (alpha as stored)
  bool clamp = false;
  gs::bilinear_mode filter = gs::bilinear_mode::nearest;
  // The memory path: the texels read from the modelled local memory at `at` (TBP0, TBW, PSM)
  // instead of the arrays above (index / texels then only give the kind: CLUT or 32-bit), through
  // the texture's tabulated addresses (gs_memory/fast_address.hpp: read = read_pixel on every texel).
  const gs::mem::local_memory* memory = nullptr;
  gs::mem::buffer at{};
  const gs::mem::texel_addresses* texel_at = nullptr;

  gs::rgba8 fetch(std::int32_t u, std::int32_t v) const noexcept {
    if (clamp) {
      u = u < 0 ? 0 : u >= width ? width - 1 : u;
      v = v < 0 ? 0 : v >= height ? height - 1 : v;
    } else {
      u &= width - 1;
      v &= height - 1;
    }
    if (memory != nullptr) {
      const std::uint32_t t =
          texel_at->read(*memory, static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v), at.BP.value());
      if (clut == nullptr) return gs::rgba8::from_u32(t);
      return at.PSM == gs::mem::psm::PSMT4 ? gs::clut_t4(*clut, gs::u4::from_wrapped(t), {})
                                           : gs::clut_t8(*clut, gs::u8::from_wrapped(t));
    }
    const std::size_t i = static_cast<std::size_t>(v) * static_cast<std::size_t>(width) + static_cast<std::size_t>(u);
    if (index != nullptr) return gs::clut_t8(*clut, gs::u8::from_wrapped(index[i]));
    return gs::rgba8::from_u32(texels[i]);
  }
  // u16, v16: texel coordinates in 12.4 (UV with PRIM.FST = 1).
  gs::rgba8 sample(std::int32_t u16, std::int32_t v16) const noexcept {
    return gs::sample([this](std::int32_t u, std::int32_t v) { return fetch(u, v); }, u16, v16, filter);
  }
};

// A CLUT's 256 entries as 32-bit words (rgba8::to_u32): entry i is what clut_t8 looks up for index i
// with CSA = 0, the form the resolved fetches read.
inline std::array<std::uint32_t, 256> clut_words(const gs::clut_buffer& clut) noexcept {
  std::array<std::uint32_t, 256> w{};
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = clut[i].to_u32();
  return w;
}

// The value path's fetch resolved once per draw: TEX1 nearest, from the host arrays (no local
// memory), REPEAT or CLAMP, CLUT indices (the CLUT's entries converted to 32-bit words here) or 32-bit
// texels. texel(u16, v16) is texture_ref::sample(u16, v16).to_u32() for every u16, v16 (its fast
// path: nearest's footprint is floor(u16 / 16), an arithmetic shift; REPEAT masks a power-of-two side;
// clut_t8 with CSA = 0 is entry `index`), checked against sample over whole coordinate ranges
// (tests/pipeline/resolved_fetch_test.cpp).
class nearest_host_fetch {
 public:
  static bool applies(const texture_ref& t) noexcept {
    return t.memory == nullptr && t.filter == gs::bilinear_mode::nearest;
  }
  explicit nearest_host_fetch(const texture_ref& t) noexcept
      : index_(t.index),
        texels_(t.texels),
        wmask_(t.width - 1),
        hmask_(t.height - 1),
        shift_(std::countr_zero(static_cast<unsigned>(t.width))),
        clamp_(t.clamp) {
    if (index_ != nullptr) words_ = clut_words(*t.clut);
  }
  std::uint32_t texel(std::int32_t u16, std::int32_t v16) const noexcept {
    std::int32_t u = u16 >> 4, v = v16 >> 4;
    if (clamp_) {
      u = u < 0 ? 0 : u > wmask_ ? wmask_ : u;
      v = v < 0 ? 0 : v > hmask_ ? hmask_ : v;
    } else {
      u &= wmask_, v &= hmask_;
    }
    const std::size_t i = static_cast<std::size_t>(v) << shift_ | static_cast<std::size_t>(u);
    return index_ != nullptr ? words_[index_[i]] : texels_[i];
  }
  // The same fetch for the span engine's lanes (gs_simd/span_draw.hpp), valid while this lives.
  simd::nearest_texture lanes() const noexcept {
    return {.index = index_,
            .words = index_ != nullptr ? words_.data() : nullptr,
            .texels = texels_,
            .wmask = wmask_,
            .hmask = hmask_,
            .shift = shift_,
            .clamp = clamp_};
  }

 private:
  const std::uint8_t* index_;
  const std::uint32_t* texels_;
  std::int32_t wmask_, hmask_;
  int shift_;
  bool clamp_;
  std::array<std::uint32_t, 256> words_{};
};

// The memory path's fetch for the span engine: TEX1 nearest from the modelled local memory through
// the texture's tabulated addresses (texel_addresses), REPEAT or CLAMP, PSMT8 / PSMT8H indices through
// the CLUT (its entries as words) or 32-bit texels: texture_ref::fetch's memory branch, in lanes
// (tests/gs_simd/span_draw_test.cpp checks the lanes against texel_addresses::read). PSMT4 and
// bilinear filtering stay with texture_ref::sample.
class nearest_memory_fetch {
 public:
  static bool applies(const texture_ref& t) noexcept {
    if (t.memory == nullptr || t.texel_at == nullptr || t.filter != gs::bilinear_mode::nearest) return false;
    if (t.texel_at->bits() != (t.clut != nullptr ? 8u : 32u)) return false;
    return std::has_single_bit(static_cast<unsigned>(t.width)) &&
           std::has_single_bit(static_cast<unsigned>(t.height)) &&
           t.texel_at->width() == static_cast<std::uint32_t>(t.width) && t.width * t.height >= 4;
  }
  explicit nearest_memory_fetch(const texture_ref& t) noexcept : t_(t) {
    if (t.clut != nullptr) words_ = clut_words(*t.clut);
  }
  // Valid while this lives.
  simd::nearest_texture lanes() const noexcept {
    simd::nearest_texture l;
    l.words = t_.clut != nullptr ? words_.data() : nullptr;
    l.memory = t_.memory->words();
    l.address = t_.texel_at->table();
    l.base = t_.at.BP.value() * gs::mem::block_bytes, l.mask = gs::mem::memory_bytes - 1;
    l.wmask = t_.width - 1, l.hmask = t_.height - 1, l.shift = std::countr_zero(static_cast<unsigned>(t_.width));
    l.clamp = t_.clamp;
    return l;
  }

 private:
  const texture_ref& t_;
  std::array<std::uint32_t, 256> words_{};
};

}  // namespace gsdot3::pipeline
