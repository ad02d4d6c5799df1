// pipeline/frame_packets.cpp — the frame program (frame_program.hpp) encoded as GIF packets:
// frame_packets.hpp describes the stream; gif_stream.hpp writes its registers and primitives.
#include "pipeline/frame_packets.hpp"

#include <optional>
#include <stdexcept>

#include "pipeline/band_renderer.hpp"
#include "pipeline/frame_limits.hpp"
#include "pipeline/frame_program.hpp"
#include "pipeline/gif_stream.hpp"

namespace gsdot3::pipeline {

namespace {

using namespace passes;
using kind = frame_op::kind;

// The FBP of a buffer role (frame_program.hpp): the diffuse layer is drawn in the DPB's memory.
std::uint32_t fbp(const buffer_layout& b, buffer_role r) {
  switch (r) {
    case buffer_role::dpb:
    case buffer_role::diffuse: return b.dpb();
    case buffer_role::lab: return b.lab();
    case buffer_role::output: return b.output();
    case buffer_role::z_words: return b.z();
  }
  throw std::logic_error("unknown buffer role");
}

struct encoder {
  const prepared_scene& ps;
  const render_options& o;
  const gs_inputs& in;
  const frame_program& prog;
  const buffer_layout& b;
  gif::stream g;

  // Slot c's CBP in layer l (the shared palettes: layer 0's).
  std::uint32_t cbp(clut_slot c, int l = 0) const {
    return in.cbp.at(l < 0 ? 0 : static_cast<std::size_t>(l))[static_cast<std::size_t>(c)];
  }
  bool z_layout(buffer_role r) const { return in_z_layout(r, o.dpb_clear); }
  std::optional<std::uint32_t> palette(const frame_op& op) const {
    return op.no_clut ? std::nullopt : std::optional<std::uint32_t>(cbp(op.clut, op.layer));
  }
  static gs::rgba8 white_vertex(const prepared_triangle&, int) { return white; }
  static std::array<std::int32_t, 2> nm_uv(const prepared_triangle& t, int k) { return normal_map_uv(t, k); }

  void texture(const frame_op& op) {
    const pass_regs& r = *op.regs;
    switch (op.texture) {
      case texture_role::normal_map:
        return g.texture(r, in.nm_at.at(texture_index(in, static_cast<std::size_t>(op.layer), op.normal_map)),
                         in.nm->width, in.nm->height, palette(op), false, o.bilinear);
      case texture_role::piece: {
        const stream_texture& t = prog.streamed[static_cast<std::size_t>(op.stream)];
        const stream_piece& p = prog.pieces[static_cast<std::size_t>(op.piece)];
        return g.texture(r, p.at, t.width, t.height, palette(op), false, o.bilinear, nullptr, op.load);
      }
      case texture_role::sphere_map: return g.texture(r, in.sphere_at, 64, 64, std::nullopt, true, false);
      case texture_role::spot_map:
        return g.texture(r, in.spot_at, spot_map_size, spot_map_size, std::nullopt, true, false);
      case texture_role::diffuse:
        return g.texture(r, in.diffuse_at, in.diffuse->width, in.diffuse->height, std::nullopt, false, o.bilinear);
      case texture_role::buffer_t8h:
        if (z_layout(op.source)) return;  // its pages' TEX0_1 are the draw's (gif::stream::t8h_quarters)
        [[fallthrough]];
      case texture_role::buffer_ct32: {
        gs::mem::buffer at = b.colour(fbp(b, op.source));
        if (op.texture == texture_role::buffer_t8h) at.PSM = gs::mem::psm::PSMT8H;
        return g.texture(r, at, ps.width, ps.height, palette(op), false, false);
      }
      case texture_role::none: break;
    }
    throw std::logic_error("a texture operation without a texture");
  }

  void triangles(const frame_op& op) {
    const stream_piece* piece = op.piece < 0 ? nullptr : &prog.pieces[static_cast<std::size_t>(op.piece)];
    const std::optional<triangle_range> range =
        op.layer < 0 ? std::nullopt : std::optional<triangle_range>(ps.layer(static_cast<std::size_t>(op.layer)));
    if (op.light < 0) return g.triangles(*op.regs, true, white_vertex, nm_uv, piece, range);
    const std::vector<light_vertex>& lv = ps.lights[static_cast<std::size_t>(op.light)];
    const pass_source src = op.texture == texture_role::sphere_map ? pass_source::sphere_map : pass_source::normal_map;
    g.triangles(
        *op.regs, true,
        [&](const prepared_triangle& t, int k) {
          return vertex_rgbaq(op.colour_of, lv[t.vertex[static_cast<std::size_t>(k)]], o.s);
        },
        [&](const prepared_triangle& t, int k) { return vertex_uv(src, t, k, lv); }, piece, range);
  }

