// gs_arith/pixel_pipeline.hpp — one pixel through the GS units in hardware order.
//
// Order (../shared/spec/gs-alu-facts.md, "After the blend", and PCSX2 SW GSDrawScanline):
//   1. texture function TFX/TCC on (texel, fragment colour), or the fragment colour when PRIM.TME = 0
//   2. alpha test on the resulting alpha: which of RGB / A / Z are written
//   3. alpha blend when PRIM.ABE = 1, unless PABE = 1 and As < 0x80 (then Cs passes); Cd/Ad are the
//      old frame-buffer word as the blender reads it (frame_read: Ad = 0x80 on 24-bit targets)
//   4. dither (DTHE, DIMX) on the wide value   5. COLCLAMP clamp / wrap   6. FBA
//   7. pack to the frame format                8. FBMSK merge (plus what the alpha test disables)
// Not modelled: fog (PRIM.FGE), anti-aliasing (AA1), the depth and destination-alpha tests, scissor.
#pragma once

#include <cstdint>
#include <string>

#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/alpha_test.hpp"
#include "gs_arith/colclamp.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/dither.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/registers.hpp"
#include "gs_arith/texture_function.hpp"

namespace gs {

struct pixel_input {
  fragment_colour vertex;  // Cf in 8.7 (flat: fragment_colour::flat(RGBAQ); Gouraud: gouraud_at)
  rgba8 texel;             // Ct after CLUT lookup and filtering; unused when PRIM.TME = 0
  std::uint32_t dst;       // the old frame-buffer word (16-bit formats: low 16 bits)
  unsigned x, y;           // window coordinates, for the dither matrix
};

// Every stage's value, in order.
struct pixel_trace {
  rgba8 tfx_out;         // 1. source colour Cs / As
  write_enables test;    // 2.
  rgba8 cd;              // 3. destination as read (Cd, Ad)
  bool blended;          // 3. ABE and not skipped by PABE
  rgb_wide blend;        // 3. ((A − B)·C >> 7) + D, or Cs
  rgb_wide dithered;     // 4.
  rgba8 clamped;         // 5. alpha is As
  rgba8 fba;             // 6.
  std::uint32_t packed;  // 7.
  std::uint32_t keep;    // 8. keep mask: FBMSK in memory bits plus the alpha test's disabled channels
  std::uint32_t out;     // the new frame-buffer word
  friend constexpr bool operator==(const pixel_trace&, const pixel_trace&) = default;
};

constexpr pixel_trace pixel_pipeline(const gs_registers& regs, const pixel_input& in, const model_options& o) noexcept {
  pixel_trace t{};
  const frame_psm psm = regs.FRAME_1.PSM;
  t.tfx_out = regs.PRIM.TME ? texture_function(regs.TEX0_1.TFX, regs.TEX0_1.TCC, in.texel, in.vertex, o)
                            : texture_off(in.vertex);
  t.test = alpha_test(regs.TEST_1, t.tfx_out.a, psm, o);
  t.cd = frame_read(psm, in.dst);
  t.blended = regs.PRIM.ABE && !(regs.PABE.PABE && t.tfx_out.a.value() < 0x80);
  t.blend = t.blended ? alpha_blend(regs.ALPHA_1, t.tfx_out, t.cd, o) : blend_off(t.tfx_out);
  t.dithered = dither(t.blend, regs.DIMX, in.x, in.y, regs.DTHE.DTHE, psm, o);
  t.clamped = colclamp(t.dithered, t.tfx_out.a, regs.COLCLAMP.CLAMP);
  t.fba = apply_fba(t.clamped, regs.FBA_1.FBA, psm);
  t.packed = frame_pack(psm, t.fba);
  const std::uint32_t disabled = (t.test.rgb ? 0u : 0x00FFFFFFu) | (t.test.a ? 0u : 0xFF000000u);
  t.keep = frame_mask(psm, regs.FRAME_1.FBMSK | disabled);
  t.out = masked_merge(t.packed, in.dst, t.keep);
  return t;
}

// The trace as text, one stage per line ("tfx      0x80808080", ...), for `gsdot3 alu --trace`.
std::string format_trace(const pixel_trace& t);

}  // namespace gs
