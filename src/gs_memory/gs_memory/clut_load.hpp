// gs_memory/clut_load.hpp — loading the CLUT buffer from local memory (TEX0.CBP, CPSM, CSM, CSA, CLD).
//
// GS User's Manual (TEX0_1, "CLUT buffer"): when TEX0 is written with an indexed PSM (PSMT8/8H: 256
// entries; PSMT4/4HL/4HH: 16), CLD decides whether the palette at CBP is copied into the CLUT buffer:
//   0 no load   1 load   2 load, CBP0 := CBP   3 load, CBP1 := CBP
//   4 load if CBP != CBP0, then CBP0 := CBP   5 load if CBP != CBP1, then CBP1 := CBP   6, 7 reserved
// (PCSX2 `pcsx2/GS/GSClut.cpp` `GSClut::WriteTest` implements the same table, and like the model
// leaves CBP0/CBP1 alone for a non-indexed PSM; it treats CLD 6 and 7 as "no load" because games
// write them — the model keeps the manual's "reserved" and rejects them, as registers.hpp does).
// The 256-entry image is read as PCSX2 `WriteCLUT32_I8_CSM1` reads it: `BlockPtr32(0, 0, CBP, 1)`.
// With CSM1 and CPSM = PSMCT32 the palette is a PSMCT32 image at CBP: 16×16 for 256 entries (in the
// first 2×2 blocks of the page, CSM1's 8×2 entry order: gs_arith/clut.hpp `load_csm1_t8`), 8×2 for 16
// entries (raster = index order, at entry 16·CSA: `load_csm1_t4`).
// Not modelled (the methods use neither): PSMCT16/16S CLUTs and CSM2; both throw std::invalid_argument.
// Reserved CLD values throw gs::register_error as gs_arith/registers.hpp's decode does.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "gs_arith/clut.hpp"
#include "gs_arith/registers.hpp"
#include "gs_memory/local_memory.hpp"

namespace gs::mem {

struct clut_state {
  clut_buffer buffer{};
  fixed::uint<14> CBP0{}, CBP1{};
  friend bool operator==(const clut_state&, const clut_state&) = default;
};

constexpr bool is_indexed(psm p) noexcept { return value_bits(p) <= 8; }

// The CLUT state after TEX0 = t is written.
inline clut_state load_clut(const local_memory& m, const tex0_reg& t, clut_state s) {
  const unsigned cld = static_cast<unsigned>(t.CLD.value());
  if (cld > 5) throw register_error("TEX0_1.CLD = " + std::to_string(cld) + ": reserved (0..5)");
  if (!is_indexed(t.PSM)) return s;
  bool load = cld != 0;
  if (cld == 4) load = t.CBP != s.CBP0;
  if (cld == 5) load = t.CBP != s.CBP1;
  if (cld == 2 || (cld == 4 && load)) s.CBP0 = t.CBP;
  if (cld == 3 || (cld == 5 && load)) s.CBP1 = t.CBP;
  if (!load) return s;
  if (t.CPSM != clut_psm::PSMCT32) throw std::invalid_argument("CLUT load: only CPSM = PSMCT32 is modelled");
  if (t.CSM) throw std::invalid_argument("CLUT load: only CSM1 is modelled");
  const buffer image{t.CBP, fixed::uint<6>::from_wrapped(1), psm::PSMCT32};
  if (value_bits(t.PSM) == 8) {
    std::array<rgba8, 256> entries{};
    for (std::uint32_t y = 0; y < 16; ++y)
      for (std::uint32_t x = 0; x < 16; ++x) entries[y * 16 + x] = rgba8::from_u32(m.read_pixel(image, x, y));
    s.buffer = load_csm1_t8(entries);
  } else {
    std::array<rgba8, 16> entries{};
    for (std::uint32_t y = 0; y < 2; ++y)
      for (std::uint32_t x = 0; x < 8; ++x) entries[y * 8 + x] = rgba8::from_u32(m.read_pixel(image, x, y));
    s.buffer = load_csm1_t4(s.buffer, entries, t.CSA);
  }
  return s;
}

}  // namespace gs::mem
