// gs_memory/texture_wrap.hpp — CLAMP_1's texture wrap modes: an integer texel coordinate to the texel
// that is fetched, per axis (WMS for u with TW, MINU, MAXU; WMT for v with TH, MINV, MAXV).
//
// GS User's Manual (CLAMP_1): REPEAT wraps at the texture size, CLAMP clamps to it, REGION_CLAMP
// clamps to [MIN, MAX], REGION_REPEAT fetches (coord & MSK) | FIX with MSK = MIN and FIX = MAX.
// PCSX2's software renderer (`pcsx2/GS/Renderers/SW/GSRendererSW.cpp`, `GetScanlineGlobalData`, the
// `switch (context->CLAMP.WMS)`) sets up exactly this, and additionally limits REGION_CLAMP's bounds
// to size - 1 and REGION_REPEAT's MSK and FIX to size - 1 bits (`MINU & (tw - 1)`); the model follows
// it. Confidence: high for the four modes with MIN/MAX inside the texture (manual + PCSX2), medium
// for the size limit (PCSX2 only), low for REGION_CLAMP with MIN > MAX (here: MAX wins).
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_memory/memory_registers.hpp"

namespace gs::mem {

constexpr std::uint32_t wrap_texel(wrap_mode wm, std::int32_t coord, fixed::u4 size_log2, fixed::uint<10> min,
                                   fixed::uint<10> max) noexcept {
  const std::int32_t last = (std::int32_t{1} << size_log2.value()) - 1;
  const std::int32_t lo = min.value() < last ? min.value() : last;
  const std::int32_t hi = max.value() < last ? max.value() : last;
  auto clamp = [](std::int32_t c, std::int32_t a, std::int32_t b) { return c < a ? a : (c > b ? b : c); };
  switch (wm) {
    case wrap_mode::REPEAT: return static_cast<std::uint32_t>(coord & last);
    case wrap_mode::CLAMP: return static_cast<std::uint32_t>(clamp(coord, 0, last));
    case wrap_mode::REGION_CLAMP: return static_cast<std::uint32_t>(lo > hi ? hi : clamp(coord, lo, hi));
    case wrap_mode::REGION_REPEAT:
      return static_cast<std::uint32_t>((coord & (min.value() & last)) | (max.value() & last));
  }
  return 0;
}

struct texel_coord {
  std::uint32_t u, v;
  friend constexpr bool operator==(const texel_coord&, const texel_coord&) = default;
};

// Both axes of CLAMP_1 for a texture of 2^TW × 2^TH.
constexpr texel_coord wrap(const clamp_reg& c, fixed::u4 TW, fixed::u4 TH, std::int32_t u, std::int32_t v) noexcept {
  return {wrap_texel(c.WMS, u, TW, c.MINU, c.MAXU), wrap_texel(c.WMT, v, TH, c.MINV, c.MAXV)};
}

}  // namespace gs::mem
