// proofs/claims.hpp — the evaluation function of every catalogue row (defined in claims_*.cpp).
#pragma once

#include "gs_arith/options.hpp"
#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::claims {

#define GSDOT3_CLAIM(fn) outcome fn(const gs::model_options& o, const sweep_config& cfg)
// section 3.2 / 3.3: signed multiplication and the R+G+B sum (claims_multiply.cpp)
GSDOT3_CLAIM(eq1_eq2_ranges);
GSDOT3_CLAIM(eq3_identity);
GSDOT3_CLAIM(eq4_signed_multiply);
GSDOT3_CLAIM(eq5_eq7_split_multiply);
GSDOT3_CLAIM(eq10_split_offset_multiply);
GSDOT3_CLAIM(eq8_offset_multiply);
GSDOT3_CLAIM(eq9_rgb_sum);
GSDOT3_CLAIM(ilp_palette_permutation);
GSDOT3_CLAIM(ilp_dpb_clear_zero);
GSDOT3_CLAIM(ilp_light_into_lab);
GSDOT3_CLAIM(lab_saturation);
GSDOT3_CLAIM(step4_diffuse_times_lab);
// appendices and section 3.5 (claims_packing.cpp, claims_two_pass.cpp)
GSDOT3_CLAIM(appendix2_packing);
GSDOT3_CLAIM(two_pass_na_rounding);
GSDOT3_CLAIM(appendix1_sphere_map);
GSDOT3_CLAIM(two_pass_error_bound);
GSDOT3_CLAIM(three_pass_error_bound);
GSDOT3_CLAIM(two_pass_max_s_vertex);
GSDOT3_CLAIM(two_pass_max_s_interpolated);
// section 3.6 - 3.8 (claims_four_pass.cpp, claims_attenuation.cpp)
GSDOT3_CLAIM(four_pass_channel_exact);
GSDOT3_CLAIM(four_pass_sum_wrap);
GSDOT3_CLAIM(clamp_wrap_intermediates);
GSDOT3_CLAIM(highlight_attenuation);
GSDOT3_CLAIM(lod_two_vs_four);
GSDOT3_CLAIM(spot_attenuation_blend);
GSDOT3_CLAIM(z_prefill_single_light);
GSDOT3_CLAIM(alpha_layer_round_trip);
GSDOT3_CLAIM(specular_attenuation_compensation);
// section 3.4: the Z-buffer clear of the DPB (claims_memory.cpp)
GSDOT3_CLAIM(dpb_clear_value);
GSDOT3_CLAIM(dpb_clear_read_before_write);
GSDOT3_CLAIM(dpb_clear_variants_agree);
GSDOT3_CLAIM(dpb_clear_lab_layout);
// seed 001, Green 2007 (claims_valve.cpp)
GSDOT3_CLAIM(valve_eq1_not_orthonormal);
GSDOT3_CLAIM(valve_source_basis_orthonormal);
GSDOT3_CLAIM(valve_float_literals);
GSDOT3_CLAIM(valve_zero_sum);
GSDOT3_CLAIM(valve_flat_normal);
GSDOT3_CLAIM(valve_precision);
GSDOT3_CLAIM(valve_ssbump_filter_linear);
GSDOT3_CLAIM(valve_rnm_filter);
GSDOT3_CLAIM(valve_reconstruct_normal);
// seed 002: compact normal storage (claims_normal_encoding.cpp)
inline constexpr std::string_view normal_encoding_section =
    "Seed 002: Pranckevičius 2009, Compact Normal Storage for small G-Buffers";
GSDOT3_CLAIM(normal_encoding_codes);
GSDOT3_CLAIM(normal_encoding_worst_case);
GSDOT3_CLAIM(normal_encoding_mean_rms);
GSDOT3_CLAIM(normal_encoding_equivalence);
GSDOT3_CLAIM(normal_encoding_singularities);
GSDOT3_CLAIM(normal_encoding_xy_wrong_sign);
GSDOT3_CLAIM(normal_encoding_2009_vs_2010);
GSDOT3_CLAIM(normal_encoding_ranking);
GSDOT3_CLAIM(normal_encoding_seed_2009_measure);  // claims_normal_encoding_2009.cpp
// seed 004: PowerVR Series 2 polar bump mapping (claims_powervr.cpp)
inline constexpr std::string_view powervr_section =
    "Seed 004: Imagination Technologies 1999, Bump Mapping Tricks for Series 2";
GSDOT3_CLAIM(powervr_identity);
GSDOT3_CLAIM(powervr_identity_8bit);
GSDOT3_CLAIM(powervr_q_quadrant);
GSDOT3_CLAIM(powervr_azimuth_scale);
GSDOT3_CLAIM(powervr_sdk_arctan);
GSDOT3_CLAIM(powervr_pack_bump);
GSDOT3_CLAIM(powervr_flipped_uv);
#undef GSDOT3_CLAIM

}  // namespace gsdot3::proofs::claims
