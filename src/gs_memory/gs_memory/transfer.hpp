// gs_memory/transfer.hpp — host -> local transfers (BITBLTBUF, TRXPOS, TRXREG, TRXDIR = 0).
//
// GS User's Manual section 4 (image transmission): the host sends RRW × RRH pixels in raster order,
// written to the destination buffer (DBP, DBW, DPSM) from (DSAX, DSAY). Pixels are packed as the
// format stores them: 32 bits (PSMCT32/Z32), 24 bits in 3 bytes (PSMCT24/Z24), 16 bits, 8 bits
// (PSMT8, PSMT8H), 4 bits two per byte with the first pixel in the low nibble (PSMT4, PSMT4HL/HH);
// PCSX2 `pcsx2/GS/GSLocalMemory.cpp` `WriteImage24`/`WriteImage4`/`WriteImage8H` read the host data
// the same way. TRXPOS.DIR only orders local -> local copies. Confidence: high.
// Not modelled: local -> host and local -> local (the methods only upload), and a rectangle that
// crosses x = 2048 (the GS wraps coordinates there): both throw std::invalid_argument.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"

namespace gs::mem {

// Bytes the host sends for an RRW × RRH rectangle of format p.
constexpr std::uint64_t transfer_bytes(psm p, std::uint32_t rrw, std::uint32_t rrh) noexcept {
  const unsigned bits = value_bits(p);
  return (std::uint64_t{rrw} * rrh * bits + 7) / 8;
}

inline void host_to_local(local_memory& m, const bitbltbuf_reg& b, const trxpos_reg& pos, const trxreg_reg& reg,
                          const trxdir_reg& dir, std::span<const std::uint8_t> data) {
  if (dir.XDIR != xdir::host_to_local) throw std::invalid_argument("transfer: only TRXDIR.XDIR = 0 (host -> local) is modelled");
  const auto w = static_cast<std::uint32_t>(reg.RRW.value()), h = static_cast<std::uint32_t>(reg.RRH.value());
  const auto x0 = static_cast<std::uint32_t>(pos.DSAX.value()), y0 = static_cast<std::uint32_t>(pos.DSAY.value());
  if (x0 + w > 2048 || y0 + h > 2048) throw std::invalid_argument("transfer: rectangle crosses the 2048-pixel wrap");
  if (data.size() != transfer_bytes(b.DPSM, w, h))
    throw std::invalid_argument("transfer: " + std::to_string(data.size()) + " bytes for " + std::to_string(w) + "x" +
                                std::to_string(h) + " pixels, expected " + std::to_string(transfer_bytes(b.DPSM, w, h)));
  const buffer dst{b.DBP, b.DBW, b.DPSM};
  const unsigned bits = value_bits(b.DPSM);
  std::uint64_t bit = 0;  // position in the host data
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x, bit += bits) {
      std::uint32_t v = 0;
      for (unsigned k = 0; k < (bits + 7) / 8; ++k) v |= std::uint32_t{data[bit / 8 + k]} << (8 * k);
      v = bits == 4 ? (v >> (bit % 8)) & 0xFu : v;
      m.write_pixel(dst, x0 + x, y0 + y, v);
    }
}

}  // namespace gs::mem
