// pipeline/render.cpp — the frame program (frame_program.hpp: the five GS methods' steps) executed over
// horizontal frame bands.
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
// is each light's DPB, the dot layers wait in free alphas (frame_buffers::alpha_plane), then the output
// becomes the LAB, its channels wait in those alphas and the diffuse layer is multiplied by them.
// The clears over the whole frame (the memory's state before step 1) are direct stores, not pixels.
// The register sets and vertex values of the passes are pass_table.hpp's; frame_packets.cpp encodes
// the same program as the GIF packet stream of the same frame.
#include "pipeline/render.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>

#include "gs_memory/local_memory.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/band_split.hpp"
#include "pipeline/channel_pass.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/frame_limits.hpp"
#include "pipeline/frame_program.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/memory_buffers.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/pass_table.hpp"
#include "pipeline/scratch.hpp"

namespace gsdot3::pipeline {

namespace {

using namespace detail;
using namespace passes;

// f.template operator()<R>() with R the register set r of List (an operation's kind takes only
// these: frame_program.hpp's program_regs), so the pixel loops are compiled per set.
template <const regs_list& List, class F>
void with_regs(const pass_regs* r, F&& f) {
  const bool found = [&]<std::size_t... I>(std::index_sequence<I...>) {
    return ((r == List.at[I] ? (f.template operator()<*List.at[I]>(), true) : false) || ...);
  }
  (std::make_index_sequence<List.n>{});
  if (!found) throw std::logic_error("an operation with a register set its kind does not take");
}

// The frame program's drawing operations over one band (the register-state operations are the
// packet stream's: here every drawing operation carries its set, buffer, texture and area).
template <class FB>
std::size_t render_band(const prepared_scene& ps, const render_options& o, const gs_inputs& in,
                        const frame_program& prog, scissor band, frame_buffers<FB>& fb, frame& result) {
  if constexpr (!in_memory(FB{}))  // the value path's buffers start at 0 (render_bands): the band's rows
    for (const row_view* v : {&fb.dpb, &fb.lab, &fb.diff, &fb.out, &fb.zb.rows})
      std::fill(v->words + static_cast<std::ptrdiff_t>(band.y0) * v->width,
                v->words + static_cast<std::ptrdiff_t>(band.y1) * v->width, 0u);
  band_renderer r(ps, o, band, fb.zb, result.visible_triangle);
  // Tracing (render_options::trace, one band): at each checkpoint, its buffer and the pass's inputs.
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
  auto note = [&](std::string_view label, int light, std::string_view target, const FB& buffer) {
    if (o.trace == nullptr) return;
    pending.label = label, pending.light = light, pending.target = target;
    pending.word.resize(frame_pixels);
    for (int y = 0; y < ps.height; ++y)
      for (int x = 0; x < ps.width; ++x) pending.word[r.index(x, y)] = buffer(x, y);
    o.trace->push_back(std::move(pending));
    open_pass();
  };
  if (o.trace != nullptr) open_pass(), r.pending = &pending;
  auto view = [&](buffer_role b) -> const FB& {
    switch (b) {
      case buffer_role::dpb: return fb.dpb;
      case buffer_role::lab: return fb.lab;
      case buffer_role::diffuse: return fb.diff;
      case buffer_role::output: return fb.out;
      case buffer_role::z_words: break;
    }
    return fb.alpha_plane[1];
  };

  const gs::bilinear_mode filter = o.bilinear ? o.model.bilinear : gs::bilinear_mode::nearest;
  auto nm_texture = [&](std::size_t k, clut_slot c, std::size_t layer) {
    const std::size_t t = texture_index(in, layer, k);  // placed: the memory path's
    return texture_ref{in.nm->width,
                       in.nm->height,
                       normal_map_texels(in, layer, k).data(),
                       palettes(in, layer)[static_cast<std::size_t>(c)],
                       nullptr,
                       false,
                       filter,
                       in.memory,
                       t < in.nm_at.size() ? in.nm_at[t] : gs::mem::buffer{},
                       t < in.nm_texels.size() ? in.nm_texels[t].get() : nullptr};
  };
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
  const texture_ref diffuse{
      in.diffuse->width, in.diffuse->height,     nullptr, nullptr, in.diffuse->texels.data(), false, filter, in.memory,
      in.diffuse_at,     in.diffuse_texels.get()};

  // The per-triangle attributes of a triangle operation; passes of one light with the same vertex
  // colours and texture coordinates share them (light −1: white, the normal map's UVs).
  int attr_light = -2;
  std::array<std::vector<tri_attr>, 2 * vertex_colour_count> attr;
  auto attributes_of = [&](const frame_op& op) -> const std::vector<tri_attr>& {
    if (op.light != attr_light)
      for (std::vector<tri_attr>& a : attr) a.clear();
    attr_light = op.light;
    const bool sphere_uv = op.texture == texture_role::sphere_map;
    std::vector<tri_attr>& a = attr[2 * static_cast<std::size_t>(op.colour_of) + sphere_uv];
    if (!a.empty() || ps.triangles.empty()) return a;
    if (op.light < 0)
      return a = attributes(
                 ps, o.model, [](std::uint32_t) { return white; }, normal_map_uv, band.y0, band.y1);
    const std::vector<light_vertex>& lv = ps.lights[static_cast<std::size_t>(op.light)];
    const pass_source src = sphere_uv ? pass_source::sphere_map : pass_source::normal_map;
    return a = attributes(
               ps, o.model, [&](std::uint32_t v) { return vertex_rgbaq(op.colour_of, lv[v], o.s); },
               [&](const prepared_triangle& t, int k) { return vertex_uv(src, t, k, lv); }, band.y0, band.y1);
  };
  auto triangles = [&](const frame_op& op) {
    const std::vector<tri_attr>& a = attributes_of(op);
    const FB& target = view(op.buffer);
    const std::size_t layer = op.layer < 0 ? 0 : static_cast<std::size_t>(op.layer);
    texture_ref tex = op.texture == texture_role::diffuse ? diffuse : nm_texture(op.normal_map, op.clut, layer);
    const stream_piece* piece = nullptr;
    if (op.piece >= 0) {
      piece = &prog.pieces[static_cast<std::size_t>(op.piece)];
      tex.at = piece->at;
      tex.texel_at = &in.stream->addresses(prog.streamed[static_cast<std::size_t>(op.stream)], piece->at);
    }
    const texture_ref* t = op.texture == texture_role::none         ? nullptr
                           : op.texture == texture_role::sphere_map ? &sphere
                                                                    : &tex;
    const triangle_range tris =
        op.layer < 0 ? triangle_range{0, static_cast<std::uint32_t>(ps.triangles.size())} : ps.layer(layer);
    with_regs<program_regs::triangles>(op.regs, [&]<const pass_regs & R>() { r.draw<R>(t, a, target, tris, piece); });
  };
  auto channel = [&](const frame_op& op) {
    const FB& src = view(op.source);
    const FB& dst = view(op.buffer);
    const gs::clut_buffer& clut = *palettes(in, 0)[static_cast<std::size_t>(op.clut)];  // the shared palettes
    if constexpr (!in_memory(FB{}))
      if (op.regs == &move_into_alpha) {  // value level: the byte itself (palette i -> i)
        const scissor& area = r.sprite_area();
        const unsigned shift = 8 * op.channel;
        for (int y = area.y0; y < area.y1; ++y) {  // rows of adjacent words
          std::uint32_t* d = &dst(area.x0, y);
          if (&src(area.x0, y) == d) {  // a buffer's own channel into its alpha
            for (int k = 0; k < area.x1 - area.x0; ++k) d[k] = (d[k] & 0x00FFFFFFu) | (((d[k] >> shift) & 0xFFu) << 24);
          } else {
            byte_into_alpha(&src(area.x0, y), d, area.x1 - area.x0, shift);
          }
        }
        return;
      }
    with_regs<program_regs::channel>(op.regs, [&]<const pass_regs & R>() {
      if constexpr (in_memory(FB{})) {
        channel_pass<R>(r, fb, op.colour, clut, op.channel, src, dst, op.z_clear,
                        op.z_clear ? o.model.tex_buffer : gs::texture_buffer::per_fragment);
      } else {
        channel_pass<R>(r, fb, op.colour, clut, op.channel, src, dst);
      }
    });
  };

  using kind = frame_op::kind;
  for (const frame_op& op : prog.ops) switch (op.what) {
      case kind::environment:
      case kind::uploads:
      case kind::scissor:
      case kind::depth:
      case kind::target:
      case kind::texflush:
      case kind::texture: break;
      case kind::piece_uploads:
        if constexpr (in_memory(FB{}))
          upload_piece(*fb.memory, prog.streamed[static_cast<std::size_t>(op.stream)],
                       prog.pieces[static_cast<std::size_t>(op.piece)]);
        break;
      case kind::fill:
        if (op.area == area_role::frame) {
          r.clear(view(op.buffer), op.colour.to_u32(), op.regs->FBMSK, op.writes_z);
        } else {
          with_regs<program_regs::fill>(
              op.regs, [&]<const pass_regs & R>() { r.fill<R>(view(op.buffer), op.colour.to_u32(), false); });
        }
        break;
      case kind::ambient: r.depth_and_ambient(view(op.buffer), op.colour); break;
      case kind::triangles: triangles(op); break;
      case kind::projective: {
        const std::vector<gs::stq_sampler> spot = spot_samplers(ps, static_cast<std::size_t>(op.light), o.model);
        with_regs<program_regs::projective>(
            op.regs, [&]<const pass_regs & R>() { r.draw_projective<R>(spot_texture, spot, white, view(op.buffer)); });
        break;
      }
      case kind::buffer_sprite:
        if (op.texture == texture_role::buffer_t8h) {
          with_regs<program_regs::t8h_sprite>(op.regs, [&]<const pass_regs & R>() {
            alpha_into_rgb<R>(r, fb, view(op.buffer), *palettes(in, 0)[static_cast<std::size_t>(op.clut)]);
          });
        } else {
          const FB& src = view(op.source);
          with_regs<program_regs::buffer_sprite>(op.regs, [&]<const pass_regs & R>() {
            r.sprite<R>(
                white, [&](int x, int y) { return gs::rgba8::from_u32(src(x, y)); }, view(op.buffer));
          });
        }
        break;
      case kind::channel: channel(op); break;
      case kind::copy_lab:
        if constexpr (in_memory(FB{})) {
          copy_lab(fb, r.sprite_area());
        } else {
          const scissor& area = r.sprite_area();
          for (int y = area.y0; y < area.y1 && area.x0 < area.x1; ++y)
            std::copy_n(&fb.lab(area.x0, y), area.x1 - area.x0, &fb.out(area.x0, y));
        }
        break;
      case kind::plain:
        with_regs<program_regs::plain>(op.regs, [&]<const pass_regs & R>() {
          r.draw_plain<R>(diffuse,
                          attributes(
                              ps.plain, o.model, [&](std::uint32_t v) { return plain_colour(ps.plain_light[v]); },
                              normal_map_uv, band.y0, band.y1),
                          view(op.buffer), result.plain_triangle);
        });
        break;
      case kind::dot_ready: {  // outside the sprite area no pass draws: 0x80, the two-buffer DPB's clear
        const FB& dpb = view(op.buffer);
        const scissor& drawn = r.sprite_area();
        for (int y = band.y0; y < band.y1; ++y) {
          std::uint8_t* row = &result.dot[static_cast<std::size_t>(op.light)][r.index(band.x0, y)];
          std::fill(row, row + (band.x1 - band.x0), std::uint8_t{0x80});
          if (y >= drawn.y0 && y < drawn.y1) {
            if constexpr (in_memory(FB{})) {
              dpb.row(y, drawn.x0, drawn.x1,
                      [&](int x, std::uint32_t w) { row[x - band.x0] = static_cast<std::uint8_t>(w & 0xFFu); });
            } else {
              low_bytes(&dpb(drawn.x0, y), row + (drawn.x0 - band.x0), drawn.x1 - drawn.x0);
            }
          }
        }
        break;
      }
      case kind::checkpoint: note(op.label, op.light, op.name, view(op.buffer)); break;
      case kind::display: {
        const FB& out = view(op.buffer);
        for (int y = band.y0; y < band.y1; ++y) {
          std::uint32_t* row = &result.colour[r.index(band.x0, y)];
          if constexpr (in_memory(FB{})) {
            out.row(y, band.x0, band.x1, [&](int x, std::uint32_t w) { row[x - band.x0] = w | 0xFF000000u; });
          } else {
            opaque(&out(band.x0, y), row, band.x1 - band.x0);
          }
        }
        break;
      }
    }
  return r.pixel_ops();
}

template <class FB>
void render_bands(const prepared_scene& ps, const render_options& o, const gs_inputs& in, const frame_program& prog,
                  frame_buffers<FB>& fb, frame& result) {
  const std::size_t pixels = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  // The value path's Z buffer, zeroed by the bands (the resize leaves a kept vector's words as they were).
  scratch<std::uint32_t> z(fb.zb.in_memory ? 0 : pixels);
  if (!fb.zb.in_memory) {
    z->resize(pixels);
    fb.zb.rows = row_view{z->data(), ps.width};
  }
  const int bands = o.trace != nullptr ? 1 : std::clamp(o.threads, 1, std::max(1, ps.height));
  std::vector<std::thread> workers;
  std::vector<std::size_t> ops(static_cast<std::size_t>(bands), 0);
  // The memory path's bands by rows, on whole pages: weighted by coverage they measured slower (band_split.hpp).
  const std::vector<int> first = fb.zb.in_memory ? band_rows(ps, bands, 32, 0) : band_rows(ps, bands, 1);
  for (int b = 0; b < bands; ++b) {
    const scissor band{0, first[static_cast<std::size_t>(b)], ps.width, first[static_cast<std::size_t>(b) + 1]};
    auto& count = ops[static_cast<std::size_t>(b)];
    if (b + 1 == bands) {
      count = render_band(ps, o, in, prog, band, fb, result);
    } else {
      workers.emplace_back([&, band] { count = render_band(ps, o, in, prog, band, fb, result); });
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
  auto start_result = [&] {
    result.colour.assign(n, 0);
    result.visible_triangle.assign(n, -1);
    result.plain_triangle.assign(n, -1);
    result.dot.assign(s.lights.size(), std::vector<std::uint8_t>(n, 0));
  };
  if (o.memory_path || o.dpb_clear != dpb_clear_mode::explicit_clear) {
    // The result's vectors are set by a second thread while this one clears the memory and uploads (neither
    // reads them); both are done before the bands start.
    std::jthread result_set;  // joins when it goes out of scope, also when an upload throws
    if (o.threads > 1)
      result_set = std::jthread(start_result);
    else
      start_result();
    const buffer_layout layout = buffer_layout_for(ps.width, ps.height);
    scratch<std::uint32_t> storage(gs::mem::memory_bytes / 4);
    gs::mem::local_memory memory(std::move(*storage));
    memory_buffers buffers(memory, layout, o.dpb_clear, ps.height);
    frame_buffers<memory_view>& fb = buffers.fb;
    render_options one = o;
    // Draw order is the model's: the z-trick clears; the one-buffer variant's alpha plane in the Z
    // buffer's words, whose pixels are not the Z buffer's (another band's depth tests read them).
    if (o.dpb_clear != dpb_clear_mode::explicit_clear || o.buffers == draw_buffers::one) one.threads = 1;
    gs_inputs uploaded = upload_inputs(memory, in, layout.first_texture_block(), one.threads > 1);
    if (uploaded.window_first != 0) one.threads = 1;  // the pieces' uploads share the window
    start_stream(uploaded, ps, o, band_renderer::drawn_area(ps, {0, 0, ps.width, ps.height}));
    if (result_set.joinable()) result_set.join();
    render_bands(ps, one, uploaded, build_frame_program(s, ps, m, o, uploaded), fb, result);
    *storage = std::move(memory).release();
  } else {
    start_result();
    // Value level: DPB, LAB, diffuse, output, frame-sized each, zeroed by the bands.
    scratch<std::uint32_t> rows(4 * n);
    rows->resize(4 * n);
    frame_buffers<row_view> fb;
    row_view* views[4] = {&fb.dpb, &fb.lab, &fb.diff, &fb.out};
    for (std::size_t k = 0; k < 4; ++k) *views[k] = row_view{rows->data() + k * n, ps.width};
    fb.alpha_plane[0] = fb.dpb, fb.alpha_plane[1] = fb.lab, fb.alpha_plane[2] = fb.out;
    render_bands(ps, o, in, build_frame_program(s, ps, m, o, in), fb, result);
  }
  return result;
}

}  // namespace gsdot3::pipeline
