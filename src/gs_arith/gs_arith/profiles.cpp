#include "gs_arith/profiles.hpp"

namespace gs {

// One column per emulator of docs/evidence.md. Where an emulator's arithmetic is a defect the matrix
// names (no option reproduces it), the profile keeps the model's default and the matrix says so.
const std::vector<profile>& profiles() {
  static const std::vector<profile> rows = {
      {"pcsx2-sw",
       "PCSX2 software renderer, pcsx2/GS/Renderers/SW/GSDrawScanline.cpp CDrawScanline (C++ path)",
       {{"tfx_rounding", "floor"},
        {"gouraud_fraction", "keep_fraction"},
        {"blend_shift", "floor"},
        {"dither_decode", "twos_complement"},
        {"dither_targets", "sixteen_bit_only"},
        {"bilinear", "lerp16_4"},
        {"rgb_only_targets", "thirty_two_bit_only"},
        {"texture_buffer", "draw_snapshot"},
        {"gouraud_setup", "pcsx2_rows_8"},
        {"stq_range", "x86_int32"},
        {"stq_convert", "trunc_16_16"},
        {"uv_convert", "floor"},
        {"uv_plane", "fixed_16"}}},
      {"dobiestation",
       "DobieStation src/core/gsthread.cpp (interpreter: tex_lookup, draw_pixel)",
       {{"tfx_rounding", "floor"},
        {"gouraud_fraction", "truncate_to_8"},
        {"blend_shift", "floor"},
        {"dither_decode", "inverted_magnitude"},
        {"dither_targets", "all_formats"},
        {"bilinear", "weighted_sum_4"},
        {"rgb_only_targets", "all_formats"},
        {"texture_buffer", "per_fragment"},
        {"gouraud_setup", "per_pixel_floor"},
        {"stq_range", "x86_int32"},
        {"stq_convert", "truncate"},
        {"uv_convert", "floor"},
        {"uv_plane", "exact"}}},
      {"play",
       "Play! Source/gs/GSH_Vulkan (GSH_VulkanDrawDesktop.cpp fragment shader, GSH_VulkanDrawUtils.cpp)",
       {{"tfx_rounding", "truncate"},
        {"gouraud_fraction", "keep_fraction"},
        {"blend_shift", "floor"},
        {"dither_decode", "twos_complement"},
        {"dither_targets", "sixteen_bit_only"},
        {"bilinear", "weighted_sum_4"},
        {"rgb_only_targets", "all_formats"},
        {"texture_buffer", "quarter_page"},
        {"gouraud_setup", "per_pixel_floor"},
        {"stq_range", "saturate_2047"},
        {"stq_convert", "truncate"},
        {"uv_convert", "floor"},
        {"uv_plane", "exact"}}},
      {"parallel-gs",
       "parallel-gs gs/shaders/ubershader.comp (compute_combined_color, alpha_blend, shade_resolve), "
       "triangle_setup.comp; rows not read keep the model default",
       {{"tfx_rounding", "floor"},
        {"gouraud_fraction", "truncate_to_8"},
        {"blend_shift", "floor"},
        {"dither_decode", "twos_complement"},
        {"dither_targets", "sixteen_bit_only"},
        {"bilinear", "weighted_sum_4"},
        {"rgb_only_targets", "thirty_two_bit_only"},
        {"texture_buffer", "quarter_page"},
        {"gouraud_setup", "per_pixel_level"},
        {"stq_range", "saturate_2047"},
        {"stq_convert", "floor_1_64"},
        {"uv_convert", "floor_1_64"},
        {"uv_plane", "exact"}}},
  };
  return rows;
}

std::string profile_names() {
  std::string s;
  for (const auto& p : profiles()) s += (s.empty() ? "" : ", ") + std::string(p.name);
  return s;
}

std::optional<std::string> apply_profile(model_options& opts, std::string_view name) {
  for (const auto& p : profiles()) {
    if (p.name != name) continue;
    for (const auto& [option, value] : p.values)
      if (auto err = set_option(opts, option, value)) return "profile " + std::string(name) + ": " + *err;
    return std::nullopt;
  }
  return "unknown profile '" + std::string(name) + "' (one of: " + profile_names() + ")";
}

}  // namespace gs
