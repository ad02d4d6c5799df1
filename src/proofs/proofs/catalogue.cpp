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
  constexpr std::string_view valve = "Seed 001: Green 2007, Efficient Self-Shadowed Radiosity Normal Mapping";
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
       "every span of <= 128 pixels between two packed vertex lights (8.7 Gouraud) × every Appendix 2 normal (size: spans × pixels per normal at s = 122)",
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
      {"valve.eq1-not-orthonormal", "eq. (1)", "the basis B0..B2 of eq. (1), as printed, is orthonormal",
       "the 6 Gram entries B_i·B_j, i ≤ j, exactly in Q(√2, √3)", M::exhaustive, {}, c::valve_eq1_not_orthonormal, valve},
      {"valve.basis-orthonormal", "eq. (1) (Source's bumpvects.h)", "Source's basis is orthonormal, so Σ(N·B_i)² = 1 for unit N",
       "the 6 Gram entries exactly; 721×1441 unit normals sampled", M::exhaustive, {}, c::valve_source_basis_orthonormal, valve},
      {"valve.float-literals", "eq. (1) (common_fxc.h)", "Source's float literals for the basis: deviation from the exact values and its effect",
       "the 6 non-zero literals; normal2ssbump on every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³)", M::exhaustive, {},
       c::valve_float_literals, valve},
      {"valve.zero-sum", "eq. (3), Listing 1", "eq. (3)'s divisor Σ saturate(N·B_i)² is non-zero for every 8-bit normal texel",
       "every RGB8 texel (2^24), signs decided exactly", M::exhaustive, {}, c::valve_zero_sum, valve},
      {"valve.flat-normal", "§1.4, normal2ssbump, height2ssbump",
       "a flat normal gives (1/3, 1/3, 1/3) through normal2ssbump; a flat unoccluded height field gives 1/√3 through height2ssbump",
       "the exact flat normal; the 4 RGB8 texels nearest it; an 8×8 flat height field", M::exhaustive, {}, c::valve_flat_normal, valve},
      {"valve.precision", "§1.4 (\"numeric precision is increased\")",
       "storing D (SSBump) instead of N (RNM) in 8 bits increases the lighting's precision",
       "every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³; all 2^24 in the valve_exhaustive ctest); unit normals on a "
       "0.25° (θ, φ) grid of the upper hemisphere", M::exhaustive, {}, c::valve_precision, valve},
      {"valve.ssbump-filter-linear", "§1.4 (\"no special processing ... when filtering or mip-mapping\")",
       "filtering SSBump texels filters the lighting exactly (Listing 2 is linear)",
       "every channel pair (a, b) × weight w/16, w = 0..16 (× 6 lightmap values, exact integers)", M::exhaustive, {},
       c::valve_ssbump_filter_linear, valve},
      {"valve.rnm-filter", "eq. (3), §1.4", "filtering RNM normal texels does not filter the lighting: how far apart",
       "every pair of the RGB8 unit normals on a 17×17 (x, y) grid in the disc × bilinear weight w/16, w = 1..15 "
       "(a 65×65 grid in the valve_exhaustive ctest)", M::exhaustive, {}, c::valve_rnm_filter, valve},
      {"valve.reconstruct-normal", "§1.4 (\"reconstruct a suitable tangent-space normal\")",
       "the tangent-space normal rebuilt from SSBump weights with the basis directions: its angular error",
       "every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³; all 2^24 in the valve_exhaustive ctest), Σd ≠ 0", M::exhaustive,
       {}, c::valve_reconstruct_normal, valve},
  };
  return rows;
}

const claim* find_claim(std::string_view id) noexcept {
  const auto& rows = catalogue();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const claim& c) { return c.id == id; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace gsdot3::proofs
