// pipeline/render.cpp — the pass sequences of the five GS methods, run over horizontal frame bands.
//
// Register level (through gs::pixel_pipeline and the gs_arith units, see gs_pass.hpp): every triangle pass (step
// 1, 2.3, 3), the clear values, the two-pass alpha post pass (PSMT8H reads the DPB's own alpha byte at the same pixel:
// gs::t8h_index), the ILP look-up × light colour added into the LAB, the diffuse pass and the per-channel blend of the
// multiply. Two storage paths (render_options::memory_path):
// - value level (default, the fast path and the oracle): frame buffers are row-major vectors; the
//   channel fetch of the R+G+B post filter (the GS reads the DPB as PSMT8 with swizzled sprites,
//   section 3.3) takes the byte from the same pixel's word directly, as do the ILP's read of the
//   summed byte and step 4's move of a LAB channel into the destination alpha (C = Ad).
// - memory path: every buffer is in the modelled 4 MiB local memory (gs_memory): the DPB at FBP 0
//   (PSMCT32; step 3 draws the diffuse layer into it, as the paper's step 3 says: "We are done with
//   the DPB. Clear it to zero and render all objects unlit"), the LAB at P, the output at 2P (P =
//   pages per buffer) and the Z buffer at ZBP = 3P (PSMZ24, band_renderer.hpp's z_view), the
//   textures from 4P on: at 512×448 that is 4 × 112 of the 512 pages, none overlapping (gs_inputs.hpp's
//   buffer_layout, the packet stream's too). The post
//   filter, the ILP read and step 4's channel move are gs_memory's channel-fetch sprites (the DPB /
//   LAB read as a PSMT8 texture, TBW = 2·FBW, TBP0 per page, CLAMP_1 REGION_REPEAT), each texel
//   through the PSMT8 address function (tabulated: gs_memory/fast_address.hpp, as are the frame
//   buffers' and textures' addresses); the two-pass alpha pass reads the DPB as PSMT8H. The copy of
//   the LAB into the output before step 4 is a local -> local transfer (TRXDIR = 2, gs_inputs.hpp's
//   lab_to_output, which the packet stream writes as A+D): the
//   GS's own copy, no pixel arithmetic, and with SPSM = PSMZ32 it is also the paper's "unswizzle the
//   LAB" of the z-trick-psmz32 mode. The normal map (PSMT8), the sphere map and the diffuse texture
//   (PSMCT32) are uploaded by host -> local transfers and every texel is read from memory; the
//   palettes (incl. the ILP) are uploaded as CSM1 images and loaded into the CLUT buffer by TEX0.CLD
//   (upload_inputs: the GIF packets of gs_inputs.hpp, run through gs_packets' interpreter); a normal
//   map and diffuse texture too big for the memory beside the buffers stream per pass in pieces
//   (texture_stream.hpp, draw_textured; the memory path then draws on one thread). Both paths
//   run the depth test through gs::depth_test.
// render_options::buffers = draw_buffers::one (section 3.1's variant for too little VRAM): the output
// is each light's DPB, the dot layers wait in free alphas (frame_buffers::alpha_plane), and
// one_buffer_steps makes the output the LAB, parks its channels in those alphas and multiplies the
// diffuse layer by them.
// The register sets and vertex values of the passes are pass_table.hpp's, which frame_packets.cpp
// writes as the GIF packet stream of the same frame.
#include "pipeline/render.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>

#include "gs_memory/local_memory.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/channel_pass.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/frame_limits.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/pass_table.hpp"

