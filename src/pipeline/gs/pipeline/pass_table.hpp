// pipeline/pass_table.hpp — the one description of the methods' passes: the depth test of every pass
// (its register set, pass_regs, is gs_methods/pass_registers.hpp's, which proofs/methods.hpp runs for
// the claims), the per-vertex colour and texture
// coordinates each triangle pass sends, and each method as data: its light passes in draw order
// (method_passes, at the end). frame_program.cpp puts that list into the frame's operations, which
// render.cpp executes on the value and the memory path and frame_packets.cpp writes as GIF packets (TEX0_1.TFX/TCC,
// PRIM.TME/ABE, ALPHA_1, COLCLAMP, FRAME_1.FBMSK; RGBAQ, UV per vertex) and gs_inputs.cpp builds the palettes it names,
// so none of them can disagree on a pass.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>

#include "gs_arith/colour.hpp"
#include "gs_arith/depth_test.hpp"
#include "gs_arith/perspective.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/gs_inputs.hpp"
#include "gs_methods/pass_registers.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/method.hpp"
#include "pipeline/prepare.hpp"

namespace gsdot3::pipeline::passes {

// The register sets of the passes and their constants: gs_methods/pass_registers.hpp (the proofs' methods.hpp
// composes the same sets).
using namespace ::gsdot3::gs_methods;

using gs::blend_alpha;
using gs::blend_colour;

inline gs::rgba8 rgb(int r, int g, int b, int a) {
  return {gs::u8::from_wrapped(r), gs::u8::from_wrapped(g), gs::u8::from_wrapped(b), gs::u8::from_wrapped(a)};
}
inline const gs::rgba8 white = rgb(0x80, 0x80, 0x80, 0x80);

// The vertex colours of the triangle passes (RGBAQ), from the light's per-vertex data.
// Two-pass (section 3.5): the tolight vector · fade_att packed as signed chars of scale s.
inline gs::rgba8 two_pass_colour(const light_vertex& l, int s) { return pack_tolight(l.T * l.fade, s); }
// Four-pass sphere pass, HIGHLIGHT: sph·scale + (1 − scale)·128 with scale = fade_att in 1/128.
inline gs::rgba8 four_pass_sphere_colour(const light_vertex& l) {
  const int scale = std::clamp(static_cast<int>(std::lround(l.fade * 128.0f)), 0, 128);
  return rgb(scale, scale, scale, 128 - scale);
}
// Gouraud (section 4, figure 6b): the VU1's per-vertex diffuse term max(N·T·fade, 0) with the
// interpolated vertex normal N = (0, 0, 1) in tangent space, i.e. max(T_z·fade, 0), as
// 128 + nearest(127·max(T_z·fade, 0)) in red and 0 in green and blue, so the post filter's r + g + b
// is the dot product + 128 like the DOT3 methods' (clamped per vertex, as traditional lighting does).
inline gs::rgba8 gouraud_colour(const light_vertex& l) {
  return rgb(128 + nearest(std::clamp(l.T.z * l.fade, 0.0f, 1.0f) * 127), 0, 0, 0x80);
}
// Baseline (section 2): TL_pos / TL_neg = nearest(127·max(±T·fade, 0)) per component, alpha 0x80.
inline gs::rgba8 baseline_colour(const light_vertex& l, bool negative) {
  const glm::vec3 t = l.T * l.fade * (negative ? -1.0f : 1.0f);
  return rgb(nearest(std::max(t.x, 0.0f) * 127), nearest(std::max(t.y, 0.0f) * 127), nearest(std::max(t.z, 0.0f) * 127),
             0x80);
}

// Step 5 (section 3.1): a non-normal-mapped vertex's Gouraud light (prepared_scene::plain_light) as
// RGBAQ, nearest per channel and clamped to 255, alpha 0x80.
inline gs::rgba8 plain_colour(const glm::vec3& light) {
  auto channel = [](float c) { return nearest(std::clamp(c, 0.0f, 255.0f)); };
  return rgb(channel(light.x), channel(light.y), channel(light.z), 0x80);
}

// The texture coordinates (UV, 12.4 texels) per triangle corner: the normal map's, or the 64×64
// sphere map's from the vertex's tolight vector.
inline std::array<std::int32_t, 2> normal_map_uv(const prepared_triangle& t, int k) {
  return t.uv16[static_cast<std::size_t>(k)];
}
inline std::array<std::int32_t, 2> sphere_uv(const light_vertex& l) {
  const st c = sphere_coordinates(l.T);
  return {static_cast<std::int32_t>(std::lround(c.s * 64 * 16)), static_cast<std::int32_t>(std::lround(c.t * 64 * 16))};
}

// ---- The methods as data ----------------------------------------------------------------------
// What a light pass samples: the normal map through palette `clut`; the 64×64 sphere map of the
// vertex tolight vectors (four-pass, section 3.6); the DPB's own alpha byte read as PSMT8H through
// palette `clut`, one sprite over the sprite area (two-pass step 2.4a, section 3.5); or nothing
// (untextured triangles, TME = 0: Gouraud).
enum class pass_source : std::uint8_t { normal_map, sphere_map, dpb_alpha, untextured };
// What a triangle pass sends per vertex as RGBAQ (the functions above).
enum class vertex_colour : std::uint8_t { tolight, sphere_fade, white, tl_pos, tl_neg, gouraud };
inline constexpr std::size_t vertex_colour_count = 6;
// One pass of step 2.3 (or its post pass 2.4a), drawn per light into the DPB.
struct light_pass {
  const pass_regs* regs;
  pass_source source;
  clut_slot clut;          // normal_map, dpb_alpha
  vertex_colour colour;    // triangle passes
  std::string_view label;  // the trace's (pass_record::label): the paper's step and what it does
};
// How the palettes of the normal map's 256 normals are built (gs_inputs.cpp's make_inputs): the
// two-pass Max(±n, 0) pair (slots pos, neg), the 2002 method's signed sides (pos, neg), or the
// four-pass per-axis reordered palettes (axis_x .. axis_z).
// The three-pass method has the two-pass pair and the terms palette (slot terms); Gouraud samples no
// normal map (none).
enum class palette_kind : std::uint8_t { two_pass, signed_side, reordered_axes, three_pass, none };
// A method: its palettes and its light passes in draw order. Steps 1, 2.1, 2.4 (R += G, R += B),
// 2.5/2.6 (the ILP into the LAB), 3 and 4 are the same for every method (section 3.1).
template <std::size_t N>
struct method_passes {
  method m;
  palette_kind palettes;
  std::array<light_pass, N> light;
};

// Two-pass (section 3.5): Max(n, 0)·l − Max(−n, 0)·l, then n'_a added into R, G and B.
inline constexpr method_passes<3> two_pass_method{method::two_pass,
                                                  palette_kind::two_pass,
                                                  {{
                                                      {&two_pass_positive, pass_source::normal_map, clut_slot::pos,
                                                       vertex_colour::tolight, "2.3 Max(n,0)·l (MODULATE)"},
                                                      {&two_pass_negative, pass_source::normal_map, clut_slot::neg,
                                                       vertex_colour::tolight, "2.3 − Max(−n,0)·l (MODULATE, Cd − Cs)"},
                                                      {&two_pass_add_alpha, pass_source::dpb_alpha, clut_slot::grey,
                                                       vertex_colour::white, "2.4a + n'a (PSMT8H of the DPB alpha)"},
                                                  }}};
// Three-pass (section 3.5, "adding the terms as a separate additive pass"): two-pass's passes 1 and 2,
// then 128 + Max(−n, 0) − Max(n, 0) added per channel from the terms palette, so the post filter is
// r + g + b alone and n_a is never divided by three. Pass 2 still writes n'_a into the DPB alpha
// (two_pass_negative's TCC = RGBA), which nothing reads.
inline constexpr method_passes<3> three_pass_method{
    method::three_pass,
    palette_kind::three_pass,
    {{
        {&two_pass_positive, pass_source::normal_map, clut_slot::pos, vertex_colour::tolight,
         "2.3 Max(n,0)·l (MODULATE)"},
        {&two_pass_negative, pass_source::normal_map, clut_slot::neg, vertex_colour::tolight,
         "2.3 − Max(−n,0)·l (MODULATE, Cd − Cs)"},
        {&three_pass_add_terms, pass_source::normal_map, clut_slot::terms, vertex_colour::white,
         "2.3 + (128 + Max(−n,0) − Max(n,0)) (DECAL, Cs + Cd)"},
    }}};
// Gouraud (section 4, figure 6b; the non-normal-mapped geometry of step 5 and section 3.8): one
// untextured pass of the per-vertex dot products, then the same post filter and ILP as the others.
inline constexpr method_passes<1> gouraud_method{
    method::gouraud,
    palette_kind::none,
    {{
        {&gouraud_dot, pass_source::untextured, clut_slot::pos /* unused */, vertex_colour::gouraud,
         "2.3 Gouraud: per-vertex max(N·T, 0) (no texture)"},
    }}};
// Four-pass (section 3.6): the sphere map · fade, then (Cs − Cd)·As + Cd per axis into R, G, B.
inline constexpr method_passes<4> four_pass_method{
    method::four_pass,
    palette_kind::reordered_axes,
    {{
        {&four_pass_sphere, pass_source::sphere_map, clut_slot::pos /* unused */, vertex_colour::sphere_fade,
         "2.3 sphere map · fade (HIGHLIGHT)"},
        {&four_pass_x, pass_source::normal_map, clut_slot::axis_x, vertex_colour::white,
         "2.3 R: x multiply (Cs − Cd)·As + Cd"},
        {&four_pass_y, pass_source::normal_map, clut_slot::axis_y, vertex_colour::white,
         "2.3 G: y multiply (Cs − Cd)·As + Cd"},
        {&four_pass_z, pass_source::normal_map, clut_slot::axis_z, vertex_colour::white,
         "2.3 B: z multiply (Cs − Cd)·As + Cd"},
    }}};
// The 2002 method (section 2): NM_pos·TL_pos + NM_neg·TL_neg − NM_neg·TL_pos − NM_pos·TL_neg.
inline constexpr method_passes<4> baseline_method{
    method::baseline,
    palette_kind::signed_side,
    {{
        {&baseline_add, pass_source::normal_map, clut_slot::pos, vertex_colour::tl_pos, "2.3 + NM_pos·TL_pos"},
        {&baseline_add, pass_source::normal_map, clut_slot::neg, vertex_colour::tl_neg, "2.3 + NM_neg·TL_neg"},
        {&baseline_subtract, pass_source::normal_map, clut_slot::neg, vertex_colour::tl_pos, "2.3 − NM_neg·TL_pos"},
        {&baseline_subtract, pass_source::normal_map, clut_slot::pos, vertex_colour::tl_neg, "2.3 − NM_pos·TL_neg"},
    }}};

// f.template operator()<D>() with D the method's method_passes (a constant, so a renderer can
// instantiate its pixel loops per pass register set); the only switch over the GS methods.
template <class F>
constexpr decltype(auto) with_method(method m, F&& f) {
  switch (m) {
    case method::two_pass: return f.template operator()<two_pass_method>();
    case method::four_pass: return f.template operator()<four_pass_method>();
    case method::baseline: return f.template operator()<baseline_method>();
    case method::three_pass: return f.template operator()<three_pass_method>();
    case method::gouraud: return f.template operator()<gouraud_method>();
  }
  throw std::logic_error("unknown GS method");  // an enum value outside the list: a bug, not input
}
struct method_view {
  palette_kind palettes;
  std::span<const light_pass> light;
};
inline method_view describe(method m) {
  return with_method(
      m, []<const auto & D>() {
        return method_view{D.palettes, D.light};
      });
}

// Section 3.6's spot light: triangle t's S, T, Q in the light's projection
// (prepare.hpp's spots), or S = T = 0, Q = 1 (texel (0, 0), a border texel: no light) when a vertex is
// behind the light; and every triangle's sampler of the spot_map_size² texture (nothing for a light
// that is not a spot light).
inline std::array<gs::stq, 3> spot_stq(const prepared_scene& ps, std::size_t light, const prepared_triangle& t) {
  const auto& sv = ps.spots[light];
  std::array<gs::stq, 3> a{};
  const bool front = sv[t.vertex[0]].front && sv[t.vertex[1]].front && sv[t.vertex[2]].front;
  for (std::size_t k = 0; k < 3; ++k) {
    const spot_vertex& v = sv[t.vertex[k]];
    a[k] = front ? gs::stq{v.S, v.T, v.Q} : gs::stq{0.0f, 0.0f, 1.0f};
  }
  return a;
}
inline constexpr auto spot_size_log2 = static_cast<unsigned>(std::bit_width(static_cast<unsigned>(spot_map_size)) - 1);
inline std::vector<gs::stq_sampler> spot_samplers(const prepared_scene& ps, std::size_t light,
                                                  const gs::model_options& o) {
  std::vector<gs::stq_sampler> out;
  if (!ps.spot(light)) return out;
  out.reserve(ps.triangles.size());
  for (const prepared_triangle& t : ps.triangles)
    out.push_back(
        gs::make_stq_sampler({t.setup.v, t.setup.area2, spot_stq(ps, light, t)}, spot_size_log2, spot_size_log2, o));
  return out;
}

// A light pass's vertex colour and texture coordinates at corner k of triangle t (lv: the light's
// per-vertex data, s: the two-pass tolight scale).
inline gs::rgba8 vertex_rgbaq(vertex_colour c, const light_vertex& l, int s) {
  switch (c) {
    case vertex_colour::tolight: return two_pass_colour(l, s);
    case vertex_colour::sphere_fade: return four_pass_sphere_colour(l);
    case vertex_colour::white: return white;
    case vertex_colour::tl_pos: return baseline_colour(l, false);
    case vertex_colour::tl_neg: return baseline_colour(l, true);
    case vertex_colour::gouraud: return gouraud_colour(l);
  }
  return white;
}
inline std::array<std::int32_t, 2> vertex_uv(pass_source src, const prepared_triangle& t, int k,
                                             const std::vector<light_vertex>& lv) {
  return src == pass_source::sphere_map ? sphere_uv(lv[t.vertex[static_cast<std::size_t>(k)]]) : normal_map_uv(t, k);
}

}  // namespace gsdot3::pipeline::passes
