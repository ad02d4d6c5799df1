// gs_memory/clut_load.hpp — loading the CLUT buffer from local memory (TEX0.CBP, CPSM, CSM, CSA, CLD,
// and TEXCLUT for CSM2).
//
// GS User's Manual (TEX0_1, "CLUT buffer"): when TEX0 is written with an indexed PSM (PSMT8/8H: 256
// entries; PSMT4/4HL/4HH: 16), CLD decides whether the palette at CBP is copied into the CLUT buffer:
//   0 no load   1 load   2 load, CBP0 := CBP   3 load, CBP1 := CBP
//   4 load if CBP != CBP0, then CBP0 := CBP   5 load if CBP != CBP1, then CBP1 := CBP   6, 7 reserved
// (PCSX2 `pcsx2/GS/GSClut.cpp` `GSClut::WriteTest` implements the same table, and like the model
// leaves CBP0/CBP1 alone for a non-indexed PSM; it treats CLD 6 and 7 as "no load" because games
// write them — the model keeps the manual's "reserved" and rejects them, as registers.hpp does).
// The buffer holds 512 16-bit halves; a 32-bit entry i is halves i (bits 0-15) and 256 + i (bits
// 16-31) — PCSX2 `GSClut::WriteCLUT32_CSM2` stores `clut[i] = c & 0xffff`, `clut[i + 256] = c >> 16`
// — so the model's clut_buffer (256 32-bit entries) is that storage, clut_half reads one half.
// CSM1 (TEX0.CSM = 0), the image at CBP with BW = 1 in CPSM (PCSX2 `WriteCLUT32_I8_CSM1` /
// `WriteCLUT16_I8_CSM1` read `BlockPtr32` / `BlockPtr16(0, 0, CBP, 1)`):
//   PSMCT32, 256 entries: 16×16, CSM1's 8×2 entry order (gs_arith/clut.hpp load_csm1_t8); 16
//   entries: 8×2 in raster order at entry 16·CSA (load_csm1_t4).
//   PSMCT16/16S: the same 16×16 (entry i at csm1_position(i)) or 8×2 image in 16-bit pixels, into
//   halves 16·CSA + i (CSA 0..31, wrapping at 512: PCSX2 `m_clut + (TEX0.CSA << 4)` with its
//   mirrored second kilobyte). Confidence medium-high (PCSX2 and the manual's figure; no recording).
// CSM2 (TEX0.CSM = 1): the palette is one row of the buffer (CBP, TEXCLUT.CBW, CPSM): entry i is
//   pixel (16·COU + i, COV) (PCSX2 `WriteCLUT32_CSM2` / `WriteCLUT16_CSM2` / `WriteCLUT16S_CSM2`:
//   `paMulti(COU << 4, COV)` stepped by i), loaded from entry (32-bit) or half (16-bit) 0: CSA is
//   ignored, as the old GSdx `GSLocalMemory::setupCLUT` does (`m_clut[i] = rt((COU << 4) + i, COV)`);
//   PCSX2 today offsets CSM2 loads by CSA as well. Confidence medium (the emulators disagree on CSA).
// Reserved CLD values throw gs::register_error as gs_arith/registers.hpp's decode does.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "gs_arith/clut.hpp"
#include "gs_arith/registers.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"

namespace gs::mem {

struct clut_state {
  clut_buffer buffer{};
  fixed::uint<14> CBP0{}, CBP1{};
  friend bool operator==(const clut_state&, const clut_state&) = default;
};

constexpr bool is_indexed(psm p) noexcept { return value_bits(p) <= 8; }

// Half j (0..511) of the CLUT buffer, and writing it.
constexpr std::uint16_t clut_half(const clut_buffer& b, std::uint32_t j) noexcept {
  const std::uint32_t w = b[j % 256].to_u32();
  return static_cast<std::uint16_t>(j % 512 < 256 ? w : w >> 16);
}
constexpr void set_clut_half(clut_buffer& b, std::uint32_t j, std::uint16_t h) noexcept {
  const std::uint32_t w = b[j % 256].to_u32();
  b[j % 256] = rgba8::from_u32(j % 512 < 256 ? (w & 0xFFFF0000u) | h : (w & 0xFFFFu) | std::uint32_t{h} << 16);
}

// The CLUT state after TEX0 = t is written (TEXCLUT = tc, read by CSM2).
inline clut_state load_clut(const local_memory& m, const tex0_reg& t, clut_state s, const texclut_reg& tc = {}) {
  const unsigned cld = static_cast<unsigned>(t.CLD.value());
  if (cld > 5) throw register_error("TEX0_1.CLD = " + std::to_string(cld) + ": reserved (0..5)");
  if (!is_indexed(t.PSM)) return s;
  bool load = cld != 0;
  if (cld == 4) load = t.CBP != s.CBP0;
  if (cld == 5) load = t.CBP != s.CBP1;
  if (cld == 2 || (cld == 4 && load)) s.CBP0 = t.CBP;
  if (cld == 3 || (cld == 5 && load)) s.CBP1 = t.CBP;
  if (!load) return s;
  const psm cpsm = t.CPSM == clut_psm::PSMCT32   ? psm::PSMCT32
                   : t.CPSM == clut_psm::PSMCT16 ? psm::PSMCT16
                                                 : psm::PSMCT16S;
  const bool wide = cpsm == psm::PSMCT32;
  const std::uint32_t n = value_bits(t.PSM) == 8 ? 256 : 16;
  if (t.CSM) {  // CSM2: one row at (16·COU, COV), from entry / half 0
    const buffer row{t.CBP, tc.CBW, cpsm};
    const auto x0 = static_cast<std::uint32_t>(tc.COU.value()) * 16, y = static_cast<std::uint32_t>(tc.COV.value());
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t v = m.read_pixel(row, (x0 + i) % 2048, y);
      if (wide)
        s.buffer[i] = rgba8::from_u32(v);
      else
        set_clut_half(s.buffer, i, static_cast<std::uint16_t>(v));
    }
    return s;
  }
  const buffer image{t.CBP, fixed::uint<6>::from_wrapped(1), cpsm};
  if (wide && n == 256) {
    std::array<rgba8, 256> entries{};
    for (std::uint32_t y = 0; y < 16; ++y)
      for (std::uint32_t x = 0; x < 16; ++x) entries[y * 16 + x] = rgba8::from_u32(m.read_pixel(image, x, y));
    s.buffer = load_csm1_t8(entries);
  } else if (wide) {
    std::array<rgba8, 16> entries{};
    for (std::uint32_t y = 0; y < 2; ++y)
      for (std::uint32_t x = 0; x < 8; ++x) entries[y * 8 + x] = rgba8::from_u32(m.read_pixel(image, x, y));
    s.buffer = load_csm1_t4(s.buffer, entries, t.CSA);
  } else {  // 16-bit: entry i at csm1_position(i) of the 16×16 image, or raster order in the 8×2 one
    const std::uint32_t base = static_cast<std::uint32_t>(t.CSA.value()) * 16, w = n == 256 ? 16 : 8;
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t p = n == 256 ? csm1_position(u8::from_wrapped(i)) : i;
      set_clut_half(s.buffer, base + i, static_cast<std::uint16_t>(m.read_pixel(image, p % w, p / w)));
    }
  }
  return s;
}

}  // namespace gs::mem
