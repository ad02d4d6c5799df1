#include "gs_arith/options.hpp"

#include <algorithm>
#include <iterator>

namespace gs {

const std::vector<option_info>& option_catalogue() {
  static const std::vector<option_info> rows = {
      {"tfx_rounding",
       {"floor", "truncate"},
       "floor: PCSX2 SW + DobieStation; truncate: PCSX2 HW shaders (tfx_ps_tfx.inc). No HW test beyond 0x80*0x80."},
      {"gouraud_fraction",
       {"keep_fraction", "truncate_to_8"},
       "keep_fraction: PCSX2 SW (Ct*Cf_8.7)>>14; truncate_to_8: DobieStation. Unconfirmed on HW."},
      {"blend_shift",
       {"floor", "truncate"},
       "floor: HW-confirmed (486/486 ps2autotests); truncate: what-if, 24 HW mismatches."},
      {"dither_decode",
       {"twos_complement", "sign_magnitude", "inverted_magnitude"},
       "twos_complement: PCSX2 (GSRegs.h s32 DM00:3); sign_magnitude: DobieStation 3a23544b; inverted_magnitude: "
       "DobieStation 68dd073e (issue 17). Unconfirmed on HW."},
      {"dither_targets",
       {"sixteen_bit_only", "all_formats"},
       "sixteen_bit_only: PCSX2 SW; all_formats: DobieStation. Unconfirmed on HW."},
      {"bilinear",
       {"weighted_sum_4", "lerp16_4", "nearest"},
       "weighted_sum_4: DobieStation (Play!, parallel-gs in float) (3 sources); lerp16_4: PCSX2 SW 4-bit weights (1); "
       "nearest: filtering off. Unconfirmed on HW."},
      {"rgb_only_targets",
       {"thirty_two_bit_only", "all_formats"},
       "thirty_two_bit_only: PCSX2 GetAFAIL(FRAME.PSM), PR 9652; all_formats: Play! Vulkan, DobieStation 3a23544b. "
       "No recording here."},
      {"texture_buffer",
       {"quarter_page", "per_fragment", "page", "draw_snapshot"},
       "quarter_page: Mikkelsen 2004 section 3.4; draw_snapshot: PCSX2 SW; per_fragment, page: what-ifs. Unconfirmed "
       "on HW."},
      {"gouraud_setup",
       {"per_pixel_floor", "per_pixel", "plane_steps", "pcsx2_rows_4", "pcsx2_rows_8", "per_pixel_level"},
       "per_pixel_floor: DobieStation 68dd073e render_half_triangle (vtx_color.r = vtx.r), Play! Vulkan "
       "int(color * 255) (float) (2 sources); per_pixel: the distance from vertex 0 truncated, no source; "
       "plane_steps: a fixed-point DDA with 8.7 steps, no source; pcsx2_rows_4/8: PCSX2 SW DrawTriangleSection + "
       "SetupPrim (1); per_pixel_level: parallel-gs ubershader.comp (1). No recording here."},
      {"stq_range",
       {"saturate_2047", "x86_int32"},
       "saturate_2047: parallel-gs sample_texture, PCSX2 PR #12201 (reported HW tests) (2 sources); x86_int32: PCSX2 "
       "SW cvttps2dq, DobieStation (int) cast (2, inference from their code). No recording here."},
      {"stq_convert",
       {"truncate", "floor_1_64", "trunc_16_16"},
       "truncate: DobieStation render_half_triangle, PCSX2 PR #14078 HW tests with Q = 1 (2 sources); floor_1_64: "
       "parallel-gs (1); trunc_16_16: PCSX2 SW SampleTexture (1). No recording here with Q other than 1."},
      {"uv_convert",
       {"floor", "floor_1_64"},
       "floor: no bias before the floor of the interpolated UV (PCSX2 SW, DobieStation, Play!: their own "
       "interpolation floored or truncated); floor_1_64: parallel-gs sample_texture floor(uv*16 + 1/64) "
       "(UV_EPSILON_PRE_SNAP) (1). No recording here of an interpolated UV near a texel boundary."},
      {"uv_plane",
       {"exact", "fixed_16"},
       "exact: the rational UV at the pixel centre; DobieStation render_half_triangle (float32 steps), Play! "
       "(GPU float), parallel-gs compute_combined_color (float barycentrics) (3 sources, each up to its float "
       "rounding); fixed_16: 16 fraction bits, floored gradients, nearest to PCSX2 SW's 16.16 steps (1). No "
       "recording here of an interpolated UV near a texel boundary."},
  };
  return rows;
}

namespace {
// gouraud_setup's names in enumerator order.
constexpr std::string_view setup_names[] = {"plane_steps",  "per_pixel",       "pcsx2_rows_4",
                                            "pcsx2_rows_8", "per_pixel_level", "per_pixel_floor"};
template <typename E>
bool pick(E& field, std::string_view value, std::string_view a, E ea, std::string_view b, E eb) {
  if (value == a) {
    field = ea;
    return true;
  }
  if (value == b) {
    field = eb;
    return true;
  }
  return false;
}
template <typename E>
bool pick(E& field, std::string_view value, std::string_view a, E ea, std::string_view b, E eb, std::string_view c,
          E ec) {
  if (value == c) {
    field = ec;
    return true;
  }
  return pick(field, value, a, ea, b, eb);
}
}  // namespace

std::optional<std::string> set_option(model_options& o, std::string_view name, std::string_view value) {
  bool ok = false;
  if (name == "tfx_rounding")
    ok = pick(o.tfx, value, "floor", tfx_rounding::floor, "truncate", tfx_rounding::truncate);
  else if (name == "gouraud_fraction")
    ok = pick(o.gouraud, value, "keep_fraction", gouraud_fraction::keep_fraction, "truncate_to_8",
              gouraud_fraction::truncate_to_8);
  else if (name == "blend_shift")
    ok = pick(o.shift, value, "floor", blend_shift::floor, "truncate", blend_shift::truncate);
  else if (name == "dither_decode")
    ok = pick(o.dither, value, "twos_complement", dither_decode::twos_complement, "sign_magnitude",
              dither_decode::sign_magnitude, "inverted_magnitude", dither_decode::inverted_magnitude);
  else if (name == "dither_targets")
    ok = pick(o.dither_on, value, "sixteen_bit_only", dither_targets::sixteen_bit_only, "all_formats",
              dither_targets::all_formats);
  else if (name == "bilinear")
    ok = pick(o.bilinear, value, "lerp16_4", bilinear_mode::lerp16_4, "nearest", bilinear_mode::nearest,
              "weighted_sum_4", bilinear_mode::weighted_sum_4);
  else if (name == "rgb_only_targets")
    ok = pick(o.rgb_only, value, "thirty_two_bit_only", rgb_only_targets::thirty_two_bit_only, "all_formats",
              rgb_only_targets::all_formats);
  else if (name == "texture_buffer")
    ok = pick(o.tex_buffer, value, "quarter_page", texture_buffer::quarter_page, "per_fragment",
              texture_buffer::per_fragment) ||
         pick(o.tex_buffer, value, "page", texture_buffer::page, "draw_snapshot", texture_buffer::draw_snapshot);
  else if (name == "stq_range")
    ok = pick(o.stq_range, value, "saturate_2047", stq_range_mode::saturate_2047, "x86_int32",
              stq_range_mode::x86_int32);
  else if (name == "stq_convert")
    ok = pick(o.stq_convert, value, "truncate", stq_convert_mode::truncate, "floor_1_64", stq_convert_mode::floor_1_64,
              "trunc_16_16", stq_convert_mode::trunc_16_16);
  else if (name == "uv_convert")
    ok = pick(o.uv_convert, value, "floor", uv_convert_mode::floor, "floor_1_64", uv_convert_mode::floor_1_64);
  else if (name == "uv_plane")
    ok = pick(o.uv_plane, value, "exact", uv_plane_mode::exact, "fixed_16", uv_plane_mode::fixed_16);
  else if (name == "gouraud_setup") {
    for (int k = 0; k < static_cast<int>(std::size(setup_names)); ++k)
      if (value == setup_names[k]) o.setup = static_cast<gouraud_setup>(k), ok = true;
  } else {
    std::string known;
    for (const auto& row : option_catalogue()) known += (known.empty() ? "" : ", ") + std::string(row.name);
    return "unknown model option '" + std::string(name) + "' (known: " + known + ")";
  }
  if (ok) return std::nullopt;
  const auto& rows = option_catalogue();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const option_info& r) { return r.name == name; });
  std::string values;
  for (auto v : it->values) values += (values.empty() ? "" : ", ") + std::string(v);
  return "bad value '" + std::string(value) + "' for model option " + std::string(name) + " (one of: " + values + ")";
}