namespace gsdot3::pipeline {

namespace {

using namespace detail;
using namespace passes;

// Steps 2.6, 3 and 4 of draw_buffers::one, after every light's dot layer is in its free alpha: the
// output becomes the LAB (its R, G, B filled with the ambient, the alphas kept; each light's ILP read
// from its alpha), the LAB's R, G, B move into the free alphas, the diffuse layer (draw_diffuse) is
// drawn into the output's R, G, B, and each channel is multiplied by its alpha read as the texel's:
// Cd·As, the product step 4's Cs·Ad forms in the two-buffer method.
template <class FB, class DrawDiffuse>
void one_buffer_steps(band_renderer& r, const scene& s, const gs_inputs& in, gs::rgba8 ambient, frame_buffers<FB>& fb,
                      DrawDiffuse&& draw_diffuse) {
  r.fill<flat_rgb>(fb.out, ambient.to_u32(), false);
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    const auto& lc = s.lights[l].colour;
    channel_pass<ilp_into_lab>(r, fb, rgb(lc[0], lc[1], lc[2], 0x80), in.ilp, 3, fb.alpha_plane[l], fb.out);
  }
  for (unsigned c = 0; c < 3; ++c)
    channel_pass<move_into_alpha>(r, fb, white, in.alpha_index, c, fb.out, fb.alpha_plane[c]);
  r.fill<flat_rgb>(fb.out, 0, false);
  draw_diffuse();
  channel_pass<multiply_red_by_as>(r, fb, white, in.alpha_index, 3, fb.alpha_plane[0], fb.out);
  channel_pass<multiply_green_by_as>(r, fb, white, in.alpha_index, 3, fb.alpha_plane[1], fb.out);
  channel_pass<multiply_blue_by_as>(r, fb, white, in.alpha_index, 3, fb.alpha_plane[2], fb.out);
}

template <class FB>
std::size_t render_band(const scene& s, const prepared_scene& ps, method m, const render_options& o,
                        const gs_inputs& in, scissor band, frame_buffers<FB>& fb, frame& result) {
  band_renderer r(ps, o, band, fb.zb, result.visible_triangle);
  // Tracing (render_options::trace, one band): after each pass, its target buffer and inputs.
  pass_record pending;
  const std::size_t frame_pixels = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  auto open_pass = [&] {
    pending = {{},
               -1,
               {},
               {},
               std::vector<std::uint32_t>(frame_pixels),
               std::vector<std::uint16_t>(4 * frame_pixels),
               std::vector<std::uint8_t>(frame_pixels)};
  };
  auto note = [&](std::string_view label, int light, const char* target, const FB& buffer) {
    if (o.trace == nullptr) return;
    pending.label = label, pending.light = light, pending.target = target;
    pending.word.resize(frame_pixels);
    for (int y = 0; y < ps.height; ++y)
      for (int x = 0; x < ps.width; ++x) pending.word[r.index(x, y)] = buffer(x, y);
    o.trace->push_back(std::move(pending));
    open_pass();
  };
  if (o.trace != nullptr) open_pass(), r.pending = &pending;
  // draw_buffers::one (section 3.1's variant, method.hpp): the output buffer is every light's DPB,
  // then the LAB; step 1's ambient, drawn there too, is cleared by the first 2.1 (the LAB's ambient
  // is filled in after the lights).
  const bool one = o.buffers == draw_buffers::one;
  const FB& dpb = one ? fb.out : fb.dpb;
  const FB& lab = one ? fb.out : fb.lab;
  const gs::rgba8 ambient = rgb(s.ambient[0], s.ambient[1], s.ambient[2], 0x80);
  r.depth_and_ambient(lab, ambient);
  note("1 Z and ambient", -1, "LAB", lab);

  const gs::bilinear_mode filter = o.bilinear ? o.model.bilinear : gs::bilinear_mode::nearest;
  // The normal-map texture a pass through palette slot c samples, and its stream.
  auto nm_texture = [&](clut_slot c) {
    const std::size_t k = normal_map_of(in, c);
    return texture_ref{in.nm->width,
                       in.nm->height,
                       normal_map_texels(in, k).data(),
                       palettes(in)[static_cast<std::size_t>(c)],
                       nullptr,
                       false,
                       filter,
                       in.memory,
                       in.nm_at[k],
                       in.nm_texels[k].get()};
  };
  auto flat_white = [&](std::uint32_t) { return white; };
  const stream_texture diffuse_texels = diffuse_stream(in);
  const texture_ref sphere{64,
                           64,
                           nullptr,
                           nullptr,
                           in.sphere.data(),
                           true,
                           gs::bilinear_mode::nearest,
                           in.memory,
                           in.sphere_at,
                           in.sphere_texels.get()};

  const texture_ref spot_texture{
      spot_map_size, spot_map_size,       nullptr, nullptr, in.spot.data(), true, gs::bilinear_mode::nearest, in.memory,
      in.spot_at,    in.spot_texels.get()};

  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    const std::vector<light_vertex>& lv = ps.lights[l];
    // 2.1 (the DPB starts cleared; nothing is drawn outside the sprite area); 2.2 COLCLAMP = 0 in
    // every pass of 2.3 and 2.4.
    if constexpr (in_memory(FB{})) {
      if (l == 0 || fb.clear == dpb_clear_mode::explicit_clear) r.fill(dpb, clear_dpb, false);  // else: 2.6's Z clear
    } else {
      r.fill(dpb, clear_dpb, false);
    }
    const int li = static_cast<int>(l);
    note("2.1 clear 0x00808080", li, "DPB", dpb);
    // 2.3 (and two-pass's 2.4a): the method's light passes (Gouraud's for a Gouraud light, lod.hpp),
    // pass_table.hpp's list in draw order, each instantiated for its register set. Passes with the
    // same vertex colours and texture coordinates share their attribute set-up.
    std::array<std::vector<tri_attr>, 2 * vertex_colour_count> attr;
    auto attributes_of = [&](const light_pass& p) -> const std::vector<tri_attr>& {
      std::vector<tri_attr>& a = attr[2 * static_cast<std::size_t>(p.colour) + (p.source == pass_source::sphere_map)];
      if (a.empty() && !ps.triangles.empty())
        a = attributes(
            ps, o.model, [&](std::uint32_t v) { return vertex_rgbaq(p.colour, lv[v], o.s); },
            [&](const prepared_triangle& t, int k) { return vertex_uv(p.source, t, k, lv); });
      return a;
    };
    auto draw_pass = [&]<const pass_regs & Regs, pass_source Source>(const light_pass& p) {
      if constexpr (Source == pass_source::normal_map) {
        draw_textured<Regs>(r, fb.memory, in.stream.get(), normal_map_stream(in, normal_map_of(in, p.clut)),
                            nm_texture(p.clut), attributes_of(p), dpb);
      } else if constexpr (Source == pass_source::sphere_map) {
        r.draw<Regs>(&sphere, attributes_of(p), dpb);
      } else if constexpr (Source == pass_source::untextured) {
        r.draw<Regs>(nullptr, attributes_of(p), dpb);
      } else {
        alpha_into_rgb<Regs>(r, fb, dpb, *palettes(in)[static_cast<std::size_t>(p.clut)]);
      }
      note(p.label, li, "DPB", dpb);
    };
    // Section 3.6: a spot light's projective intensity texture over the DPB, (Cd − Cs)·As + Cs with
    // Cs = 128: each channel's signed value scaled by the texel's alpha / 128, where spot_step says.
    const std::vector<gs::stq_sampler> spot = spot_samplers(ps, l, o.model);
    const spot_step spot_at = spot_placement(light_method(m, s.lights[l]), o);
    auto spot_pass = [&](spot_step when) {
      if (spot.empty() || when != spot_at) return;
      if (when == spot_step::after_post_filter) {
        r.draw_projective<spot_attenuation_red>(spot_texture, spot, white, dpb);
        note("2.4 spot light: (R − 128)·As + 128 on the sum (projective texture, ST/Q)", li, "DPB", dpb);
      } else {
        r.draw_projective<spot_attenuation>(spot_texture, spot, white, dpb);
        note("2.3 spot light: (Cd − 128)·As + 128 (projective texture, ST/Q)", li, "DPB", dpb);
      }
    };
    with_method(
        light_method(m, s.lights[l]), [&]<const auto & D>() {
          [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((draw_pass.template operator()<*D.light[I].regs, D.light[I].source>(D.light[I]),
              I == 0 ? spot_pass(spot_step::after_first_pass) : void()),
             ...);
          }
          (std::make_index_sequence<D.light.size()>{});
        });
    spot_pass(spot_step::after_light_passes);
    // 2.4: R += G, R += B (mod 256): additive sprites writing red only.
    channel_pass<post_add_into_red>(r, fb, white, in.grey, 1, dpb, dpb);
    note("2.4 R += G", li, "DPB", dpb);
    channel_pass<post_add_into_red>(r, fb, white, in.grey, 2, dpb, dpb);
    note("2.4 R += B (the post-filter sum)", li, "DPB", dpb);
    spot_pass(spot_step::after_post_filter);
    // Outside the sprite area no pass draws: 0x80 (dot 0), the two-buffer DPB's clear (with one
    // buffer the output there keeps its 0).
    const scissor& drawn = r.sprite_area();
    for (int y = band.y0; y < band.y1; ++y) {
      std::uint8_t* row = &result.dot[l][r.index(band.x0, y)];
      std::fill(row, row + (band.x1 - band.x0), std::uint8_t{0x80});
      if (y >= drawn.y0 && y < drawn.y1)
        for (int x = drawn.x0; x < drawn.x1; ++x) row[x - band.x0] = static_cast<std::uint8_t>(dpb(x, y) & 0xFF);
    }
    if (one) {  // the dot layer into free alpha l; 2.6 waits until the output is the LAB
      channel_pass<move_into_alpha>(r, fb, white, in.alpha_index, 0, dpb, fb.alpha_plane[l]);
      note("2.6' dot layer into a free alpha", li, "alpha plane", fb.alpha_plane[l]);
      continue;
    }
    // 2.5, 2.6: COLCLAMP = 1; ILP[sum] × light colour (MODULATE) added into the LAB.
    const auto& lc = s.lights[l].colour;
    if constexpr (in_memory(FB{})) {
      channel_pass<ilp_into_lab>(r, fb, rgb(lc[0], lc[1], lc[2], 0x80), in.ilp, 0, fb.dpb, fb.lab,
                                 fb.clear != dpb_clear_mode::explicit_clear, o.model.tex_buffer);
    } else {
      channel_pass<ilp_into_lab>(r, fb, rgb(lc[0], lc[1], lc[2], 0x80), in.ilp, 0, fb.dpb, fb.lab);
    }
    note("2.6 LAB += ILP[sum] × light colour", li, "LAB", fb.lab);
  }

