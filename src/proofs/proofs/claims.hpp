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
// appendices and section 3.5 (claims_packing.cpp, claims_two_pass.cpp)
GSDOT3_CLAIM(appendix2_packing);
GSDOT3_CLAIM(two_pass_na_rounding);
GSDOT3_CLAIM(appendix1_sphere_map);
GSDOT3_CLAIM(two_pass_error_bound);
GSDOT3_CLAIM(two_pass_max_s_vertex);
GSDOT3_CLAIM(two_pass_max_s_interpolated);
// section 3.6 - 3.8 (claims_four_pass.cpp, claims_attenuation.cpp)
GSDOT3_CLAIM(four_pass_channel_exact);
GSDOT3_CLAIM(four_pass_sum_wrap);
GSDOT3_CLAIM(clamp_wrap_intermediates);
GSDOT3_CLAIM(highlight_attenuation);
GSDOT3_CLAIM(lod_two_vs_four);
GSDOT3_CLAIM(specular_attenuation_compensation);
// section 3.4: the Z-buffer clear of the DPB (claims_memory.cpp)
GSDOT3_CLAIM(dpb_clear_value);
GSDOT3_CLAIM(dpb_clear_read_before_write);
GSDOT3_CLAIM(dpb_clear_variants_agree);
GSDOT3_CLAIM(dpb_clear_lab_layout);
#undef GSDOT3_CLAIM

}  // namespace gsdot3::proofs::claims
