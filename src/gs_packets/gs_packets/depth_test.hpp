// gs_packets/depth_test.hpp — the depth test the packet interpreter draws with (TEST.ZTE / ZTST,
// ZBUF.PSM / ZMSK). The interpreter's own small unit: no gs_arith depth-test unit was in main when this
// was written (engineer i14a's gs_arith/depth_test.hpp, if merged, should replace it).
//
// GS User's Manual (TEST_1, ZBUF_1): ZTST NEVER / ALWAYS / GEQUAL / GREATER compares the fragment's Z
// with the buffer's (larger is nearer); ZMSK = 1 keeps the Z buffer unwritten. ZBUF.PSM is PSMZ32 (0),
// PSMZ24 (1), PSMZ16 (2) or PSMZ16S (0xA) — the frame-format codes without the 0x30 bit.
// Model choices (no recording decides them; confidence low):
// - a fragment's Z is clamped to the largest value the Z format holds (0xFFFFFF, 0xFFFF) before the
//   test and the write;
// - ZTE = 0 (which the manual does not describe as a working mode) draws without a test and without
//   a Z write.
#pragma once

#include <cstdint>

#include "gs_arith/alpha_test.hpp"

namespace gs::packets {

constexpr std::uint32_t z_max(unsigned z_bits) noexcept {
  return z_bits >= 32 ? 0xFFFFFFFFu : (std::uint32_t{1} << z_bits) - 1;
}

// Does a fragment with depth z pass against the buffer's z_buffer?
constexpr bool depth_test(bool ZTE, ztst ZTST, std::uint32_t z, std::uint32_t z_buffer) noexcept {
  if (!ZTE) return true;
  switch (ZTST) {
    case ztst::NEVER: return false;
    case ztst::ALWAYS: return true;
    case ztst::GEQUAL: return z >= z_buffer;
    case ztst::GREATER: return z > z_buffer;
  }
  return false;
}

// Whether the passing fragment writes Z: the test is on, ZMSK = 0, and the alpha test left Z enabled.
constexpr bool depth_write(bool ZTE, bool ZMSK, bool alpha_test_z) noexcept { return ZTE && !ZMSK && alpha_test_z; }

}  // namespace gs::packets