  const texture_ref diffuse{
      in.diffuse->width, in.diffuse->height,     nullptr, nullptr, in.diffuse->texels.data(), false, filter, in.memory,
      in.diffuse_at,     in.diffuse_texels.get()};
  // Step 5 (section 3.1): the non-normal-mapped geometry drawn into the output after step 4; then
  // the lit frame, from the output.
  auto write_frame = [&] {
    if (!ps.plain.empty()) {
      r.draw_plain<plain_gouraud>(
          diffuse,
          attributes(
              ps.plain, o.model, [&](std::uint32_t v) { return plain_colour(ps.plain_light[v]); }, normal_map_uv),
          fb.out, result.plain_triangle);
      note("5 non-normal-mapped geometry: Gouraud × diffuse (MODULATE), Z written", -1, "frame", fb.out);
    }
    for (int y = band.y0; y < band.y1; ++y)
      for (int x = band.x0; x < band.x1; ++x) result.colour[r.index(x, y)] = fb.out(x, y) | 0xFF000000u;
    return r.pixel_ops();
  };
  if (one) {
    one_buffer_steps(r, s, in, ambient, fb, [&] {
      draw_textured<diffuse_layer_rgb>(r, fb.memory, in.stream.get(), diffuse_texels, diffuse,
                                       attributes(ps, o.model, flat_white, normal_map_uv), fb.out);
    });
    note("2.6, 3, 4 in one buffer (LAB, its channels into the free alphas, diffuse, × the alphas)", -1, "frame",
         fb.out);
    return write_frame();
  }

