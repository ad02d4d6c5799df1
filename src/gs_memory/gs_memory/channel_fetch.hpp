// gs_memory/channel_fetch.hpp — the sprites that fetch one byte channel of every pixel of a PSMCT32
// page into place (section 3.3's "real-time swizzling"; Breugelmans' channel fetch).
//
// The page is read as a PSMT8 texture with the same base (TEX0.TBP0 = the page's block address) and
// TBW = 2·FBW, TW = 7, TH = 6 (one 128×64 PSMT8 page = the 64×32 PSMCT32 page's 8 KiB). Derivation
// from the memory model (gs-memory-facts' mapping, which tests/gs_memory checks against both address
// formulations on every texel): byte c of pixel (x, y) — c = 0 R, 1 G, 2 B, 3 A; g = 1 for G and A,
// b = 1 for B and A — is texel
//     v = 4·(y >> 1) + 2·g + (y & 1),   u = 16·(x >> 3) + 8·b + ((x & 7) ^ 4·s),   s = ((y >> 1) & 1) ^ g.
// v is linear in y over each aligned pair of rows; u is linear in x over each aligned 8 pixels
// except for the "^ 4". So one sprite per 8×2 tile, drawn 1:1 from texel (u0, v0) =
// (16·k + 4·s, 4·j + 2·g) for tile column k, tile row j, with CLAMP_1.WMS = REGION_REPEAT,
// MSK (MINU) = 0x3F7 and FIX (MAXU) = 8·b: u0 + (x & 7) runs over 16k + 4s .. 16k + 4s + 7; clearing
// bit 3 folds 16k + 8 .. 16k + 11 back onto 16k .. 16k + 3 (the "^ 4" for s = 1; for s = 0 bit 3 is
// already clear) and FIX sets bit 3 for the B and A channels. WMT = REPEAT (v stays inside the page).
// 8 × 16 = 128 sprites per page per channel; the register settings (TBP0 per page, CLAMP_1 per
// channel) are what a VU1 chain sends per page. tests/gs_memory proves, for every channel and every
// pixel of a page, that the sprite covering it fetches exactly that pixel's byte, and that every
// pixel is covered by exactly one sprite.
#pragma once

#include <array>
#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_memory/memory_registers.hpp"

namespace gs::mem {

struct fetch_sprite {
  std::uint32_t x0, y0, x1, y1;  // destination pixels [x0, x1) × [y0, y1) inside the page
  std::int32_t u0, v0;           // the texel at (x0, y0); 1:1 from there
};

struct channel_fetch {
  clamp_reg CLAMP;                          // REGION_REPEAT for u, REPEAT for v
  std::array<fetch_sprite, 128> sprites{};  // one page
};

constexpr channel_fetch channel_fetch_sprites(unsigned channel) noexcept {
  const std::uint32_t g = (channel == 1 || channel == 3) ? 1u : 0u;
  const std::uint32_t b = (channel == 2 || channel == 3) ? 1u : 0u;
  channel_fetch f{};
  f.CLAMP = clamp_reg{wrap_mode::REGION_REPEAT,
                      wrap_mode::REPEAT,
                      fixed::uint<10>::from_wrapped(0x3F7),
                      fixed::uint<10>::from_wrapped(8 * b),
                      fixed::uint<10>{},
                      fixed::uint<10>{}};
  for (std::uint32_t j = 0; j < 16; ++j)
    for (std::uint32_t k = 0; k < 8; ++k) {
      const std::uint32_t s = (j & 1u) ^ g;
      f.sprites[j * 8 + k] = {8 * k,
                              2 * j,
                              8 * k + 8,
                              2 * j + 2,
                              static_cast<std::int32_t>(16 * k + 4 * s),
                              static_cast<std::int32_t>(4 * j + 2 * g)};
    }
  return f;
}

}  // namespace gs::mem