  void run(const frame_op& op) {
    switch (op.what) {
      case kind::environment:
        g.set(gif::address("PRMODECONT"), 1);
        g.set(gif::address("XYOFFSET_1"), gs::packets::xyoffset_value(16 * xy_offset_pixels, 16 * xy_offset_pixels));
        g.clip(g.frame());
        g.set(gif::address("DTHE"), gs::encode(gs::dthe_reg{false}));
        g.set(gif::address("PABE"), gs::encode(gs::pabe_reg{false}));
        g.set(gif::address("FBA_1"), gs::encode(gs::fba_reg{false}));
        return;
      case kind::uploads: return g.flush(), add_uploads(g.out, in), g.texflush();
      case kind::scissor:
        return g.clip(op.area == area_role::frame          ? g.frame()
                      : op.area == area_role::sprite_area  ? g.area()
                      : op.area == area_role::sprite_pages ? whole_pages(g.area())
                                                           : prog.pieces[static_cast<std::size_t>(op.piece)].area);
      case kind::depth: return g.depth(*op.test, *op.zbuf, fbp(b, op.buffer));
      case kind::target:
        return g.target(fbp(b, op.buffer), *op.regs,
                        z_layout(op.buffer) ? gs::frame_psm::PSMZ32 : gs::frame_psm::PSMCT32);
      case kind::texflush: return g.texflush();
      case kind::texture: return texture(op);
      case kind::piece_uploads:
        g.flush();
        return add_piece_uploads(g.out, prog.streamed[static_cast<std::size_t>(op.stream)],
                                 prog.pieces[static_cast<std::size_t>(op.piece)]);
      case kind::fill:
        return op.area == area_role::frame ? g.frame_sprite(*op.regs, op.colour) : g.area_sprite(*op.regs, op.colour);
      case kind::ambient:
        return g.triangles(
            *op.regs, false, [&](const prepared_triangle&, int) { return op.colour; }, nm_uv);
      case kind::triangles: return triangles(op);
      case kind::projective:
        return g.projective_triangles(*op.regs, white, [&](const prepared_triangle& t) {
          return spot_stq(ps, static_cast<std::size_t>(op.light), t);
        });
      case kind::buffer_sprite:
        if (op.texture == texture_role::buffer_t8h && z_layout(op.source))
          return g.t8h_quarters(*op.regs, cbp(op.clut), fbp(b, op.source));
        return g.area_sprite(*op.regs, white);
      case kind::channel:
        return g.channel_pass(*op.regs, op.colour, cbp(op.clut), op.channel, fbp(b, op.source), z_layout(op.source),
                              op.z_clear ? clear_dpb : 0);
      case kind::copy_lab: return g.copy(lab_to_output(b, g.area(), z_layout(buffer_role::lab)));
      case kind::plain:
        return g.triangles_of(
            ps.plain, *op.regs, true,
            [&](const prepared_triangle& t, int k) {
              return plain_colour(ps.plain_light[t.vertex[static_cast<std::size_t>(k)]]);
            },
            nm_uv);
      case kind::dot_ready:
      case kind::checkpoint: return;
      case kind::display: return g.flush();
    }
  }
};

}  // namespace

frame_packets build_frame_packets(const scene& s, const prepared_scene& ps, method m, const render_options& o) {
  check(s, m, o, frame_use::packets);
  frame_packets fp;
  fp.buffers = buffer_layout_for(ps.width, ps.height);
  const buffer_layout& b = fp.buffers;
  gs_inputs in = place_inputs(make_inputs(s, m, o), b.first_texture_block());
  const scissor area = detail::band_renderer::drawn_area(ps, {0, 0, ps.width, ps.height});
  start_stream(in, ps, o, area);
  const frame_program prog = build_frame_program(s, ps, m, o, in);
  encoder e{ps, o, in, prog, b, gif::stream(ps, b, area)};
  std::uint32_t out = b.output();
  for (const frame_op& op : prog.ops) {
    e.run(op);
    if (op.what == kind::display) out = fbp(b, op.buffer);
  }
  e.g.flush();
  fp.gif = e.g.out.bytes();
  fp.triangles = e.g.triangles_written;
  fp.sprites = e.g.sprites_written;
  fp.PMODE = gs::packets::pmode_circuit1();
  fp.DISPFB1 = gs::packets::dispfb_value(out, b.fbw);
  fp.width = ps.width;
  fp.height = ps.height;
  return fp;
}

}  // namespace gsdot3::pipeline
