// Section 3.1's variants for too little VRAM: "use a single light and save the dot product layer in a
// free alpha channel like the one in the display buffer", and "2 to 3 lights ... by storing their dot
// product layers in unused alpha pixels in the VRAM ... copy the red, green, and blue to the free
// alphas and render the unlit diffuse buffer. Afterwards, at step 4, apply the LAB by using these
// alphas". What they add to the two-buffer steps is a byte moved into a destination's alpha and read
// back from there: the move is gs_methods::move_into_alpha (the renderer's step-4 move on the memory
// path: the source channel read as PSMT8 through a CLUT whose entry i is (i, i, i, i), DECAL / RGBA,
// FBMSK keeping R, G and B), the read back PSMT8H (gs::t8h_index). Steps 2.6 and 4 then use that byte
// as the two-buffer method uses the DPB's red or the LAB's channel (ilp.light-into-lab,
// step4.diffuse-times-lab). Every unit is the model's (gs::pixel_pipeline).
#include <cstdint>
#include <string>

#include "gs_arith/clut.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/methods.hpp"
#include "proofs/sweep.hpp"

namespace gsdot3::proofs::claims {

namespace m = methods;

namespace {

// The destination word after moving byte b into its alpha: old = (v, v, v, a).
std::uint32_t moved(int b, int a, int v, const gs::model_options& o) {
  static constexpr gs::gs_registers regs = gs_methods::move_into_alpha.registers();
  const gs::rgba8 texel = m::grey(b, b);  // the CLUT entry (b, b, b, b) of the source byte b
  return gs::pixel_pipeline(regs, {gs::fragment_colour::flat(m::grey(0x80, 0x80)), texel, m::grey(v, a).to_u32(), 0, 0},
                            o)
      .out;
}

}  // namespace

outcome alpha_layer_round_trip(const gs::model_options& o, const sweep_config& cfg) {
  constexpr std::uint64_t n = 1u << 24;  // moved byte b × old alpha a × old grey v
  auto wrong = [&](std::uint64_t k) {
    const int b = static_cast<int>(k >> 16), a = static_cast<int>((k >> 8) & 0xFF), v = static_cast<int>(k & 0xFF);
    const std::uint32_t w = moved(b, a, v, o), old = m::grey(v, a).to_u32();
    return gs::t8h_index(w).value() != b || (w & 0x00FFFFFFu) != (old & 0x00FFFFFFu);
  };
  const tally bad = sweep<tally>(n, cfg, [&](tally& t, std::uint64_t lo, std::uint64_t hi) {
    for (auto k = lo; k < hi; ++k)
      if (wrong(k)) t.add(k);
  });
  outcome out = verdict_of(bad, n, [&](std::uint64_t k) {
    const int b = static_cast<int>(k >> 16), a = static_cast<int>((k >> 8) & 0xFF), v = static_cast<int>(k & 0xFF);
    return "byte " + hexdec(b) + " into " + hexdec(m::grey(v, a).to_u32(), 32) + " => " + hexdec(moved(b, a, v, o), 32);
  });
  out.note =
      "the byte lands in alpha unchanged (DECAL passes the texel, no blend, no alpha test, no dither) and FBMSK keeps "
      "the destination's R, G, B bit for bit, so a dot product or LAB channel kept in a free alpha reads back as "
      "PSMT8H exactly as the two-buffer method reads it from the DPB or the LAB";
  return out;
}

}  // namespace gsdot3::proofs::claims
