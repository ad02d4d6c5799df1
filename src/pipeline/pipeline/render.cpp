// pipeline/render.cpp — the pass sequences of the three methods, run over horizontal frame bands.
//
// Register level (through gs::pixel_pipeline and the gs_arith units, see gs_pass.hpp): every triangle pass (step 1, 2.3, 3), the
// clear values, the two-pass alpha post pass (PSMT8H reads the DPB's own alpha byte at the same
// pixel: gs::t8h_index), the ILP look-up × light colour added into the LAB, the diffuse pass and
// the per-channel blend of the multiply.
// Value level (composed here, not through GS memory): the channel fetch of the R+G+B post filter
// (the GS reads the DPB as PSMT8 with swizzled sprites, section 3.3, so that a texel is one byte of
// the 32-bit pixel; here the byte is taken from the same pixel's word directly), the ILP's read of
// the summed byte, and in step 4 the LAB channel moved into the destination alpha that the
// multiply blends with (C = Ad). The PSMT8 swizzle tables themselves are not modelled.
#include "pipeline/render.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "pipeline/band_renderer.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/gs_pass.hpp"

namespace gsdot3::pipeline {

std::string_view name(method m) {
  switch (m) {
    case method::two_pass: return "two-pass";
    case method::four_pass: return "four-pass";
    case method::baseline: return "baseline";
  }
  return "?";
}

namespace {

using namespace detail;
using gs::blend_alpha;
using gs::blend_colour;

constexpr std::uint32_t clear_dpb = 0x00808080u;        // step 2.1
constexpr std::uint32_t keep_alpha = 0xFF000000u;       // FBMSK: write RGB only
constexpr std::uint32_t only_channel[3] = {0xFFFFFF00u, 0xFFFF00FFu, 0xFF00FFFFu};  // FBMSK: R, G, B only

gs::u8 byte(int v) { return gs::u8::from_wrapped(v); }

// ALPHA_1 settings used by the methods.
constexpr gs::alpha_reg add_source{blend_colour::Cs, blend_colour::zero, blend_alpha::FIX, blend_colour::Cd,
                                   gs::u8::literal(0x80)};  // Cs + Cd
constexpr gs::alpha_reg subtract_source{blend_colour::Cd, blend_colour::Cs, blend_alpha::FIX, blend_colour::zero,
                                        gs::u8::literal(0x80)};  // Cd − Cs
constexpr gs::alpha_reg signed_multiply{blend_colour::Cs, blend_colour::Cd, blend_alpha::As, blend_colour::Cd,
                                        gs::u8{}};  // (Cs − Cd)·As + Cd, section 3.6
constexpr gs::alpha_reg multiply_by_ad{blend_colour::Cs, blend_colour::zero, blend_alpha::Ad, blend_colour::zero,
                                       gs::u8{}};  // Cs·Ad, step 4

// The register sets of the passes. Each is a constant the pass loops are instantiated with, so the
// compiler folds gs::pixel_pipeline for it (the same model function, specialised, not a copy).
//                                              TME    ABE    TFX                 TCC             ALPHA_1          CLAMP  FBMSK
constexpr pass_regs two_pass_positive{          true,  false, gs::tfx::MODULATE,  gs::tcc::RGB,   {},              false, 0};
constexpr pass_regs two_pass_negative{          true,  true,  gs::tfx::MODULATE,  gs::tcc::RGBA,  subtract_source, false, 0};
constexpr pass_regs two_pass_add_alpha{         true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   add_source,      false, keep_alpha};
constexpr pass_regs four_pass_sphere{           true,  false, gs::tfx::HIGHLIGHT, gs::tcc::RGB,   {},              false, keep_alpha};
constexpr pass_regs four_pass_x{                true,  true,  gs::tfx::DECAL,     gs::tcc::RGBA,  signed_multiply, false, only_channel[0]};
constexpr pass_regs four_pass_y{                true,  true,  gs::tfx::DECAL,     gs::tcc::RGBA,  signed_multiply, false, only_channel[1]};
constexpr pass_regs four_pass_z{                true,  true,  gs::tfx::DECAL,     gs::tcc::RGBA,  signed_multiply, false, only_channel[2]};
constexpr pass_regs baseline_add{               true,  true,  gs::tfx::MODULATE,  gs::tcc::RGB,   add_source,      false, keep_alpha};
constexpr pass_regs baseline_subtract{          true,  true,  gs::tfx::MODULATE,  gs::tcc::RGB,   subtract_source, false, keep_alpha};
constexpr pass_regs post_add_into_red{          true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   add_source,      false, only_channel[0]};
constexpr pass_regs ilp_into_lab{               true,  true,  gs::tfx::MODULATE,  gs::tcc::RGB,   add_source,      true,  keep_alpha};
constexpr pass_regs diffuse_layer{              true,  false, gs::tfx::DECAL,     gs::tcc::RGB,   {},              true,  0};
constexpr pass_regs multiply_red{               true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   multiply_by_ad,  true,  only_channel[0]};
constexpr pass_regs multiply_green{             true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   multiply_by_ad,  true,  only_channel[1]};
constexpr pass_regs multiply_blue{              true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   multiply_by_ad,  true,  only_channel[2]};

// The textures and palettes, built once per frame (VU1/tool side).
struct gs_inputs {
  const normal_map* nm = nullptr;
  gs::clut_buffer pos, neg, axis[3], ilp, grey;
  std::vector<std::uint32_t> sphere;
  const texture32* diffuse = nullptr;
};

gs_inputs make_inputs(const scene& s, method m, const render_options& o) {
  gs_inputs in;
  in.nm = &s.normals;
  in.diffuse = &s.diffuse;
  in.ilp = intensity_palette(o.specular_power);
  in.grey = identity_palette();
  switch (m) {
    case method::two_pass:
      in.pos = two_pass_palette(s.normals.palette, false);
      in.neg = two_pass_palette(s.normals.palette, true);
      break;
    case method::four_pass:
      for (int a = 0; a < 3; ++a) in.axis[a] = reordered_palette(s.normals.palette, a);
      in.sphere = sphere_map(64, 64);
      break;
    case method::baseline:
      in.pos = signed_side_palette(s.normals.palette, false);
      in.neg = signed_side_palette(s.normals.palette, true);
      break;
  }
  return in;
}

std::array<std::int32_t, 2> normal_map_uv(const prepared_triangle& t, int k) { return t.uv16[static_cast<std::size_t>(k)]; }

gs::rgba8 rgb(int r, int g, int b, int a) { return {byte(r), byte(g), byte(b), byte(a)}; }

struct frame_buffers {
  std::vector<std::uint32_t> z, lab, dpb, diff, out;
};

std::size_t render_band(const scene& s, const prepared_scene& ps, method m, const render_options& o, const gs_inputs& in,
                        scissor band, frame_buffers& fb, frame& result) {
  band_renderer r(ps, o, band, fb.z, result.visible_triangle);
  // Tracing (render_options::trace, one band): after each pass, its target buffer and inputs.
  pass_record pending;
  const std::size_t frame_pixels = fb.dpb.size();
  auto open_pass = [&] {
    pending = {{}, -1, {}, {}, std::vector<std::uint32_t>(frame_pixels), std::vector<std::uint16_t>(4 * frame_pixels),
               std::vector<std::uint8_t>(frame_pixels)};
  };
  auto note = [&](const char* label, int light, const char* target, const std::vector<std::uint32_t>& buffer) {
    if (o.trace == nullptr) return;
    pending.label = label, pending.light = light, pending.target = target, pending.word = buffer;
    o.trace->push_back(std::move(pending));
    open_pass();
  };
  if (o.trace != nullptr) open_pass(), r.pending = &pending;
  r.depth_and_ambient(fb.lab, rgb(s.ambient[0], s.ambient[1], s.ambient[2], 0x80));
  note("1 Z and ambient", -1, "LAB", fb.lab);

  const gs::bilinear_mode filter = o.bilinear ? o.model.bilinear : gs::bilinear_mode::nearest;
  auto nm_texture = [&](const gs::clut_buffer& clut) {
    return texture_ref{in.nm->width, in.nm->height, in.nm->index.data(), &clut, nullptr, false, filter};
  };
  const gs::rgba8 white = rgb(0x80, 0x80, 0x80, 0x80);
  auto flat_white = [&](std::uint32_t) { return white; };
  auto dpb_byte = [&](int channel) {  // value-level channel fetch (see the file comment)
    return [&fb, &in, channel](std::size_t i) { return gs::clut_t8(in.grey, byte(static_cast<int>(fb.dpb[i] >> (8 * channel)))); };
  };

  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    const std::vector<light_vertex>& lv = ps.lights[l];
    // 2.1 (the DPB starts cleared; nothing is drawn outside the sprite area); 2.2 COLCLAMP = 0 in
    // every pass of 2.3 and 2.4.
    r.fill(fb.dpb, clear_dpb, false);
    const int li = static_cast<int>(l);
    note("2.1 clear 0x00808080", li, "DPB", fb.dpb);
    switch (m) {
      case method::two_pass: {
        const auto attr = attributes(ps, [&](std::uint32_t v) { return pack_tolight(lv[v].T * lv[v].fade, o.s); }, normal_map_uv);
        const texture_ref pos = nm_texture(in.pos), neg = nm_texture(in.neg);
        r.draw<two_pass_positive>(&pos, attr, fb.dpb);
        note("2.3 Max(n,0)·l (MODULATE)", li, "DPB", fb.dpb);
        r.draw<two_pass_negative>(&neg, attr, fb.dpb);
        note("2.3 − Max(−n,0)·l (MODULATE, Cd − Cs)", li, "DPB", fb.dpb);
        // 2.4a: n'_a into R, G and B: the DPB read as PSMT8H (its own alpha byte) through a grey CLUT.
        r.sprite<two_pass_add_alpha>(white,
                 [&](std::size_t i) { return gs::clut_t8(in.grey, gs::t8h_index(fb.dpb[i])); }, fb.dpb);
        note("2.4a + n'a (PSMT8H of the DPB alpha)", li, "DPB", fb.dpb);
        break;
      }
      case method::four_pass: {
        const auto pass1 = attributes(
            ps,
            [&](std::uint32_t v) {
              const int scale = std::clamp(static_cast<int>(std::lround(lv[v].fade * 128.0f)), 0, 128);
              return rgb(scale, scale, scale, 128 - scale);  // HIGHLIGHT: sph·scale + (1 − scale)·128
            },
            [&](const prepared_triangle& t, int k) {
              const st c = sphere_coordinates(lv[t.vertex[static_cast<std::size_t>(k)]].T);
              return std::array<std::int32_t, 2>{static_cast<std::int32_t>(std::lround(c.s * 64 * 16)),
                                                 static_cast<std::int32_t>(std::lround(c.t * 64 * 16))};
            });
        const texture_ref sphere{64, 64, nullptr, nullptr, in.sphere.data(), true, gs::bilinear_mode::nearest};
        r.draw<four_pass_sphere>(&sphere, pass1, fb.dpb);
        note("2.3 sphere map · fade (HIGHLIGHT)", li, "DPB", fb.dpb);
        const auto attr = attributes(ps, flat_white, normal_map_uv);
        const texture_ref x = nm_texture(in.axis[0]), y = nm_texture(in.axis[1]), z = nm_texture(in.axis[2]);
        r.draw<four_pass_x>(&x, attr, fb.dpb);
        note("2.3 R: x multiply (Cs − Cd)·As + Cd", li, "DPB", fb.dpb);
        r.draw<four_pass_y>(&y, attr, fb.dpb);
        note("2.3 G: y multiply (Cs − Cd)·As + Cd", li, "DPB", fb.dpb);
        r.draw<four_pass_z>(&z, attr, fb.dpb);
        note("2.3 B: z multiply (Cs − Cd)·As + Cd", li, "DPB", fb.dpb);
        break;
      }
      case method::baseline: {
        auto side = [&](bool negative) {
          return attributes(
              ps,
              [&, negative](std::uint32_t v) {
                const glm::vec3 t = lv[v].T * lv[v].fade * (negative ? -1.0f : 1.0f);
                return rgb(nearest(std::max(t.x, 0.0f) * 127), nearest(std::max(t.y, 0.0f) * 127),
                           nearest(std::max(t.z, 0.0f) * 127), 0x80);
              },
              normal_map_uv);
        };
        const auto tl_pos = side(false), tl_neg = side(true);
        const texture_ref pos = nm_texture(in.pos), neg = nm_texture(in.neg);
        r.draw<baseline_add>(&pos, tl_pos, fb.dpb);       // NM_pos·TL_pos
        note("2.3 + NM_pos·TL_pos", li, "DPB", fb.dpb);
        r.draw<baseline_add>(&neg, tl_neg, fb.dpb);       // NM_neg·TL_neg
        note("2.3 + NM_neg·TL_neg", li, "DPB", fb.dpb);
        r.draw<baseline_subtract>(&neg, tl_pos, fb.dpb);  // −NM_neg·TL_pos
        note("2.3 − NM_neg·TL_pos", li, "DPB", fb.dpb);
        r.draw<baseline_subtract>(&pos, tl_neg, fb.dpb);  // −NM_pos·TL_neg
        note("2.3 − NM_pos·TL_neg", li, "DPB", fb.dpb);
        break;
      }
    }
    // 2.4: R += G, R += B (mod 256): additive sprites writing red only.
    r.sprite<post_add_into_red>(white, dpb_byte(1), fb.dpb);
    note("2.4 R += G", li, "DPB", fb.dpb);
    r.sprite<post_add_into_red>(white, dpb_byte(2), fb.dpb);
    note("2.4 R += B (the post-filter sum)", li, "DPB", fb.dpb);
    for (int y = band.y0; y < band.y1; ++y)
      for (int x = band.x0; x < band.x1; ++x) result.dot[l][r.index(x, y)] = static_cast<std::uint8_t>(fb.dpb[r.index(x, y)] & 0xFF);
    // 2.5, 2.6: COLCLAMP = 1; ILP[sum] × light colour (MODULATE) added into the LAB.
    const auto& lc = s.lights[l].colour;
    r.sprite<ilp_into_lab>(rgb(lc[0], lc[1], lc[2], 0x80),
             [&](std::size_t i) { return gs::clut_t8(in.ilp, byte(static_cast<int>(fb.dpb[i] & 0xFF))); }, fb.lab);
    note("2.6 LAB += ILP[sum] × light colour", li, "LAB", fb.lab);
  }

