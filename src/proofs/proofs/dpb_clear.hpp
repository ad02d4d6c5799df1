// proofs/dpb_clear.hpp — section 3.4's Z-buffer clear of the DPB, modelled over one DPB page.
//
// Step 2.6 (the ILP pass) reads the DPB page as PSMT8 through gs_memory's channel-fetch sprites
// (channel R: 128 tiles of 8×2, row-major, each drawn in raster order) and adds ILP[R] into the LAB.
// With the trick, ZBUF points at the DPB (ZBUF.PSM = PSMZ24 or PSMZ32), every fragment writes Z =
// 0x00808080 with ZTST = ALWAYS, so the pass also clears the DPB for the next light:
//   z_trick:        the sprites' XYZ in the Z layout: the fragment that reads DPB pixel P is drawn at
//                   the frame pixel Q = zsigma(P) whose PSMZ address is P's PSMCT32 address (found
//                   from gs_memory's two address functions); FRAME = LAB in PSMCT32.
//   z_trick_psmz32: the sprites at their own XYZ (Q = P); FRAME = LAB in PSMZ32.
//   explicit_clear: no Z write (the DPB is cleared by its own pass at 2.1).
// The texel fetches go through gs_memory's texture_page_buffer under the model option
// gs::texture_buffer. The DPB is page 0 (FBW 1), the LAB page 1; into the LAB each fragment writes
// the word (P + 1) << 8 | fetched R byte, so that the LAB records where each contribution went.
#pragma once

#include <array>
#include <cstdint>

#include "gs_arith/options.hpp"
#include "gs_memory/format.hpp"

namespace gsdot3::proofs {

enum class dpb_clear { explicit_clear, z_trick, z_trick_psmz32 };
const char* name(dpb_clear v) noexcept;

inline constexpr int page_pixels = 64 * 32;
using page_words = std::array<std::uint32_t, page_pixels>;  // PSMCT32 pixel (x, y) at y·64 + x

struct ilp_pass {
  page_words dpb_after{};                           // the DPB page after the pass (PSMCT32 pixel order)
  page_words lab{};                                 // the LAB page read as PSMCT32 (0 = no contribution)
  std::array<std::uint8_t, page_pixels> fetched{};  // per DPB pixel P: the R byte the ILP read for it
};

ilp_pass run_ilp_pass(const page_words& dpb_before, dpb_clear variant, gs::mem::psm zbuf_psm, gs::texture_buffer tb);

// zsigma(P): the frame pixel whose PSMZ32/PSMZ24 address is PSMCT32 pixel P's (index y·64 + x).
int zsigma(int p);

}  // namespace gsdot3::proofs
