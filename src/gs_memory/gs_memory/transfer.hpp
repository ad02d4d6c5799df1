// gs_memory/transfer.hpp — host -> local, local -> host and local -> local transfers (BITBLTBUF,
// TRXPOS, TRXREG, TRXDIR = 0, 1, 2).
//
// GS User's Manual section 4 (image transmission): the host sends RRW × RRH pixels in raster order,
// written to the destination buffer (DBP, DBW, DPSM) from (DSAX, DSAY). Pixels are packed as the
// format stores them: 32 bits (PSMCT32/Z32), 24 bits in 3 bytes (PSMCT24/Z24), 16 bits, 8 bits
// (PSMT8, PSMT8H), 4 bits two per byte with the first pixel in the low nibble (PSMT4, PSMT4HL/HH);
// PCSX2 `pcsx2/GS/GSLocalMemory.cpp` `WriteImage24`/`WriteImage4`/`WriteImage8H` read the host data
// the same way. Confidence: high.
// Local -> host (XDIR = 1): the RRW × RRH rectangle at (SSAX, SSAY) of the source buffer (SBP, SBW,
// SPSM) read back in the same raster order and packing (PCSX2 `pcsx2/GS/GSState.cpp` `GSState::Read`
// -> `GSLocalMemory::ReadImageX`). On the console the data leaves through the GIF FIFO (BUSDIR), which
// is not modelled: the function returns the bytes the host would receive.
// Local -> local (XDIR = 2): pixel by pixel, source value read with SPSM's read, written with DPSM's
// write (PSMCT24 keeps the destination's top byte), coordinates wrapping at 2048, in the order
// TRXPOS.DIR gives (manual: 0 upper left -> lower right, 1 lower left -> upper right, 2 upper right ->
// lower left, 3 lower right -> upper left; bit 0 = DIRY, bit 1 = DIRX as in PCSX2 `GSRegs.h`
// `GIFRegTRXPOS`; PCSX2 `GSState::Move` walks x and y from the far end when DIRX / DIRY are set and
// wraps with `& 2047`). The copy is modelled as strictly sequential: the GS's transfer buffer, which
// PCSX2's Move imitates for a buffer copied onto itself within one page (Gitaroo Man), is not; the
// renderer's copies never overlap. SPSM and DPSM must store the same number of bits (PCSX2 copies
// mixed formats through the generic read/write, the manual leaves them undefined): else
// std::invalid_argument. Confidence: high for the non-overlapping copy, medium for overlapping ones.
// Not modelled: a host <-> local rectangle that crosses x = 2048 (throws std::invalid_argument).
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_memory/swizzle_tables.hpp"

