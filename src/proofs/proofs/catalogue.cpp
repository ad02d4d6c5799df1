// The catalogue: every claim of "DOT3 Normal Mapping on the PS2" (Mikkelsen 2004) the proofs settle,
// in the paper's order. This table is the only list of claims: the runner, the CLI, the ledger,
// docs/claims.md and the tests all read it.
#include <algorithm>

#include "proofs/claim.hpp"
#include "proofs/claims.hpp"

namespace gsdot3::proofs {

const char* name(method m) noexcept { return m == method::exhaustive ? "exhaustive" : "reduction + argument"; }

const std::vector<claim>& catalogue() {
  using M = method;
  namespace c = claims;
  static const std::vector<claim> rows = {
      {"eq1-eq2.ranges", "§3.2 eq. (1), (2)",
       "a2 = 128 − a and b2 = b + 128 are 8-bit unsigned, and a·b (>> 7) is a signed byte, for a ∈ [−127, 128], b ∈ [−128, 127]",
       "every (a, b)", M::exhaustive, {}, c::eq1_eq2_ranges},
      {"eq3.identity", "§3.2 eq. (3)", "(128 − a2)·(b2 − 128) = 128·b2 − a2·b2 + 128·a2 − 128², exactly (no shifts)",
       "every (a2, b2) ∈ [0, 255]²", M::exhaustive, {}, c::eq3_identity},
      {"eq4.signed-multiply", "§3.2 eq. (4)",
       "a·b (signed >> 7) = (128 − a2)·b2 + a2 − 128, evaluated by the GS blend (Cs − Cd)·As + Cd",
       "every (a, b)", M::exhaustive, {"blend_shift"}, c::eq4_signed_multiply},
      {"eq5-eq7.split-multiply", "§3.2 eq. (5)-(7)",
       "a·b = Max(a,0)·b2 − Max(−a,0)·b2 + c2 − 128, as the GS evaluates it (MODULATE, then a subtracting blend)",
       "every (a, b)", M::exhaustive, {"tfx_rounding", "blend_shift"}, c::eq5_eq7_split_multiply},
      {"eq10.split-offset-multiply", "§3.3 eq. (10)",
       "a·b + 128 = Max(a,0)·b2 − Max(−a,0)·b2 + c2 in the DPB byte (COLCLAMP off)", "every (a, b)", M::exhaustive,
       {"tfx_rounding", "blend_shift"}, c::eq10_split_offset_multiply},
      {"eq8.offset-multiply", "§3.3 eq. (8)",
       "a·b + 128 = (128 − a2)·b2 + a2 exactly by the blend, without clamp or wrap", "every (a, b)", M::exhaustive,
       {"blend_shift"}, c::eq8_offset_multiply},
      {"eq9.rgb-sum", "§3.3 eq. (9)",
       "(r + g + b − 128) mod 256 with COLCLAMP off is the dot product; exact iff the summed products are in [−128, 127]",
       "every DPB pixel (r, g, b)", M::exhaustive, {"blend_shift"}, c::eq9_rgb_sum},
      {"ilp.palette-permutation", "§3.3",
       "the ILP for the offset-keeping sum r + g + b is a permutation (rotation) of the ILP for the plain sum",
       "every sum byte 0..255", M::exhaustive, {"blend_shift"}, c::ilp_palette_permutation},
      {"ilp.dpb-clear-zero", "§3.4, §3.1 step 2.1",
       "with the DPB cleared to 0x00808080 and the ILP 1..128, 0.., never-rendered pixels get intensity zero",
       "the clear value under both methods' post filters", M::exhaustive, {"blend_shift"}, c::ilp_dpb_clear_zero},
      {"appendix2.packing", "Appendix 2",
       "both asserts hold, B_neg is always 0, and the alpha clamp keeps alpha in a byte",
       "every (iX, iY) the code produces from a unit normal", M::exhaustive, {}, c::appendix2_packing},
      {"two-pass.na-rounding", "§3.5", "n_a can exceed 255 (so bilinear filtering of it goes wrong); n'_a = (n_a + 1)/3 fits a byte and loses at most 1",
       "every Appendix 2 normal; every pair of their n_a values × every bilinear weight", M::exhaustive,
       {"bilinear"}, c::two_pass_na_rounding},
      {"appendix1.sphere-map", "Appendix 1", "the asserts r, g, b ∈ [0, 255] hold; how far packed vectors are from exact",
       "every texel at sizes 16, 32, 64, 128, 256", M::exhaustive, {}, c::appendix1_sphere_map},
      {"two-pass.error-bound", "§3.5",
       "the two-pass per-pixel dot product (s = 122) against the exact integer dot product floor(n·l/128)",
       "every Appendix 2 normal × every packed light (char)(122·T)", M::reduction,
       {"tfx_rounding", "blend_shift"}, c::two_pass_error_bound},
      {"two-pass.max-s.vertex", "§3.5", "s = 122 avoids wrapping (found by trial and error); the largest safe s",
       "every Appendix 2 normal × every packed light, from s = 126 up to the first s that wraps (s <= 125 by argument)", M::reduction,
       {"tfx_rounding", "blend_shift"}, c::two_pass_max_s_vertex},
      {"two-pass.max-s.interpolated", "§3.5",
       "s = 122 avoids wrapping for the barycentrically interpolated light vectors; the largest safe s",
       "every triangle in the GS's 2048² window (12.4 vertices) × three packed vertex lights × every covered pixel (8.7 Gouraud, gs::gouraud_triangle) × every Appendix 2 normal (size: the normals × s bound evaluations and the certificates)",
       M::reduction, {"tfx_rounding", "gouraud_fraction", "blend_shift"}, c::two_pass_max_s_interpolated},
      {"four-pass.channel-exact", "§3.6",
       "each pass's signed multiplication is identical to a char multiplication a·b with a signed >> 7, offset by 128",
       "every (a, b) × 3 channels (FBMSK per channel)", M::exhaustive, {"blend_shift"}, c::four_pass_channel_exact},
      {"four-pass.sum-wrap", "§3.6, §3.3",
       "R+G+B of the three channel products does not wrap, for sphere-map vectors against normal-map vectors",
       "every 64×64 Appendix 1 texel × every 8-bit normal-map vector (n_z >= 0)", M::exhaustive,
       {"blend_shift"}, c::four_pass_sum_wrap},  // tfx_rounding: HIGHLIGHT's operands are unsigned, floor = truncation
      {"clamp-wrap.intermediates", "§3.2, §3.5, §3.6",
       "every intermediate of every pass stays in 0..255 or wraps exactly as the method needs; the TFX clamp never bites",
       "each pass's unit over its whole input range", M::exhaustive, {"tfx_rounding", "gouraud_fraction", "blend_shift"},
       c::clamp_wrap_intermediates},
      {"highlight.attenuation", "§3.6",
       "128 − (128 − sph)·scale = sph·scale + (1 − scale)·128 by a HIGHLIGHT texture function", "every texel × every scale 0..128",
       M::exhaustive, {"tfx_rounding"}, c::highlight_attenuation},
      {"specular.attenuation-compensation", "§3.7",
       "(att^(1/n)·dot)^n through the ILP approximates att·dot^n", "n = 2..64 × att 0..128 × dot index 0..127",
       M::exhaustive, {"tfx_rounding"}, c::specular_attenuation_compensation},
      {"lod.two-vs-four", "§3.8",
       "two-pass and four-pass can be switched using the same 8-bit palette indices; how far apart their dot products are",
       "every 8-bit normal-map vector × every 64×64 sphere-map texel in the disc", M::exhaustive,
       {"blend_shift"}, c::lod_two_vs_four},
  };
  return rows;
}

const claim* find_claim(std::string_view id) noexcept {
  const auto& rows = catalogue();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const claim& c) { return c.id == id; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace gsdot3::proofs
