// gs_packets/register_values.hpp — the values of the registers a GIF stream sets that have no typed
// encoder in gs_arith or gs_memory (XYOFFSET, SCISSOR, TEX1, PMODE, DISPFB), packed by their field
// tables (gs_regs), for every writer of a stream: the pipeline's dump writer and the probe.
#pragma once

#include <cstdint>

#include "gs_regs/drawing.hpp"
#include "gs_regs/privileged.hpp"

namespace gs::packets {

// XYOFFSET_1: the primitive coordinate offset, in 12.4 fixed point.
constexpr std::uint64_t xyoffset_value(std::uint32_t ofx, std::uint32_t ofy) {
  namespace X = gs::regs::XYOFFSET;
  return gs::regs::encode(X::OFX, ofx) | gs::regs::encode(X::OFY, ofy);
}

// SCISSOR_1 from inclusive pixel bounds (SCAX1 and SCAY1 are the last column and row drawn).
constexpr std::uint64_t scissor_value(int x0, int x1, int y0, int y1) {
  namespace S = gs::regs::SCISSOR;
  auto put = [](gs::regs::field f, int v) { return gs::regs::encode(f, static_cast<std::uint64_t>(v)); };
  return put(S::SCAX0, x0) | put(S::SCAX1, x1) | put(S::SCAY0, y0) | put(S::SCAY1, y1);
}

// TEX1_1 at the base level (MXL = L = K = 0): MMAG = MMIN = the filter (1 LINEAR, 0 NEAREST) and LCM
// (1 = LOD fixed at K; with K = 0 and Q = 1 both settings give LOD 0).
constexpr std::uint64_t tex1_value(bool linear, bool lcm) {
  namespace T = gs::regs::TEX1;
  return gs::regs::encode(T::LCM, lcm) | gs::regs::encode(T::MMAG, linear) | gs::regs::encode(T::MMIN, linear);
}

// PMODE with read circuit 1 on (EN1), CRTMD 001 (the manual's fixed value), MMOD = 1 (blend with
// ALP = 0xFF: circuit 1 opaque).
constexpr std::uint64_t pmode_circuit1() {
  namespace P = gs::regs::PMODE;
  using gs::regs::encode;
  return encode(P::EN1, 1) | encode(P::CRTMD, 1) | encode(P::MMOD, 1) | encode(P::ALP, 0xFF);
}

// DISPFB1 at FBP (in 2048-word pages), FBW (in 64-pixel units), PSMCT32, DBX = DBY = 0.
constexpr std::uint64_t dispfb_value(std::uint32_t fbp, std::uint32_t fbw) {
  return gs::regs::encode(gs::regs::DISPFB::FBP, fbp) | gs::regs::encode(gs::regs::DISPFB::FBW, fbw);
}

}  // namespace gs::packets