namespace gs::mem {

// Bytes the host sends for an RRW × RRH rectangle of format p.
constexpr std::uint64_t transfer_bytes(psm p, std::uint32_t rrw, std::uint32_t rrh) noexcept {
  const unsigned bits = value_bits(p);
  return (std::uint64_t{rrw} * rrh * bits + 7) / 8;
}

namespace detail {
// The host -> local transfer of a w × h rectangle at (x0, y0) of a buffer whose pixel is one whole unit of
// layout L (PSMCT32, PSMZ32: a 32-bit word; PSMT8: a byte), with the layout a constant: local_memory::write of
// such a location replaces exactly its unit, so each value is stored at tables::unit_address_of directly.
// tests/gs_memory/transfer_test.cpp checks it against write_pixel on random rectangles, BP and BW.
template <layout L>
void store_units(local_memory& m, std::uint32_t bp, std::uint32_t bw, std::uint32_t x0, std::uint32_t y0,
                 std::uint32_t w, std::uint32_t h, const std::uint8_t* data) {
  static_assert(unit_bits(L) == 32 || unit_bits(L) == 8);
  std::uint32_t* words = m.words();
  for (std::uint32_t y = y0; y < y0 + h; ++y)
    for (std::uint32_t x = x0; x < x0 + w; ++x) {
      const std::uint32_t unit = tables::unit_address_of<L>(bp, bw, x, y);
      if constexpr (unit_bits(L) == 32) {
        words[unit] = std::uint32_t{data[0]} | std::uint32_t{data[1]} << 8 | std::uint32_t{data[2]} << 16 |
                      std::uint32_t{data[3]} << 24;
        data += 4;
      } else {
        const unsigned shift = 8 * (unit % 4);
        words[unit / 4] = (words[unit / 4] & ~(0xFFu << shift)) | std::uint32_t{*data++} << shift;
      }
    }
}
}  // namespace detail

inline void host_to_local(local_memory& m, const bitbltbuf_reg& b, const trxpos_reg& pos, const trxreg_reg& reg,
                          const trxdir_reg& dir, std::span<const std::uint8_t> data) {
  if (dir.XDIR != xdir::host_to_local)
    throw std::invalid_argument("transfer: only TRXDIR.XDIR = 0 (host -> local) is modelled");
  const auto w = static_cast<std::uint32_t>(reg.RRW.value()), h = static_cast<std::uint32_t>(reg.RRH.value());
  const auto x0 = static_cast<std::uint32_t>(pos.DSAX.value()), y0 = static_cast<std::uint32_t>(pos.DSAY.value());
  if (x0 + w > 2048 || y0 + h > 2048) throw std::invalid_argument("transfer: rectangle crosses the 2048-pixel wrap");
  if (data.size() != transfer_bytes(b.DPSM, w, h))
    throw std::invalid_argument("transfer: " + std::to_string(data.size()) + " bytes for " + std::to_string(w) + "x" +
                                std::to_string(h) + " pixels, expected " +
                                std::to_string(transfer_bytes(b.DPSM, w, h)));
  const auto bp = static_cast<std::uint32_t>(b.DBP.value()), bw = static_cast<std::uint32_t>(b.DBW.value());
  switch (b.DPSM) {  // a pixel that is one whole unit of its layout: stored directly
    case psm::PSMCT32: return detail::store_units<layout::ct32>(m, bp, bw, x0, y0, w, h, data.data());
    case psm::PSMZ32: return detail::store_units<layout::z32>(m, bp, bw, x0, y0, w, h, data.data());
    case psm::PSMT8: return detail::store_units<layout::t8>(m, bp, bw, x0, y0, w, h, data.data());
    default: break;
  }
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

// Local -> host: the bytes the host receives for the TRXREG rectangle at (SSAX, SSAY) of the source.
inline std::vector<std::uint8_t> local_to_host(const local_memory& m, const bitbltbuf_reg& b, const trxpos_reg& pos,
                                               const trxreg_reg& reg, const trxdir_reg& dir) {
  if (dir.XDIR != xdir::local_to_host) throw std::invalid_argument("transfer: local_to_host needs TRXDIR.XDIR = 1");
  const auto w = static_cast<std::uint32_t>(reg.RRW.value()), h = static_cast<std::uint32_t>(reg.RRH.value());
  const auto x0 = static_cast<std::uint32_t>(pos.SSAX.value()), y0 = static_cast<std::uint32_t>(pos.SSAY.value());
  if (x0 + w > 2048 || y0 + h > 2048) throw std::invalid_argument("transfer: rectangle crosses the 2048-pixel wrap");
  const buffer src{b.SBP, b.SBW, b.SPSM};
  const unsigned bits = value_bits(b.SPSM);
  std::vector<std::uint8_t> data(transfer_bytes(b.SPSM, w, h), 0);
  std::uint64_t bit = 0;
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x, bit += bits) {
      const std::uint32_t v = m.read_pixel(src, x0 + x, y0 + y) << (bits == 4 ? bit % 8 : 0);
      for (unsigned k = 0; k < (bits + 7) / 8; ++k) data[bit / 8 + k] |= static_cast<std::uint8_t>(v >> (8 * k));
    }
  return data;
}

// Local -> local: the TRXREG rectangle from (SSAX, SSAY) of the source to (DSAX, DSAY) of the
// destination, in TRXPOS.DIR's order.
inline void local_to_local(local_memory& m, const bitbltbuf_reg& b, const trxpos_reg& pos, const trxreg_reg& reg,
                           const trxdir_reg& dir) {
  if (dir.XDIR != xdir::local_to_local) throw std::invalid_argument("transfer: local_to_local needs TRXDIR.XDIR = 2");
  if (value_bits(b.SPSM) != value_bits(b.DPSM))
    throw std::invalid_argument("transfer: local -> local between formats of different sizes is not modelled");
  const buffer src{b.SBP, b.SBW, b.SPSM}, dst{b.DBP, b.DBW, b.DPSM};
  const auto w = static_cast<std::uint32_t>(reg.RRW.value()), h = static_cast<std::uint32_t>(reg.RRH.value());
  const bool from_bottom = (pos.DIR.value() & 1) != 0, from_right = (pos.DIR.value() & 2) != 0;  // DIRY, DIRX
  for (std::uint32_t j = 0; j < h; ++j)
    for (std::uint32_t i = 0; i < w; ++i) {
      const std::uint32_t x = from_right ? w - 1 - i : i, y = from_bottom ? h - 1 - j : j;
      const std::uint32_t v = m.read_pixel(src, (static_cast<std::uint32_t>(pos.SSAX.value()) + x) % 2048,
                                           (static_cast<std::uint32_t>(pos.SSAY.value()) + y) % 2048);
      m.write_pixel(dst, (static_cast<std::uint32_t>(pos.DSAX.value()) + x) % 2048,
                    (static_cast<std::uint32_t>(pos.DSAY.value()) + y) % 2048, v);
    }
}

}  // namespace gs::mem
