// The catalogue: every claim of "DOT3 Normal Mapping on the PS2" (Mikkelsen 2004) the proofs settle,
// in the paper's order. This table is the only list of claims: the runner, the CLI, the ledger,
// docs/claims.md and the tests all read it.
#include <algorithm>

#include "proofs/claim.hpp"
#include "proofs/claims.hpp"

namespace gsdot3::proofs {

const char* name(method m) noexcept { return m == method::exhaustive ? "exhaustive" : "reduction + argument"; }

namespace {
// A row's model options (gs::option_catalogue names); a call, not a nested braced list, so clang-format
// keeps each row packed.
template <class... Names>
std::vector<std::string_view> depends(Names... names) {
  return {names...};
}
}  // namespace

const std::vector<claim>& catalogue() {
  using M = method;
  namespace c = claims;
  constexpr std::string_view valve = "Seed 001: Green 2007, Efficient Self-Shadowed Radiosity Normal Mapping";
  static const std::vector<claim> rows = {
      {"eq1-eq2.ranges", "§3.2 eq. (1), (2)",
       "a2 = 128 − a and b2 = b + 128 are 8-bit unsigned, and a·b (>> 7) is a signed byte, for a ∈ [−127, 128], b ∈ "
       "[−128, 127]",
       "every (a, b)", M::exhaustive, depends(), c::eq1_eq2_ranges},
      {"eq3.identity", "§3.2 eq. (3)", "(128 − a2)·(b2 − 128) = 128·b2 − a2·b2 + 128·a2 − 128², exactly (no shifts)",
       "every (a2, b2) ∈ [0, 255]²", M::exhaustive, depends(), c::eq3_identity},
      {"eq4.signed-multiply", "§3.2 eq. (4)",
       "a·b (signed >> 7) = (128 − a2)·b2 + a2 − 128, evaluated by the GS blend (Cs − Cd)·As + Cd", "every (a, b)",
       M::exhaustive, depends("blend_shift"), c::eq4_signed_multiply},
      {"eq5-eq7.split-multiply", "§3.2 eq. (5)-(7)",
       "a·b = Max(a,0)·b2 − Max(−a,0)·b2 + c2 − 128, as the GS evaluates it (MODULATE, then a subtracting blend)",
       "every (a, b)", M::exhaustive, depends("tfx_rounding", "blend_shift"), c::eq5_eq7_split_multiply},
      {"eq10.split-offset-multiply", "§3.3 eq. (10)",
       "a·b + 128 = Max(a,0)·b2 − Max(−a,0)·b2 + c2 in the DPB byte (COLCLAMP off)", "every (a, b)", M::exhaustive,
       depends("tfx_rounding", "blend_shift"), c::eq10_split_offset_multiply},
      {"eq8.offset-multiply", "§3.3 eq. (8)",
       "a·b + 128 = (128 − a2)·b2 + a2 exactly by the blend, without clamp or wrap", "every (a, b)", M::exhaustive,
       depends("blend_shift"), c::eq8_offset_multiply},
      {"eq9.rgb-sum", "§3.3 eq. (9)",
       "(r + g + b − 128) mod 256 with COLCLAMP off is the dot product; exact iff the summed products are in [−128, "
       "127]",
       "every DPB pixel (r, g, b)", M::exhaustive, depends("blend_shift"), c::eq9_rgb_sum},
      {"ilp.palette-permutation", "§3.3",
       "the ILP for the offset-keeping sum r + g + b is a permutation (rotation) of the ILP for the plain sum",
       "every sum byte 0..255", M::exhaustive, depends("blend_shift"), c::ilp_palette_permutation},
      {"ilp.dpb-clear-zero", "§3.4, §3.1 step 2.1",
       "with the DPB cleared to 0x00808080 and the ILP 1..128, 0.., never-rendered pixels get intensity zero",
       "the clear value under both methods' post filters", M::exhaustive, depends("blend_shift"),
       c::ilp_dpb_clear_zero},
      {"ilp.light-into-lab", "§3.1 step 2.6",
       "the ILP look-up multiplied by the light colour (MODULATE) and added to the LAB (Cs + Cd, COLCLAMP on) is "
       "min(255, LAB + floor(ILP·colour/128)); ILP 128 adds the colour itself",
       "every ILP entry 0..128 × light colour byte × LAB byte", M::exhaustive, depends("tfx_rounding", "blend_shift"),
       c::ilp_light_into_lab},
      {"lab.saturation", "§3.1 step 2",
       "lights added into the LAB one after another (COLCLAMP on) give min(255, the sum): it saturates, never wraps",
       "every LAB byte × two contributions (n lights by induction)", M::reduction, depends("blend_shift"),
       c::lab_saturation},
      {"step4.diffuse-times-lab", "§3.1 step 4",
       "the diffuse layer times the LAB per channel, (Cs − 0)·Ad >> 7 with COLCLAMP on, is min(255, floor(diffuse·LAB/"
       "128)); LAB 0x80 is 1.0",
       "every diffuse byte × LAB byte", M::exhaustive, depends("tfx_rounding", "blend_shift"),
       c::step4_diffuse_times_lab},
      {"appendix2.packing", "Appendix 2",
       "both asserts hold, B_neg is always 0, and the alpha clamp keeps alpha in a byte",
       "every (iX, iY) the code produces from a unit normal", M::exhaustive, depends(), c::appendix2_packing},
      {"two-pass.na-rounding", "§3.5",
       "n_a can exceed 255 (so bilinear filtering of it goes wrong); n'_a = (n_a + 1)/3 fits a byte and loses at most "
       "1",
       "every Appendix 2 normal; every pair of their n_a values × every bilinear weight", M::exhaustive,
       depends("bilinear"), c::two_pass_na_rounding},
      {"appendix1.sphere-map", "Appendix 1",
       "the asserts r, g, b ∈ [0, 255] hold; how far packed vectors are from exact",
       "every texel at sizes 16, 32, 64, 128, 256", M::exhaustive, depends(), c::appendix1_sphere_map},
      {"two-pass.error-bound", "§3.5",
       "the two-pass per-pixel dot product (s = 122) against the exact integer dot product floor(n·l/128)",
       "every Appendix 2 normal × every packed light (char)(122·T)", M::reduction,
       depends("tfx_rounding", "blend_shift"), c::two_pass_error_bound},
      {"three-pass.error-bound", "§3.5",
       "\"to completely avoid the precision loss, one could also do a three-pass solution by adding the terms as a "
       "separate additive pass\": its per-pixel dot product (s = 122) against floor(n·l/128)",
       "every Appendix 2 normal × every packed light (char)(122·T)", M::reduction,
       depends("tfx_rounding", "blend_shift"), c::three_pass_error_bound},
      {"two-pass.max-s.vertex", "§3.5", "s = 122 avoids wrapping (found by trial and error); the largest safe s",
       "every Appendix 2 normal × every packed light, from s = 126 up to the first s that wraps (s <= 125 by argument)",
       M::reduction, depends("tfx_rounding", "blend_shift"), c::two_pass_max_s_vertex},
      {"two-pass.max-s.interpolated", "§3.5",
       "s = 122 avoids wrapping for the barycentrically interpolated light vectors; the largest safe s",
       "every triangle in the GS's 2048² window (12.4 vertices) × three packed vertex lights × every covered pixel "
       "(8.7 Gouraud, gs::gouraud_triangle read per gouraud_setup) × every Appendix 2 normal (size: the normals × s "
       "bound evaluations and the certificates)",
       M::reduction, depends("tfx_rounding", "gouraud_fraction", "blend_shift", "gouraud_setup"),
       c::two_pass_max_s_interpolated},
      {"four-pass.channel-exact", "§3.6",
       "each pass's signed multiplication is identical to a char multiplication a·b with a signed >> 7, offset by 128",
       "every (a, b) × 3 channels (FBMSK per channel)", M::exhaustive, depends("blend_shift"),
       c::four_pass_channel_exact},
      {"four-pass.sum-wrap", "§3.6, §3.3",
       "R+G+B of the three channel products does not wrap, for sphere-map vectors against normal-map vectors",
       "every 64×64 Appendix 1 texel × every 8-bit normal-map vector (n_z >= 0)", M::exhaustive, depends("blend_shift"),
       c::four_pass_sum_wrap},  // tfx_rounding: HIGHLIGHT's operands are unsigned, floor = truncation
      {"clamp-wrap.intermediates", "§3.2, §3.5, §3.6",
       "every intermediate of every pass stays in 0..255 or wraps exactly as the method needs; the TFX clamp never "
       "bites",
       "each pass's unit over its whole input range", M::exhaustive,
       depends("tfx_rounding", "gouraud_fraction", "blend_shift"), c::clamp_wrap_intermediates},
      {"zprefill.single-light", "§3.1",
       "for a single light source, pre-filling the Z buffer (step 1) is not necessary: the light's first pass "
       "testing GEQUAL and writing Z leaves the DPB and Z as step 1 then the pass does",
       "every Z order of 1..6 fragments at a pixel (Z in 0..k-1) × each method's first light pass", M::exhaustive,
       depends("tfx_rounding", "gouraud_fraction", "blend_shift"), c::z_prefill_single_light},
      {"alpha-layer.round-trip", "§3.1",
       "without VRAM for two draw buffers, a light's dot-product layer (or a LAB channel) kept in a free alpha: the "
       "byte moved into a destination's alpha (DECAL / RGBA, FBMSK keeping R, G, B) reads back as PSMT8H unchanged and "
       "leaves R, G, B as they were, so steps 2.6 and 4 read what the two-buffer method gives them",
       "every moved byte × destination alpha × destination grey (v, v, v)", M::exhaustive, depends(),
       c::alpha_layer_round_trip},
      {"highlight.attenuation", "§3.6",
       "128 − (128 − sph)·scale = sph·scale + (1 − scale)·128 by a HIGHLIGHT texture function",
       "every texel × every scale 0..128", M::exhaustive, depends("tfx_rounding"), c::highlight_attenuation},
      {"spot.attenuation-blend", "§3.6",
       "a spot light's projective intensity texture attenuates the DPB per pixel by the GS blend in the same way as "
       "HIGHLIGHT, after the first pass or after all four",
       "every DPB channel × As 0..128, and every sphere component × normal component × As 0..128 for each placement",
       M::exhaustive, depends("tfx_rounding", "blend_shift"), c::spot_attenuation_blend},
      {"specular.attenuation-compensation", "§3.7", "(att^(1/n)·dot)^n through the ILP approximates att·dot^n",
       "n = 2..64 × att 0..128 × dot index 0..127", M::exhaustive, depends("tfx_rounding"),
       c::specular_attenuation_compensation},
      {"lod.two-vs-four", "§3.8",
       "two-pass and four-pass can be switched using the same 8-bit palette indices; how far apart their dot products "
       "are",
       "every 8-bit normal-map vector × every 64×64 sphere-map texel in the disc", M::exhaustive,
       depends("blend_shift"), c::lod_two_vs_four},
      // §3.4: the Z-buffer clear of the DPB during the ILP pass, over one DPB page through gs_memory.
      {"dpb-clear.value", "§3.4",
       "with ZBUF at the DPB, Z = 0x00808080 and ZTST all-pass, the DPB ends as 0x00808080 everywhere the trick covers",
       "z-trick, z-trick-psmz32 × ZBUF PSMZ24, PSMZ32 × DPB alpha 0..255 × every pixel of a page", M::exhaustive,
       depends(), c::dpb_clear_value},
      {"dpb-clear.read-before-write", "§3.4",
       "no texel of the DPB is overwritten by the Z clear before the ILP pass (or the post filter) reads it",
       "z-trick, z-trick-psmz32 × ZBUF PSMZ24, PSMZ32 × every pixel of a page", M::exhaustive,
       depends("texture_buffer"), c::dpb_clear_read_before_write},
      {"dpb-clear.variants-agree", "§3.4",
       "the two variants (sprites' XYZ in the Z layout; LAB rendered in PSMZ32) give the same LAB",
       "ZBUF PSMZ24, PSMZ32 × every LAB pixel of a page", M::exhaustive, depends("texture_buffer"),
       c::dpb_clear_variants_agree},
      {"dpb-clear.lab-layout", "§3.4",
       "the LAB comes out in PSMZ32 layout; rendering the signed multiplications in PSMZ32 brings it back to PSMCT32",
       "z-trick, z-trick-psmz32 × DPB in PSMCT32, PSMZ32 × every pixel of a page", M::exhaustive,
       depends("texture_buffer"), c::dpb_clear_lab_layout},
      {"valve.eq1-not-orthonormal", "eq. (1)", "the basis B0..B2 of eq. (1), as printed, is orthonormal",
       "the 6 Gram entries B_i·B_j, i ≤ j, exactly in Q(√2, √3)", M::exhaustive, depends(),
       c::valve_eq1_not_orthonormal, valve},
      {"valve.basis-orthonormal", "eq. (1) (Source's bumpvects.h)",
       "Source's basis is orthonormal, so Σ(N·B_i)² = 1 for unit N",
       "the 6 Gram entries exactly; 721×1441 unit normals sampled", M::exhaustive, depends(),
       c::valve_source_basis_orthonormal, valve},
      {"valve.float-literals", "eq. (1) (common_fxc.h)",
       "Source's float literals for the basis: deviation from the exact values and its effect",
       "the 6 non-zero literals; normal2ssbump on every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³)", M::exhaustive,
       depends(), c::valve_float_literals, valve},
      {"valve.zero-sum", "eq. (3), Listing 1",
       "eq. (3)'s divisor Σ saturate(N·B_i)² is non-zero for every 8-bit normal texel",
       "every RGB8 texel (2^24), signs decided exactly", M::exhaustive, depends(), c::valve_zero_sum, valve},
      {"valve.flat-normal", "§1.4, normal2ssbump, height2ssbump",
       "a flat normal gives (1/3, 1/3, 1/3) through normal2ssbump; a flat unoccluded height field gives 1/√3 through "
       "height2ssbump",
       "the exact flat normal; the 4 RGB8 texels nearest it; an 8×8 flat height field", M::exhaustive, depends(),
       c::valve_flat_normal, valve},
      {"valve.precision", "§1.4 (\"numeric precision is increased\")",
       "storing D (SSBump) instead of N (RNM) in 8 bits increases the lighting's precision",
       "every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³; all 2^24 in the valve_exhaustive ctest); unit normals on "
       "a "
       "0.25° (θ, φ) grid of the upper hemisphere",
       M::exhaustive, depends(), c::valve_precision, valve},
      {"valve.ssbump-filter-linear", "§1.4 (\"no special processing ... when filtering or mip-mapping\")",
       "filtering SSBump texels filters the lighting exactly (Listing 2 is linear)",
       "every channel pair (a, b) × weight w/16, w = 0..16 (× 6 lightmap values, exact integers)", M::exhaustive,
       depends(), c::valve_ssbump_filter_linear, valve},
      {"valve.rnm-filter", "eq. (3), §1.4", "filtering RNM normal texels does not filter the lighting: how far apart",
       "every pair of the RGB8 unit normals on a 17×17 (x, y) grid in the disc × bilinear weight w/16, w = 1..15 "
       "(a 65×65 grid in the valve_exhaustive ctest)",
       M::exhaustive, depends(), c::valve_rnm_filter, valve},
      {"valve.reconstruct-normal", "§1.4 (\"reconstruct a suitable tangent-space normal\")",
       "the tangent-space normal rebuilt from SSBump weights with the basis directions: its angular error",
       "every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³; all 2^24 in the valve_exhaustive ctest), Σd ≠ 0",
       M::exhaustive, depends(), c::valve_reconstruct_normal, valve},
      {"normal-encoding.codes", "seed 002, all methods", "every stored 2×8 code decodes to a unit normal",
       "every 2×8 code of every two-channel method (#2 with its sign bit)", M::exhaustive, depends(),
       c::normal_encoding_codes, c::normal_encoding_section},
      {"normal-encoding.worst-case", "seed 002, all methods; 2010 revision; octahedral",
       "the methods' error (published only as PSNR on one scene): the worst angle over the whole sphere at 2×8",
       "every rounding cell at 2×8 (xyz 3×8), 1/8 of them by the dihedral symmetry where it holds", M::reduction,
       depends(), c::normal_encoding_worst_case, c::normal_encoding_section},
      {"normal-encoding.mean-rms", "seed 002, quality comparison", "mean and RMS angle at 2×8 over an area-uniform set",
       "2^16 spherical Fibonacci directions", M::exhaustive, depends(), c::normal_encoding_mean_rms,
       c::normal_encoding_section},
      {"normal-encoding.equivalence", "2010 revision, method #4",
       "sphere map, CryEngine 3 and Lambert are the same mapping for unit normals",
       "2^16 Fibonacci directions (encoders) and every 2×8 code (decoders)", M::exhaustive, depends(),
       c::normal_encoding_equivalence, c::normal_encoding_section},
      {"normal-encoding.singularities", "seed 002 #1, #4-#7; 2010 #8; octahedral",
       "each method encodes every unit normal (the seed: #4 'can point away from the camera')",
       "every method × the 6 axes and 8 octant diagonals", M::exhaustive, depends(), c::normal_encoding_singularities,
       c::normal_encoding_section},
      {"normal-encoding.xy-wrong-sign", "seed 002 #1",
       "X&Y with z = sqrt(1 − x² − y²) loses the sign of z: how much of the sphere", "2^16 Fibonacci directions",
       M::exhaustive, depends(), c::normal_encoding_xy_wrong_sign, c::normal_encoding_section},
      {"normal-encoding.2009-vs-2010", "seed 002 header; 2010 revision",
       "the 2009 encoders did not normalise their input: what it cost", "2^14 Fibonacci directions × 2 input lengths",
       M::exhaustive, depends(), c::normal_encoding_2009_vs_2010, c::normal_encoding_section},
      {"normal-encoding.ranking", "seed 002 and 2010 quality tables", "the PSNR ranking of the methods",
       "the 4 methods in both tables: worst case at 2×8 vs PSNR 2009 and 2010", M::reduction, depends(),
       c::normal_encoding_ranking, c::normal_encoding_section},
      {"normal-encoding.seed-2009-measure", "seed 002 quality table; 2010 header (\"do not normalize\")",
       "sphere map, CryEngine 3 and Lambert score 44.781, 40.355 and 43.054 dB as the seed measured them",
       "every method × the pixels of UV spheres 8×16, 16×32, 32×64 drawn at 512×512 (per-vertex normals "
       "interpolated, not normalised)",
       M::exhaustive, depends(), c::normal_encoding_seed_2009_measure, c::normal_encoding_section},
      {"powervr.identity", "Tangent Space and Bump Shading Shortcuts",
       "K1 + K2·sin S + K3·cos S·cos(R − Q) with K1 = 1 − S_l, K2 = S_l sin T, K3 = S_l cos T equals (1 − S_l) + "
       "S_l·(N·L)",
       "every (S, R) texel × T = 0..90° (10°) × 8 azimuths × S_l ∈ {0.5, 1}, in double, tolerance 1e-12", M::exhaustive,
       depends(), c::powervr_identity, c::powervr_section},
      {"powervr.identity-8bit", "Tangent Space and Bump Shading Shortcuts",
       "the 8-bit bump unit computes N·L: its error per precision option (float, fixed8, fixed10, fixed12)",
       "every (S, R) texel × Q = 0, 32, .., 224 × T = 0..90° (15°), S_l = 1, azimuths /255, × 4 precision options (all "
       "Q: exhaustive test)",
       M::exhaustive, depends(), c::powervr_identity_8bit, c::powervr_section},
      {"powervr.q-quadrant", "Tangent Space and Bump Shading Shortcuts", "Q = arctan(Pz/Px) gives the light's azimuth",
       "light azimuths every 0.1° at 30° elevation (and every texel for lights every 10°)", M::exhaustive, depends(),
       c::powervr_q_quadrant, c::powervr_section},
      {"powervr.azimuth-255-256", "encoders and decoders (other-schemes.md)",
       "the azimuth byte means the same to encoder and decoder (/255 against /256)",
       "every R byte (KallistiOS pvrtex); every (S, R, Q) with Q in 1/256 turns read as /255", M::exhaustive, depends(),
       c::powervr_azimuth_scale, c::powervr_section},
      {"powervr.sdk-arctan", "Fast calculation of K1, K2, K3 and Q",
       "the SDK's quadratic arctangent (FXYZLightDirToSKK) is accurate enough for Q",
       "s = tan ∈ [0, 1] every 2^−20 (supremum argued: |e''| < 60); the whole routine at azimuths every 0.01°",
       M::reduction, depends(), c::powervr_sdk_arctan, c::powervr_section},
      {"powervr.pack-bump", "encoders (other-schemes.md)", "KallistiOS pvr_pack_bump writes the seed's K1, K2, K3, Q",
       "h = 0.1..1 (0.1) × t = 0..90° (1°) × q = 0..359° (1°), against rounding to nearest", M::exhaustive, depends(),
       c::powervr_pack_bump, c::powervr_section},
      {"powervr.flipped-uv", "Flipped UV",
       "flipped UVs flip the light; mirroring one axis of the local co-ordinate system fixes it",
       "every (S, R) texel × light azimuths every 10° × T ∈ {30°, 60°}, exact evaluation of the 8-bit K/Q",
       M::exhaustive, depends(), c::powervr_flipped_uv, c::powervr_section},
  };
  return rows;
}

const claim* find_claim(std::string_view id) noexcept {
  const auto& rows = catalogue();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const claim& c) { return c.id == id; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace gsdot3::proofs