  // Step 3: the unlit diffuse layer.
  r.fill(fb.diff, 0, false);
  draw_textured<diffuse_layer>(r, fb.memory, in.stream.get(), diffuse_texels, diffuse,
                               attributes(ps, o.model, flat_white, normal_map_uv), fb.diff);
  note("3 diffuse layer", -1, "diffuse", fb.diff);

  // Step 4: diffuse × LAB per channel: (Cs − 0)·Ad >> 7 with the LAB channel in the destination
  // alpha, writing that channel only (the channel move: value level, or on the memory path a
  // channel-fetch pass of the LAB through a palette with the index in alpha, FBMSK = 0x00FFFFFF).
  // Outside the sprite area the LAB and the output are 0.
  const scissor& area = r.sprite_area();
  if constexpr (in_memory(FB{})) {
    copy_lab(fb, area);
  } else {
    for (int y = area.y0; y < area.y1; ++y)
      for (int x = area.x0; x < area.x1; ++x) fb.out(x, y) = fb.lab(x, y);
  }
  auto multiply = [&](int c, auto pass) {
    if constexpr (in_memory(FB{})) {
      channel_pass<move_into_alpha>(r, fb, white, in.alpha_index, static_cast<unsigned>(c), fb.lab, fb.out);
    } else {
      for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x) {
          std::uint32_t& o = fb.out(x, y);
          o = (o & 0x00FFFFFFu) | (((fb.lab(x, y) >> (8 * c)) & 0xFFu) << 24);
        }
    }
    pass(
        white, [&](int x, int y) { return gs::rgba8::from_u32(fb.diff(x, y)); }, fb.out);
  };
  multiply(0, [&](auto&&... a) { r.sprite<multiply_red>(a...); });
  multiply(1, [&](auto&&... a) { r.sprite<multiply_green>(a...); });
  multiply(2, [&](auto&&... a) { r.sprite<multiply_blue>(a...); });
  note("4 diffuse × LAB (R, G, B)", -1, "frame", fb.out);
  return write_frame();
}