std::string_view option_value(const model_options& o, std::string_view name) {
  if (name == "tfx_rounding") return o.tfx == tfx_rounding::floor ? "floor" : "truncate";
  if (name == "gouraud_fraction")
    return o.gouraud == gouraud_fraction::keep_fraction ? "keep_fraction" : "truncate_to_8";
  if (name == "blend_shift") return o.shift == blend_shift::floor ? "floor" : "truncate";
  if (name == "dither_decode")
    return o.dither == dither_decode::twos_complement  ? "twos_complement"
           : o.dither == dither_decode::sign_magnitude ? "sign_magnitude"
                                                       : "inverted_magnitude";
  if (name == "dither_targets")
    return o.dither_on == dither_targets::sixteen_bit_only ? "sixteen_bit_only" : "all_formats";
  if (name == "bilinear")
    return o.bilinear == bilinear_mode::lerp16_4  ? "lerp16_4"
           : o.bilinear == bilinear_mode::nearest ? "nearest"
                                                  : "weighted_sum_4";
  if (name == "rgb_only_targets")
    return o.rgb_only == rgb_only_targets::thirty_two_bit_only ? "thirty_two_bit_only" : "all_formats";
  if (name == "texture_buffer") {
    constexpr std::string_view names[] = {"quarter_page", "per_fragment", "page", "draw_snapshot"};
    return names[static_cast<int>(o.tex_buffer)];
  }
  if (name == "gouraud_setup") return setup_names[static_cast<int>(o.setup)];
  if (name == "stq_range") return o.stq_range == stq_range_mode::saturate_2047 ? "saturate_2047" : "x86_int32";
  if (name == "stq_convert") {
    constexpr std::string_view names[] = {"truncate", "floor_1_64", "trunc_16_16"};
    return names[static_cast<int>(o.stq_convert)];
  }
  if (name == "uv_convert") return o.uv_convert == uv_convert_mode::floor ? "floor" : "floor_1_64";
  if (name == "uv_plane") return o.uv_plane == uv_plane_mode::exact ? "exact" : "fixed_16";
  return {};
}

}  // namespace gs