  // Step 3: the unlit diffuse layer.
  r.fill(fb.diff, 0, false);
  const texture_ref diffuse{in.diffuse->width, in.diffuse->height, nullptr, nullptr, in.diffuse->texels.data(), false, filter};
  r.draw<diffuse_layer>(&diffuse, attributes(ps, flat_white, normal_map_uv), fb.diff);
  note("3 diffuse layer", -1, "diffuse", fb.diff);

  // Step 4: diffuse × LAB per channel: (Cs − 0)·Ad >> 7 with the LAB channel in the destination
  // alpha (value level), writing that channel only. Outside the sprite area the LAB and the output
  // are 0.
  const scissor& area = r.sprite_area();
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x) fb.out[r.index(x, y)] = fb.lab[r.index(x, y)];
  auto multiply = [&](int c, auto pass) {
    for (int y = area.y0; y < area.y1; ++y)
      for (int x = area.x0; x < area.x1; ++x) {
        const std::size_t i = r.index(x, y);
        fb.out[i] = (fb.out[i] & 0x00FFFFFFu) | (((fb.lab[i] >> (8 * c)) & 0xFFu) << 24);
      }
    pass(white, [&](std::size_t i) { return gs::rgba8::from_u32(fb.diff[i]); }, fb.out);
  };
  multiply(0, [&](auto&&... a) { r.sprite<multiply_red>(a...); });
  multiply(1, [&](auto&&... a) { r.sprite<multiply_green>(a...); });
  multiply(2, [&](auto&&... a) { r.sprite<multiply_blue>(a...); });
  note("4 diffuse × LAB (R, G, B)", -1, "frame", fb.out);
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x) {
      const std::size_t i = r.index(x, y);
      result.colour[i] = fb.out[i] | 0xFF000000u;
    }
  return r.pixel_ops();
}

}  // namespace

