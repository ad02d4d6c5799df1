// pipeline/render.cpp — the pass sequences of the three methods, run over horizontal frame bands.
//
// Register level (through gs::pixel_pipeline and the gs_arith units, see gs_pass.hpp): every triangle pass (step 1, 2.3, 3), the
// clear values, the two-pass alpha post pass (PSMT8H reads the DPB's own alpha byte at the same
// pixel: gs::t8h_index), the ILP look-up × light colour added into the LAB, the diffuse pass and
// the per-channel blend of the multiply.
// Two storage paths (render_options::memory_path):
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
#include <thread>

#include "gs_memory/address.hpp"
#include "gs_memory/channel_fetch.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/texture_buffer.hpp"
#include "gs_memory/texture_wrap.hpp"
#include "gs_memory/transfer.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/pass_table.hpp"

namespace gsdot3::pipeline {

std::string_view name(method m) {
  switch (m) {
    case method::two_pass: return "two-pass";
    case method::four_pass: return "four-pass";
    case method::baseline: return "baseline";
  }
  return "?";
}

std::string_view name(dpb_clear_mode m) {
  switch (m) {
    case dpb_clear_mode::explicit_clear: return "explicit";
    case dpb_clear_mode::z_trick: return "z-trick";
    case dpb_clear_mode::z_trick_psmz32: return "z-trick-psmz32";
  }
  return "?";
}

namespace {

using namespace detail;
using namespace passes;

gs::u8 byte(int v) { return gs::u8::from_wrapped(v); }

template <class FB>
struct frame_buffers {
  std::vector<std::uint32_t> z;  // the value path's Z buffer storage (zb's rows)
  z_view zb;
  FB lab, dpb, diff, out;
  gs::mem::local_memory* memory = nullptr;  // the memory path's local memory, else null
  buffer_layout layout;                     // the memory path's buffers (gs_inputs.hpp)
  const gs::mem::texel_addresses* page_as_t8 = nullptr;  // the memory path: a page of the DPB / LAB as PSMT8 (BP 0)
  dpb_clear_mode clear = dpb_clear_mode::explicit_clear;
};

// zsigma(x, y): the pixel of the same page whose PSMZ32 address is PSMCT32 pixel (x, y)'s, from
// gs_memory's two layouts (the four 32×16 quarters of the page swapped along the diagonals).
std::array<int, 2> zsigma(int x, int y) {
  static const std::array<std::uint16_t, 2048> table = [] {
    std::array<std::uint16_t, 2048> ct_at_word{}, sigma{};
    const gs::mem::buffer ct{{}, fixed::uint<6>::from_wrapped(1), gs::mem::psm::PSMCT32};
    const gs::mem::buffer z{{}, fixed::uint<6>::from_wrapped(1), gs::mem::psm::PSMZ32};
    for (std::uint32_t p = 0; p < 2048; ++p) ct_at_word[gs::mem::locate(ct, p % 64, p / 64).byte / 4] = static_cast<std::uint16_t>(p);
    for (std::uint32_t q = 0; q < 2048; ++q) sigma[ct_at_word[gs::mem::locate(z, q % 64, q / 64).byte / 4]] = static_cast<std::uint16_t>(q);
    return sigma;
  }();
  const int s = table[static_cast<std::size_t>((y & 31) * 64 + (x & 63))];
  return {(x & ~63) + s % 64, (y & ~31) + s / 64};
}
constexpr bool in_memory(const row_view&) { return false; }
constexpr bool in_memory(const memory_view&) { return true; }

// A sprite pass whose texel is byte `channel` of each pixel of `src` through `clut`, into `dst`.
// Value level: the byte of the same pixel's word. Memory path: gs_memory's channel-fetch sprites
// (8×2 tiles per page, the page read as PSMT8 with TBP0 = its base, TBW = 2·FBW, TW = 7, TH = 6).
template <const pass_regs& Pass>
void channel_pass(band_renderer& r, const frame_buffers<row_view>&, gs::rgba8 colour, const gs::clut_buffer& clut,
                  unsigned channel, const row_view& src, const row_view& dst) {
  r.sprite<Pass>(colour, [&](int x, int y) { return gs::clut_t8(clut, byte(static_cast<int>(src(x, y) >> (8 * channel)))); }, dst);
}
// The memory path. A source drawn in PSMZ32 (src.z) has logical pixel L in the word of PSMCT32
// pixel zsigma(L): the tile that fetches PSMCT32 pixel M is drawn at zsigma(M) (the sprites' XYZ
// in the Z layout). z_clear: the ILP pass of the z-trick modes, also writing Z = 0x00808080 into the
// DPB as PSMZ24 at every fragment (after its texel fetch). In the z-trick modes the texel fetches
// go through gs_memory's texture_page_buffer model (model option texture_buffer).
template <const pass_regs& Pass>
void channel_pass(band_renderer& r, const frame_buffers<memory_view>& fb, gs::rgba8 colour, const gs::clut_buffer& clut,
                  unsigned channel, const memory_view& src, const memory_view& dst, bool z_clear = false,
                  gs::texture_buffer tb = gs::texture_buffer::per_fragment) {
  static constexpr gs::mem::channel_fetch layout[4] = {gs::mem::channel_fetch_sprites(0), gs::mem::channel_fetch_sprites(1),
                                                       gs::mem::channel_fetch_sprites(2), gs::mem::channel_fetch_sprites(3)};
  const gs::mem::channel_fetch& f = layout[channel];
  gs::mem::local_memory& mem = *fb.memory;
  const gs::mem::buffer zbuf{fixed::uint<14>::from_wrapped(fb.dpb.bp), fixed::uint<6>::from_wrapped(fb.dpb.bw), gs::mem::psm::PSMZ24};
  const bool buffered = fb.clear != dpb_clear_mode::explicit_clear;
  const scissor& a = r.sprite_area();
  // With the Z clear the ILP sprites cover every page the area touches (the paper's per-page
  // primitives, section 3.3), so that the Z writes clear whole pages.
  const scissor pages{a.x0 & ~63, a.y0 & ~31, (a.x1 + 63) & ~63, (a.y1 + 31) & ~31};
  r.scalar_sprites = true;  // the texel fetches read the memory the sprites write (span_batch.hpp)
  // The byte of the page (at TBP0 = 0) each sprite pixel fetches, through CLAMP_1 and the PSMT8
  // address: sprite k's pixel (dx, dy) at 16·k + 8·dy + dx. The sprites and their texels are the
  // same on every page, which only moves TBP0 (texel_addresses::byte adds it).
  static_assert([] {
    for (const gs::mem::channel_fetch& c : layout)
      for (const gs::mem::fetch_sprite& sp : c.sprites)
        if (sp.x1 - sp.x0 != 8 || sp.y1 - sp.y0 != 2) return false;
    return true;
  }());
  std::array<std::uint32_t, 16 * 128> fetched{};
  for (std::size_t k = 0; k < f.sprites.size(); ++k)
    for (std::int32_t dy = 0; dy < 2; ++dy)
      for (std::int32_t dx = 0; dx < 8; ++dx) {
        const gs::mem::fetch_sprite& sp = f.sprites[k];
        const auto u = gs::mem::wrap_texel(f.CLAMP.WMS, sp.u0 + dx, fixed::u4::literal(7), f.CLAMP.MINU, f.CLAMP.MAXU);
        const auto v = gs::mem::wrap_texel(f.CLAMP.WMT, sp.v0 + dy, fixed::u4::literal(6), f.CLAMP.MINV, f.CLAMP.MAXV);
        fetched[16 * k + static_cast<std::size_t>(8 * dy + dx)] = fb.page_as_t8->byte(u, v, 0);
      }
  for (int py = a.y0 / 32; py * 32 < a.y1; ++py)
    for (int px = a.x0 / 64; px * 64 < a.x1; ++px) {
      const std::uint32_t page = static_cast<std::uint32_t>(px) + static_cast<std::uint32_t>(py) * src.bw;
      const gs::mem::buffer tex{fixed::uint<14>::from_wrapped(src.bp + 32 * page), fixed::uint<6>::from_wrapped(2 * src.bw),
                                gs::mem::psm::PSMT8};
      gs::mem::texture_page_buffer texels(buffered ? tb : gs::texture_buffer::per_fragment, mem, (src.bp + 32 * page) * 256,
                                          gs::mem::page_bytes);
      for (std::size_t k = 0; k < f.sprites.size(); ++k) {
        const gs::mem::fetch_sprite& sp = f.sprites[k];
        const std::uint32_t* sprite_texels = &fetched[16 * k];
        const int mx = px * 64 + static_cast<int>(sp.x0), my = py * 32 + static_cast<int>(sp.y0);  // PSMCT32 pixel fetched
        const std::array<int, 2> drawn = src.z ? zsigma(mx, my) : std::array<int, 2>{mx, my};   // where it is drawn
        const int x0 = drawn[0], y0 = drawn[1];  // plain ints: clang 14 cannot capture structured bindings
        const int w = static_cast<int>(sp.x1 - sp.x0), h = static_cast<int>(sp.y1 - sp.y0);
        r.sprite_rect<Pass>(colour, {x0, y0, x0 + w, y0 + h},
                            [&](int x, int y) {
                              const std::uint32_t at = sprite_texels[8 * (y - y0) + (x - x0)] + tex.BP.value() * gs::mem::block_bytes;
                              const std::uint8_t index = texels.fetch(at % gs::mem::memory_bytes);
                              if (z_clear) {  // ZBUF = the DPB (PSMZ24), Z = 0x00808080, ZTST = ALWAYS
                                const auto zx = static_cast<std::uint32_t>(x), zy = static_cast<std::uint32_t>(y);
                                const gs::depth_result d = gs::depth_test(passes::depth_always, passes::z_written, clear_dpb, mem.read_pixel(zbuf, zx, zy));
                                if (d.write_z) mem.write_pixel(zbuf, zx, zy, d.z);
                              }
                              return gs::clut_t8(clut, gs::u8::from_wrapped(index));
                            },
                            dst, z_clear ? &pages : nullptr);
      }
    }
  r.scalar_sprites = false;
}

// The memory path's copy of the LAB into the output over `area` (before step 4): gs_inputs.hpp's
// lab_to_output, the transfer the packet stream writes, run through gs_memory's local_to_local.
void copy_lab(const frame_buffers<memory_view>& fb, const scissor& area) {
  if (const std::optional<lab_copy> c = lab_to_output(fb.layout, area, fb.lab.z))
    gs::mem::local_to_local(*fb.memory, c->BITBLTBUF, c->TRXPOS, c->TRXREG, lab_copy::TRXDIR);
}

template <class FB>
std::size_t render_band(const scene& s, const prepared_scene& ps, method m, const render_options& o, const gs_inputs& in,
                        scissor band, frame_buffers<FB>& fb, frame& result) {
  band_renderer r(ps, o, band, fb.zb, result.visible_triangle);
  // Tracing (render_options::trace, one band): after each pass, its target buffer and inputs.
  pass_record pending;
  const std::size_t frame_pixels = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  auto open_pass = [&] {
    pending = {{}, -1, {}, {}, std::vector<std::uint32_t>(frame_pixels), std::vector<std::uint16_t>(4 * frame_pixels),
               std::vector<std::uint8_t>(frame_pixels)};
  };
  auto note = [&](const char* label, int light, const char* target, const FB& buffer) {
    if (o.trace == nullptr) return;
    pending.label = label, pending.light = light, pending.target = target;
    pending.word.resize(frame_pixels);
    for (int y = 0; y < ps.height; ++y)
      for (int x = 0; x < ps.width; ++x) pending.word[r.index(x, y)] = buffer(x, y);
    o.trace->push_back(std::move(pending));
    open_pass();
  };
  if (o.trace != nullptr) open_pass(), r.pending = &pending;
  r.depth_and_ambient(fb.lab, rgb(s.ambient[0], s.ambient[1], s.ambient[2], 0x80));
  note("1 Z and ambient", -1, "LAB", fb.lab);

  const gs::bilinear_mode filter = o.bilinear ? o.model.bilinear : gs::bilinear_mode::nearest;
  auto nm_texture = [&](const gs::clut_buffer& clut) {
    return texture_ref{in.nm->width, in.nm->height, in.nm->index.data(), &clut, nullptr, false, filter, in.memory, in.nm_at, in.nm_texels.get()};
  };
  auto flat_white = [&](std::uint32_t) { return white; };
  const stream_texture nm_stream = normal_map_stream(in), diffuse_texels = diffuse_stream(in);

  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    const std::vector<light_vertex>& lv = ps.lights[l];
    // 2.1 (the DPB starts cleared; nothing is drawn outside the sprite area); 2.2 COLCLAMP = 0 in
    // every pass of 2.3 and 2.4.
    if constexpr (in_memory(FB{})) {
      if (l == 0 || fb.clear == dpb_clear_mode::explicit_clear) r.fill(fb.dpb, clear_dpb, false);  // else: 2.6's Z clear
    } else {
      r.fill(fb.dpb, clear_dpb, false);
    }
    const int li = static_cast<int>(l);
    note("2.1 clear 0x00808080", li, "DPB", fb.dpb);
    switch (m) {
      case method::two_pass: {
        const auto attr = attributes(ps, o.model.setup, [&](std::uint32_t v) { return two_pass_colour(lv[v], o.s); }, normal_map_uv);
        const texture_ref pos = nm_texture(in.pos), neg = nm_texture(in.neg);
        draw_textured<two_pass_positive>(r, fb.memory, in.stream.get(), nm_stream, pos, attr, fb.dpb);
        note("2.3 Max(n,0)·l (MODULATE)", li, "DPB", fb.dpb);
        draw_textured<two_pass_negative>(r, fb.memory, in.stream.get(), nm_stream, neg, attr, fb.dpb);
        note("2.3 − Max(−n,0)·l (MODULATE, Cd − Cs)", li, "DPB", fb.dpb);
        // 2.4a: n'_a into R, G and B: the DPB read as PSMT8H (its own alpha byte) through a grey CLUT.
        if constexpr (in_memory(FB{})) {
          const gs::mem::buffer t8h{fixed::uint<14>::from_wrapped(fb.dpb.bp), fixed::uint<6>::from_wrapped(fb.dpb.bw),
                                    gs::mem::psm::PSMT8H};
          r.sprite<two_pass_add_alpha>(
              white,
              [&](int x, int y) {
                const auto [tx, ty] = fb.dpb.z ? zsigma(x, y) : std::array<int, 2>{x, y};  // the word of logical (x, y)
                return gs::clut_t8(in.grey, gs::u8::from_wrapped(fb.memory->read_pixel(t8h, static_cast<std::uint32_t>(tx),
                                                                                         static_cast<std::uint32_t>(ty))));
              },
              fb.dpb);
        } else {
          r.sprite<two_pass_add_alpha>(white, [&](int x, int y) { return gs::clut_t8(in.grey, gs::t8h_index(fb.dpb(x, y))); },
                                       fb.dpb);
        }
        note("2.4a + n'a (PSMT8H of the DPB alpha)", li, "DPB", fb.dpb);
        break;
      }
      case method::four_pass: {
        const auto pass1 = attributes(
            ps, o.model.setup, [&](std::uint32_t v) { return four_pass_sphere_colour(lv[v]); },
            [&](const prepared_triangle& t, int k) { return sphere_uv(lv[t.vertex[static_cast<std::size_t>(k)]]); });
        const texture_ref sphere{64, 64, nullptr, nullptr, in.sphere.data(), true, gs::bilinear_mode::nearest, in.memory, in.sphere_at,
                                 in.sphere_texels.get()};
        r.draw<four_pass_sphere>(&sphere, pass1, fb.dpb);
        note("2.3 sphere map · fade (HIGHLIGHT)", li, "DPB", fb.dpb);
        const auto attr = attributes(ps, o.model.setup, flat_white, normal_map_uv);
        const texture_ref x = nm_texture(in.axis[0]), y = nm_texture(in.axis[1]), z = nm_texture(in.axis[2]);
        draw_textured<four_pass_x>(r, fb.memory, in.stream.get(), nm_stream, x, attr, fb.dpb);
        note("2.3 R: x multiply (Cs − Cd)·As + Cd", li, "DPB", fb.dpb);
        draw_textured<four_pass_y>(r, fb.memory, in.stream.get(), nm_stream, y, attr, fb.dpb);
        note("2.3 G: y multiply (Cs − Cd)·As + Cd", li, "DPB", fb.dpb);
        draw_textured<four_pass_z>(r, fb.memory, in.stream.get(), nm_stream, z, attr, fb.dpb);
        note("2.3 B: z multiply (Cs − Cd)·As + Cd", li, "DPB", fb.dpb);
        break;
      }
      case method::baseline: {
        auto side = [&](bool negative) {
          return attributes(ps, o.model.setup, [&, negative](std::uint32_t v) { return baseline_colour(lv[v], negative); }, normal_map_uv);
        };
        const auto tl_pos = side(false), tl_neg = side(true);
        const texture_ref pos = nm_texture(in.pos), neg = nm_texture(in.neg);
        draw_textured<baseline_add>(r, fb.memory, in.stream.get(), nm_stream, pos, tl_pos, fb.dpb); // NM_pos·TL_pos
        note("2.3 + NM_pos·TL_pos", li, "DPB", fb.dpb);
        draw_textured<baseline_add>(r, fb.memory, in.stream.get(), nm_stream, neg, tl_neg, fb.dpb); // NM_neg·TL_neg
        note("2.3 + NM_neg·TL_neg", li, "DPB", fb.dpb);
        draw_textured<baseline_subtract>(r, fb.memory, in.stream.get(), nm_stream, neg, tl_pos, fb.dpb);  // −NM_neg·TL_pos
        note("2.3 − NM_neg·TL_pos", li, "DPB", fb.dpb);
        draw_textured<baseline_subtract>(r, fb.memory, in.stream.get(), nm_stream, pos, tl_neg, fb.dpb);  // −NM_pos·TL_neg
        note("2.3 − NM_pos·TL_neg", li, "DPB", fb.dpb);
        break;
      }
    }
    // 2.4: R += G, R += B (mod 256): additive sprites writing red only.
    channel_pass<post_add_into_red>(r, fb, white, in.grey, 1, fb.dpb, fb.dpb);
    note("2.4 R += G", li, "DPB", fb.dpb);
    channel_pass<post_add_into_red>(r, fb, white, in.grey, 2, fb.dpb, fb.dpb);
    note("2.4 R += B (the post-filter sum)", li, "DPB", fb.dpb);
    for (int y = band.y0; y < band.y1; ++y)
      for (int x = band.x0; x < band.x1; ++x) result.dot[l][r.index(x, y)] = static_cast<std::uint8_t>(fb.dpb(x, y) & 0xFF);
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

  // Step 3: the unlit diffuse layer.
  r.fill(fb.diff, 0, false);
  const texture_ref diffuse{in.diffuse->width, in.diffuse->height, nullptr, nullptr, in.diffuse->texels.data(), false, filter,
                            in.memory, in.diffuse_at, in.diffuse_texels.get()};
  draw_textured<diffuse_layer>(r, fb.memory, in.stream.get(), diffuse_texels, diffuse, attributes(ps, o.model.setup, flat_white, normal_map_uv), fb.diff);
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
    pass(white, [&](int x, int y) { return gs::rgba8::from_u32(fb.diff(x, y)); }, fb.out);
  };
  multiply(0, [&](auto&&... a) { r.sprite<multiply_red>(a...); });
  multiply(1, [&](auto&&... a) { r.sprite<multiply_green>(a...); });
  multiply(2, [&](auto&&... a) { r.sprite<multiply_blue>(a...); });
  note("4 diffuse × LAB (R, G, B)", -1, "frame", fb.out);
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x) {
      result.colour[r.index(x, y)] = fb.out(x, y) | 0xFF000000u;
    }
  return r.pixel_ops();
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
  const gs_inputs in = make_inputs(s, m, o);
  frame result;
  result.width = ps.width;
  result.height = ps.height;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  result.colour.assign(n, 0);
  result.visible_triangle.assign(n, -1);
  result.dot.assign(s.lights.size(), std::vector<std::uint8_t>(n, 0));
  if (o.memory_path || o.dpb_clear != dpb_clear_mode::explicit_clear) {
    // gs_inputs.hpp's buffer layout: the DPB (and in step 3 the diffuse layer), the LAB, the output
    // (PSMCT32) and the Z buffer (PSMZ24), FBW = ceil(width / 64).
    const buffer_layout layout = buffer_layout_for(ps.width, ps.height);
    const std::uint32_t fbw = layout.fbw;
    if (!layout.fits())
      throw std::invalid_argument("memory path: four " + std::to_string(ps.width) + "x" + std::to_string(ps.height) +
                                  " 32-bit buffers do not fit in the GS's 4 MiB");
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
    std::vector<gs::mem::row_column_address> addresses;
    addresses.reserve(5);
    for (memory_view* v : {&fb.dpb, &fb.lab, &fb.diff, &fb.out, &fb.zb.memory})
      v->address = &addresses.emplace_back(v->layout(), v->bp, v->bw, 64 * fbw, 32 * static_cast<std::uint32_t>((ps.height + 31) / 32));
    render_options one = o;
    if (o.dpb_clear != dpb_clear_mode::explicit_clear) one.threads = 1;  // draw order is the model's
    gs_inputs uploaded = upload_inputs(memory, in, layout.first_texture_block(), one.threads > 1);
    if (uploaded.window_first != 0) one.threads = 1;  // the pieces' uploads share the window
    start_stream(uploaded, ps, o, band_renderer::drawn_area(ps, {0, 0, ps.width, ps.height}));
    render_bands(s, ps, m, one, uploaded, fb, result);
  } else {
    std::vector<std::uint32_t> rows(4 * n, 0);  // value level: DPB, LAB, diffuse, output, frame-sized each
    frame_buffers<row_view> fb;
    row_view* views[4] = {&fb.dpb, &fb.lab, &fb.diff, &fb.out};
    for (std::size_t k = 0; k < 4; ++k) *views[k] = row_view{rows.data() + k * n, ps.width};
    render_bands(s, ps, m, o, in, fb, result);
  }
  return result;
}

}  // namespace gsdot3::pipeline
