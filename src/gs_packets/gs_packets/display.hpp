// gs_packets/display.hpp — the displayed frame: the read circuits the privileged registers select.
//
// The 8 KiB privileged block of a dump is the GS's privileged register space from 0x12000000, one
// 64-bit register per 16 bytes (GS User's Manual register map; PCSX2 `GSPrivRegSet` mirrors it):
//   PMODE 0x00, SMODE2 0x20, DISPFB1 0x70, DISPLAY1 0x80, DISPFB2 0x90, DISPLAY2 0xA0, BGCOLOR 0xE0.
// Fields: gs_regs/privileged.hpp's PMODE, DISPFB and DISPLAY tables.
// A read circuit shows the rectangle at (DBX, DBY) of its buffer, (DW + 1) / (MAGH + 1) pixels wide and
// (DH + 1) / (MAGV + 1) rows high, in buffer pixels (the magnification and the CRT timing are the
// output's, not the frame's). With both circuits on, the merge circuit (alpha blend of circuit 1 over
// circuit 2 with ALP or circuit 1's alpha, and the background colour) is not modelled: the frame is
// circuit 1's, and `unmodelled` says so. DISPFB.PSM 0, 1, 2, 0xA (PSMCT32, 24, 16, 16S) as the manual
// lists for the display.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "gs_memory/address.hpp"
#include "gs_regs/privileged.hpp"

namespace gs::packets {

struct displayed_frame {
  unsigned circuit = 1;        // 1 or 2
  mem::buffer buffer;          // DISPFB's FBP (as blocks), FBW, PSM
  std::uint32_t x = 0, y = 0;  // DBX, DBY
  std::uint32_t width = 0, height = 0;
};

struct display_state {
  std::optional<displayed_frame> frame;  // none when neither circuit is enabled
  std::string unmodelled;                // what of the display the frame leaves out, "" when nothing
};

inline std::uint64_t privileged_register(std::span<const std::uint8_t> block, std::uint32_t offset) {
  std::uint64_t v = 0;
  for (unsigned b = 0; b < 8 && offset + b < block.size(); ++b) v |= std::uint64_t{block[offset + b]} << (8 * b);
  return v;
}

inline display_state decode_display(std::span<const std::uint8_t> privileged) {
  namespace R = gs::regs;
  const std::uint64_t pmode = privileged_register(privileged, 0x00);
  const bool en1 = R::decode_as(R::PMODE::EN1, pmode) != 0, en2 = R::decode_as(R::PMODE::EN2, pmode) != 0;
  display_state s;
  if (!en1 && !en2) {
    s.unmodelled = "PMODE: both read circuits disabled (no displayed frame)";
    return s;
  }
  if (en1 && en2)
    s.unmodelled = "PMODE: both read circuits enabled; the merge circuit is not modelled (circuit 1 shown)";
  const unsigned c = en1 ? 1 : 2;
  const std::uint64_t dispfb = privileged_register(privileged, c == 1 ? 0x70 : 0x90);
  const std::uint64_t display = privileged_register(privileged, c == 1 ? 0x80 : 0xA0);
  namespace F = R::DISPFB;
  namespace D = R::DISPLAY;
  const std::uint32_t psm = R::decode_as(F::PSM, dispfb);
  if (!R::is_one_of(psm, F::PSM_valid)) {
    s.unmodelled = "DISPFB" + std::to_string(c) + ".PSM = " + std::to_string(psm) + " (not a display format)";
    return s;
  }
  displayed_frame f;
  f.circuit = c;
  f.buffer = {mem::from_page(fixed::uint<9>::from_wrapped(R::decode_as(F::FBP, dispfb))),
              fixed::uint<6>::from_wrapped(R::decode_as(F::FBW, dispfb)), static_cast<mem::psm>(psm)};
  f.x = R::decode_as(F::DBX, dispfb);
  f.y = R::decode_as(F::DBY, dispfb);
  f.width = (R::decode_as(D::DW, display) + 1) / (R::decode_as(D::MAGH, display) + 1);
  f.height = (R::decode_as(D::DH, display) + 1) / (R::decode_as(D::MAGV, display) + 1);
  s.frame = f;
  return s;
}

}  // namespace gs::packets