frame render(const scene& s, const prepared_scene& ps, method m, const render_options& o) {
  const gs_inputs in = make_inputs(s, m, o);
  frame result;
  result.width = ps.width;
  result.height = ps.height;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  result.colour.assign(n, 0);
  result.visible_triangle.assign(n, -1);
  result.dot.assign(s.lights.size(), std::vector<std::uint8_t>(n, 0));
  frame_buffers fb{std::vector<std::uint32_t>(n), std::vector<std::uint32_t>(n), std::vector<std::uint32_t>(n, clear_dpb),
                   std::vector<std::uint32_t>(n), std::vector<std::uint32_t>(n)};
  const int bands = o.trace != nullptr ? 1 : std::clamp(o.threads, 1, std::max(1, ps.height));
  std::vector<std::thread> workers;
  std::vector<std::size_t> ops(static_cast<std::size_t>(bands), 0);
  for (int b = 0; b < bands; ++b) {
    const scissor band{0, ps.height * b / bands, ps.width, ps.height * (b + 1) / bands};
    auto& count = ops[static_cast<std::size_t>(b)];
    if (b + 1 == bands) {
      count = render_band(s, ps, m, o, in, band, fb, result);
    } else {
      workers.emplace_back([&, band] { count = render_band(s, ps, m, o, in, band, fb, result); });
    }
  }
  for (std::thread& t : workers) t.join();
  for (std::size_t c : ops) result.pixel_ops += c;
  return result;
}

}  // namespace gsdot3::pipeline