template <class FB>
void render_bands(const scene& s, const prepared_scene& ps, method m, const render_options& o, const gs_inputs& in,
                  frame_buffers<FB>& fb, frame& result) {
  if (!fb.zb.in_memory) {
    fb.z.assign(static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height), 0);
    fb.zb.rows = row_view{fb.z.data(), ps.width};
  }
  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) fb.dpb(x, y) = clear_dpb;
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
}

}  // namespace

frame render(const scene& s, const prepared_scene& ps, method m, const render_options& o) {
  check(s, m, o, frame_use::render);
  const gs_inputs in = make_inputs(s, m, o);
  frame result;
  result.width = ps.width;
  result.height = ps.height;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  result.colour.assign(n, 0);
  result.visible_triangle.assign(n, -1);
  result.plain_triangle.assign(n, -1);
  result.dot.assign(s.lights.size(), std::vector<std::uint8_t>(n, 0));
  if (o.memory_path || o.dpb_clear != dpb_clear_mode::explicit_clear) {
    // gs_inputs.hpp's buffer layout: the DPB (and in step 3 the diffuse layer), the LAB, the output
    // (PSMCT32) and the Z buffer (PSMZ24), FBW = ceil(width / 64).
    const buffer_layout layout = buffer_layout_for(ps.width, ps.height);
    const std::uint32_t fbw = layout.fbw;
    gs::mem::local_memory memory;
    frame_buffers<memory_view> fb;
    fb.memory = &memory;
    fb.layout = layout;
    fb.clear = o.dpb_clear;
    fb.dpb = memory_view{memory.words(), 32 * layout.dpb(), fbw, false};
    fb.lab = memory_view{memory.words(), 32 * layout.lab(), fbw, false};
    fb.out = memory_view{memory.words(), 32 * layout.output(), fbw, false};
    fb.diff = fb.dpb;
    fb.zb.memory = memory_view{memory.words(), 32 * layout.z(), fbw, true};
    fb.zb.in_memory = true;
    fb.dpb.z = o.dpb_clear == dpb_clear_mode::z_trick;
    fb.lab.z = o.dpb_clear == dpb_clear_mode::z_trick_psmz32;
    // The inner loops' addresses tabulated over whole pages (gs_memory/fast_address.hpp).
    const gs::mem::texel_addresses page_as_t8(gs::mem::psm::PSMT8, 2 * fbw, 128, 64);  // channel_pass's TBW
    fb.page_as_t8 = &page_as_t8;
    fb.alpha_plane[1] = memory_view{memory.words(), 32 * layout.z(), fbw, false};
    std::vector<gs::mem::row_column_address> addresses;
    addresses.reserve(6);
    for (memory_view* v : {&fb.dpb, &fb.lab, &fb.diff, &fb.out, &fb.zb.memory, &fb.alpha_plane[1]})
      v->address = &addresses.emplace_back(v->layout(), v->bp, v->bw, 64 * fbw,
                                           32 * static_cast<std::uint32_t>((ps.height + 31) / 32));
    fb.alpha_plane[0] = fb.dpb, fb.alpha_plane[2] = fb.out;  // with their address tables
    render_options one = o;
    // Draw order is the model's: the z-trick clears; the one-buffer variant's alpha plane in the Z
    // buffer's words, whose pixels are not the Z buffer's (another band's depth tests read them).
    if (o.dpb_clear != dpb_clear_mode::explicit_clear || o.buffers == draw_buffers::one) one.threads = 1;
    gs_inputs uploaded = upload_inputs(memory, in, layout.first_texture_block(), one.threads > 1);
    if (uploaded.window_first != 0) one.threads = 1;  // the pieces' uploads share the window
    if (uploaded.window_first != 0 && !ps.plain.empty()) throw std::invalid_argument(plain_needs_resident_texture);
    start_stream(uploaded, ps, o, band_renderer::drawn_area(ps, {0, 0, ps.width, ps.height}));
    render_bands(s, ps, m, one, uploaded, fb, result);
  } else {
    std::vector<std::uint32_t> rows(4 * n, 0);  // value level: DPB, LAB, diffuse, output, frame-sized each
    frame_buffers<row_view> fb;
    row_view* views[4] = {&fb.dpb, &fb.lab, &fb.diff, &fb.out};
    for (std::size_t k = 0; k < 4; ++k) *views[k] = row_view{rows.data() + k * n, ps.width};
    fb.alpha_plane[0] = fb.dpb, fb.alpha_plane[1] = fb.lab, fb.alpha_plane[2] = fb.out;
    render_bands(s, ps, m, o, in, fb, result);
  }
  return result;
}

}  // namespace gsdot3::pipeline
