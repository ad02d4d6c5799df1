#include "pipeline/frame_packets.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "gs_arith/registers.hpp"
#include "gs_memory/channel_fetch.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/builder.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/packed.hpp"
#include "gs_packets/packetiser.hpp"
#include "gs_packets/register_values.hpp"
#include "gs_packets/video_mode.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/frame_limits.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/pass_table.hpp"

namespace gsdot3::pipeline {

namespace {

using namespace passes;
namespace pk = gs::packets;

// The A+D addresses this stream writes (GS User's Manual register map; gs_registers.hpp's table).
constexpr std::uint8_t address(std::string_view name) { return *pk::gs_register_address(name); }

std::uint64_t rgbaq(gs::rgba8 c) { return gs::encode(gs::rgbaq_reg{c, 0x3F800000u}); }  // Q = 1.0

// log2 of the power of two >= n (TW / TH of a texture n texels wide).
fixed::u4 size_log2(int n) { return fixed::u4::from_wrapped(std::bit_width(static_cast<unsigned>(n - 1))); }

class stream {
 public:
  stream(const prepared_scene& ps, const buffer_layout& b, const scissor& area)
      : ps_(ps), b_(b), area_(area), frame_{0, 0, ps.width, ps.height} {}

  void set(std::uint8_t a, std::uint64_t v) { pending_.emplace_back(a, v); }
  void flush() {
    if (!pending_.empty()) out.ad(pending_);
    pending_.clear();
  }

  // FRAME_1 (a buffer of the layout, FBP `fbp`), ALPHA_1, COLCLAMP of a pass.
  void target(std::uint32_t fbp, const pass_regs& p, gs::frame_psm psm = gs::frame_psm::PSMCT32) {
    set(address("FRAME_1"), gs::encode(gs::frame_reg{fixed::uint<9>::from_wrapped(fbp),
                                                     fixed::uint<6>::from_wrapped(b_.fbw), psm, p.FBMSK}));
    set(address("ALPHA_1"), gs::encode(p.ALPHA));
    set(address("COLCLAMP"), gs::encode(gs::colclamp_reg{p.CLAMP}));
  }
  // TEST_1 and ZBUF_1 of a pass (pass_table.hpp's depth settings), ZBUF_1.ZBP the layout's Z buffer.
  void depth(const gs::test_reg& test, gs::zbuf_reg z) {
    set(address("TEST_1"), gs::encode(test));
    z.ZBP = fixed::uint<9>::from_wrapped(b_.z());
    set(address("ZBUF_1"), gs::encode(z));
  }
  // The local -> local copy of gs_inputs.hpp's lab_to_output (nothing when the area is empty).
  void copy(const std::optional<lab_copy>& c) {
    if (!c) return;
    set(address("BITBLTBUF"), gs::mem::encode(c->BITBLTBUF));
    set(address("TRXPOS"), gs::mem::encode(c->TRXPOS));
    set(address("TRXREG"), gs::mem::encode(c->TRXREG));
    set(address("TRXDIR"), gs::mem::encode(lab_copy::TRXDIR));
  }
  // SCISSOR_1 over r; an empty r (the sprite area of a frame that shows no triangle, which may lie at
  // row or column 0) as SCAX0 = 1 > SCAX1 = 0 and the same in y, which no pixel passes.
  void clip(const scissor& r) {
    const bool empty = r.x0 >= r.x1 || r.y0 >= r.y1;
    set(address("SCISSOR_1"),
        empty ? pk::scissor_value(1, 0, 1, 0) : pk::scissor_value(r.x0, r.x1 - 1, r.y0, r.y1 - 1));
  }
  // TEX0_1 (with the pass's TFX / TCC), TEX1_1, CLAMP_1.
  // cbp: the palette of a PSMT8 / PSMT8H texture, loaded (CLD = 1) unless `load` is false.
  void texture(const pass_regs& p, gs::mem::buffer at, int w, int h, std::optional<std::uint32_t> cbp, bool clamp,
               bool linear, const gs::mem::clamp_reg* region = nullptr, bool load = true) {
    gs::tex0_reg t;
    t.TBP0 = at.BP;
    t.TBW = at.BW;
    t.PSM = static_cast<gs::tex_psm>(at.PSM);
    t.TW = size_log2(w);
    t.TH = size_log2(h);
    t.TCC = p.TCC;
    t.TFX = p.TFX;
    if (cbp) {
      t.CBP = fixed::uint<14>::from_wrapped(*cbp);
      t.CLD = gs::u3::from_wrapped(load ? 1 : 0);
    }
    set(address("TEX0_1"), gs::encode(t));
    set(address("TEX1_1"), pk::tex1_value(linear, true));
    gs::mem::clamp_reg c;
    if (clamp) c.WMS = c.WMT = gs::mem::wrap_mode::CLAMP;
    set(address("CLAMP_1"), gs::mem::encode(region != nullptr ? *region : c));
  }
  void texflush() { set(address("TEXFLUSH"), 0); }

  // Every prepared triangle, PACKED {RGBAQ, UV, XYZ2} per vertex, PRE = 1; with `only` just those the
  // streamed texture's piece draws (stream_piece::draws: the others draw nothing in it).
  template <class Colour, class UV>
  void triangles(const pass_regs& p, bool gouraud, Colour&& colour, UV&& uv, const stream_piece* only = nullptr) {
    triangles_of(ps_.triangles, p, gouraud, colour, uv, only);
  }
  // The same for a list of triangles (the DOT3 mesh's, or step 5's).
  template <class Colour, class UV>
  void triangles_of(const std::vector<prepared_triangle>& tris, const pass_regs& p, bool gouraud, Colour&& colour,
                    UV&& uv, const stream_piece* only = nullptr) {
    flush();
    const gs::prim_reg prim{gs::prim_type::TRIANGLE, gouraud, p.TME, false, p.ABE, false, true, false, false};
    static constexpr unsigned regs[] = {pk::desc::RGBAQ, pk::desc::UV, pk::desc::XYZ2};
    std::vector<pk::qword> data;
    auto send = [&] {
      if (!data.empty()) out.packed(static_cast<std::uint32_t>(gs::encode(prim)), regs, data);
      data.clear();
    };
    for (std::uint32_t i = 0; i < tris.size(); ++i) {
      const prepared_triangle& t = tris[i];
      if (only != nullptr && !only->draws(i, t)) continue;
      for (int k = 0; k < 3; ++k) {
        const gs::rgba8 c = colour(t, k);
        const auto [u, v] = uv(t, k);
        const xy124 xy = t.setup.v[static_cast<std::size_t>(k)];
        data.push_back(pk::packed_rgba(c.r.value(), c.g.value(), c.b.value(), c.a.value()));
        data.push_back(pk::packed_uv(static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v)));
        data.push_back(pk::packed_xyz2(static_cast<std::uint16_t>(xy.x + 16 * xy_offset_pixels),
                                       static_cast<std::uint16_t>(xy.y + 16 * xy_offset_pixels),
                                       static_cast<std::uint32_t>(t.z24[static_cast<std::size_t>(k)]), false));
      }
      ++triangles_written;
      if (data.size() >= 3 * 3 * 10000) send();  // NLOOP = 3 per triangle, well under 32767
    }
    send();
  }

  // Every prepared triangle with PRIM.FST = 0: PACKED {ST (with Q), RGBAQ, XYZ2} per vertex, stq(t) its
  // three S, T, Q, vertex colour `colour` (the PACKED RGBAQ write takes the Q the ST write held).
  template <class Stq>
  void projective_triangles(const pass_regs& p, gs::rgba8 colour, Stq&& stq) {
    flush();
    const gs::prim_reg prim{gs::prim_type::TRIANGLE, false, p.TME, false, p.ABE, false, false, false, false};
    static constexpr unsigned regs[] = {pk::desc::ST, pk::desc::RGBAQ, pk::desc::XYZ2};
    std::vector<pk::qword> data;
    for (const prepared_triangle& t : ps_.triangles) {
      const std::array<gs::stq, 3> a = stq(t);
      for (std::size_t k = 0; k < 3; ++k) {
        const xy124 xy = t.setup.v[k];
        data.push_back(pk::packed_stq(std::bit_cast<std::uint32_t>(a[k].S), std::bit_cast<std::uint32_t>(a[k].T),
                                      std::bit_cast<std::uint32_t>(a[k].Q)));
        data.push_back(pk::packed_rgba(colour.r.value(), colour.g.value(), colour.b.value(), colour.a.value()));
        data.push_back(pk::packed_xyz2(static_cast<std::uint16_t>(xy.x + 16 * xy_offset_pixels),
                                       static_cast<std::uint16_t>(xy.y + 16 * xy_offset_pixels),
                                       static_cast<std::uint32_t>(t.z24[k]), false));
      }
      ++triangles_written;
      if (data.size() >= 3 * 3 * 10000) {  // NLOOP = 3 per triangle, well under 32767
        out.packed(static_cast<std::uint32_t>(gs::encode(prim)), regs, data);
        data.clear();
      }
    }
    if (!data.empty()) out.packed(static_cast<std::uint32_t>(gs::encode(prim)), regs, data);
  }

  // Sprites of one flat colour, each [x0, x1) × [y0, y1) drawn 1:1 from texel (u0, v0).
  struct rect {
    int x0, y0, x1, y1, u0, v0;
  };
  void sprites(const pass_regs& p, gs::rgba8 colour, const std::vector<rect>& rs) {
    if (rs.empty()) return;
    set(address("RGBAQ"), rgbaq(colour));
    flush();
    const gs::prim_reg prim{gs::prim_type::SPRITE, false, p.TME, false, p.ABE, false, true, false, false};
    static constexpr unsigned regs[] = {pk::desc::UV, pk::desc::XYZ2, pk::desc::UV, pk::desc::XYZ2};
    std::vector<pk::qword> data;
    auto corner = [&](int x, int y, int u, int v) {
      data.push_back(pk::packed_uv(static_cast<std::uint32_t>(16 * u), static_cast<std::uint32_t>(16 * v)));
      data.push_back(pk::packed_xyz2(static_cast<std::uint16_t>(16 * (x + xy_offset_pixels)),
                                     static_cast<std::uint16_t>(16 * (y + xy_offset_pixels)), 0, false));
    };
    for (const rect& r : rs) {
      corner(r.x0, r.y0, r.u0, r.v0);
      corner(r.x1, r.y1, r.u0 + (r.x1 - r.x0), r.v0 + (r.y1 - r.y0));
    }
    out.packed(static_cast<std::uint32_t>(gs::encode(prim)), regs, data);
    sprites_written += rs.size();
  }
  // One sprite over the sprite area (nothing when it is empty), texel (x, y) at pixel (x, y).
  void area_sprite(const pass_regs& p, gs::rgba8 colour) {
    if (area_.x0 < area_.x1 && area_.y0 < area_.y1)
      sprites(p, colour, {{area_.x0, area_.y0, area_.x1, area_.y1, area_.x0, area_.y0}});
  }
  void frame_sprite(const pass_regs& p, gs::rgba8 colour) { sprites(p, colour, {{0, 0, ps_.width, ps_.height, 0, 0}}); }

  // Byte `channel` of every pixel of buffer src_fbp through palette cbp into the current target:
  // gs_memory's channel-fetch sprites per page of the sprite area (as render.cpp's channel_pass).
  void channel_pass(const pass_regs& p, gs::rgba8 colour, std::uint32_t cbp, unsigned channel, std::uint32_t src_fbp) {
    const gs::mem::channel_fetch f = gs::mem::channel_fetch_sprites(channel);
    const scissor& a = area_;
    bool first = true;
    for (int py = a.y0 / 32; py * 32 < a.y1; ++py)
      for (int px = a.x0 / 64; px * 64 < a.x1; ++px) {
        const std::uint32_t page = src_fbp + static_cast<std::uint32_t>(px) + static_cast<std::uint32_t>(py) * b_.fbw;
        const gs::mem::buffer tex{fixed::uint<14>::from_wrapped(32 * page), fixed::uint<6>::from_wrapped(2 * b_.fbw),
                                  gs::mem::psm::PSMT8};
        texture(p, tex, 128, 64, cbp, false, false, &f.CLAMP, first);  // the CLUT loaded once per pass
        first = false;
        std::vector<rect> rs;
        for (const gs::mem::fetch_sprite& sp : f.sprites) {
          const int x0 = px * 64 + static_cast<int>(sp.x0), y0 = py * 32 + static_cast<int>(sp.y0);
          rs.push_back(
              {x0, y0, x0 + static_cast<int>(sp.x1 - sp.x0), y0 + static_cast<int>(sp.y1 - sp.y0), sp.u0, sp.v0});
        }
        sprites(p, colour, rs);
      }
  }

  const scissor& area() const { return area_; }
  const scissor& frame() const { return frame_; }

  pk::packet_builder out;
  std::size_t triangles_written = 0, sprites_written = 0;

 private:
  const prepared_scene& ps_;
  buffer_layout b_;
  scissor area_, frame_;
  std::vector<std::pair<std::uint8_t, std::uint64_t>> pending_;
};

// The stream's bytes and counts, the output buffer displayed.
void finish(frame_packets& fp, stream& g, const prepared_scene& ps, std::uint32_t out, const buffer_layout& b) {
  g.flush();
  fp.gif = g.out.bytes();
  fp.triangles = g.triangles_written;
  fp.sprites = g.sprites_written;
  fp.PMODE = pk::pmode_circuit1();
  fp.DISPFB1 = pk::dispfb_value(out, b.fbw);
  fp.width = ps.width;
  fp.height = ps.height;
}

}  // namespace

frame_packets build_frame_packets(const scene& s, const prepared_scene& ps, method m, const render_options& o) {
  check(s, m, o, frame_use::packets);
  frame_packets fp;
  fp.buffers = buffer_layout_for(ps.width, ps.height);
  const buffer_layout& b = fp.buffers;
  gs_inputs in = place_inputs(make_inputs(s, m, o), b.first_texture_block());
  const scissor area = detail::band_renderer::drawn_area(ps, {0, 0, ps.width, ps.height});
  start_stream(in, ps, o, area);
  if (in.stream && !ps.plain.empty()) throw std::invalid_argument(plain_needs_resident_texture);
  stream g(ps, b, area);
  // draw_buffers::one (render.cpp's one_buffer_steps): the output is every light's DPB, then the
  // LAB; the free alphas are those of the buffer at FBP 0, of the Z buffer's words (as PSMCT32) and
  // of the output.
  const bool one = o.buffers == draw_buffers::one;
  const std::uint32_t DPB = one ? b.output() : b.dpb(), LAB = one ? b.output() : b.lab(), OUT = b.output();
  const std::uint32_t plane[3] = {b.dpb(), b.z(), b.output()};

  // 1. Environment.
  g.set(address("PRMODECONT"), 1);
  g.set(address("XYOFFSET_1"), pk::xyoffset_value(16 * xy_offset_pixels, 16 * xy_offset_pixels));
  g.clip(g.frame());
  g.set(address("DTHE"), gs::encode(gs::dthe_reg{false}));
  g.set(address("PABE"), gs::encode(gs::pabe_reg{false}));
  g.set(address("FBA_1"), gs::encode(gs::fba_reg{false}));
  // 2. Uploads.
  g.flush();
  add_uploads(g.out, in);
  g.texflush();
  // 3. Clears over the frame; the output and the Z buffer by one sprite (colour 0, Z 0).
  g.depth(depth_always, z_masked);
  g.target(b.dpb(), step1_ambient);
  g.frame_sprite(step1_ambient, gs::rgba8::from_u32(clear_dpb));
  g.target(b.lab(), step1_ambient);
  g.frame_sprite(step1_ambient, gs::rgba8{});
  g.depth(depth_always, z_written);
  g.target(OUT, step1_ambient);
  g.frame_sprite(step1_ambient, gs::rgba8{});

  // 4. Step 1: Z and ambient.
  const auto nm_uv = [](const prepared_triangle& t, int k) { return normal_map_uv(t, k); };
  const gs::rgba8 ambient = rgb(s.ambient[0], s.ambient[1], s.ambient[2], 0x80);
  g.depth(depth_gequal, z_written);
  g.target(LAB, step1_ambient);
  g.triangles(
      step1_ambient, false, [&](const prepared_triangle&, int) { return ambient; }, nm_uv);

  const bool linear = o.bilinear;
  const stream_texture diffuse_texels = diffuse_stream(in);
  // A pass drawing the normal map (through palette cbp) or the diffuse texture into fbp: its
  // TEX0_1, TEX1_1, CLAMP_1, FRAME_1 ... and triangles; with the texture streamed, per piece its
  // uploads and TEXFLUSH, SCISSOR_1 = the piece, TEX0_1 with the piece's TBP0 / TBW (the CLUT loaded
  // by the first) and the triangles that reach the piece.
  auto textured = [&](const pass_regs& p, std::uint32_t fbp, std::optional<std::uint32_t> cbp, const stream_texture& t,
                      const gs::mem::buffer& at, auto&& colour, auto&& uv) {
    if (!in.stream) {
      g.texture(p, at, t.width, t.height, cbp, false, linear);
      g.target(fbp, p);
      g.triangles(p, true, colour, uv);
      return;
    }
    g.target(fbp, p);
    bool first = true;
    for (const stream_piece& piece : in.stream->next_pass(t)) {
      g.flush();
      add_piece_uploads(g.out, t, piece);
      if (!piece.uploads.empty()) g.texflush();
      g.clip(piece.area);
      g.texture(p, piece.at, t.width, t.height, cbp, false, linear, nullptr, first);
      first = false;
      g.triangles(p, true, colour, uv, &piece);
    }
    g.clip(g.frame());
  };
  auto white_vertex = [](const prepared_triangle&, int) { return white; };
  auto cbp = [&](clut_slot c) { return in.cbp[static_cast<std::size_t>(c)]; };
  // Step 3: buffer fbp cleared to zero over the sprite area (clear's FBMSK kept) and the diffuse layer
  // drawn into it.
  auto diffuse_step = [&](std::uint32_t fbp, const pass_regs& clear, const pass_regs& layer) {
    g.clip(area);
    g.depth(depth_always, z_masked);
    g.target(fbp, clear);
    g.area_sprite(clear, gs::rgba8{});
    g.clip(g.frame());
    g.depth(depth_gequal, z_masked);
    textured(layer, fbp, std::nullopt, diffuse_texels, in.diffuse_at, white_vertex, nm_uv);
  };
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    const std::vector<light_vertex>& lv = ps.lights[l];
    auto at = [&](const prepared_triangle& t, int k) -> const light_vertex& {
      return lv[t.vertex[static_cast<std::size_t>(k)]];
    };
    // 2.1: the DPB cleared over the sprite area.
    g.clip(area);
    g.depth(depth_always, z_masked);
    g.target(DPB, step1_ambient);
    g.area_sprite(step1_ambient, gs::rgba8::from_u32(clear_dpb));
    g.clip(g.frame());
    g.depth(depth_gequal, z_masked);
    // 2.3 (and two-pass's 2.4a): the method's light passes (Gouraud's for a Gouraud light, lod.hpp),
    // pass_table.hpp's list in draw order.
    // Section 3.6's spot light where spot_step says (render.cpp): its texture (CLAMP, nearest), ST/Q.
    const spot_step spot_at = spot_placement(light_method(m, s.lights[l]), o);
    auto spot_pass = [&](spot_step when) {  // whether it drew
      if (!ps.spot(l) || when != spot_at) return false;
      const pass_regs& regs = when == spot_step::after_post_filter ? spot_attenuation_red : spot_attenuation;
      g.clip(g.frame());
      g.depth(depth_gequal, z_masked);
      g.texture(regs, in.spot_at, spot_map_size, spot_map_size, std::nullopt, true, false);
      g.target(DPB, regs);
      g.projective_triangles(regs, white, [&](const prepared_triangle& t) { return spot_stq(ps, l, t); });
      return true;
    };
    std::size_t drawn = 0;
    for (const light_pass& p : describe(light_method(m, s.lights[l])).light) {
      if (drawn++ == 1) spot_pass(spot_step::after_first_pass);  // after the first pass, before the second
      const pass_regs& regs = *p.regs;
      const std::uint32_t cbp = in.cbp[static_cast<std::size_t>(p.clut)];
      auto colour = [&](const prepared_triangle& t, int k) { return vertex_rgbaq(p.colour, at(t, k), o.s); };
      switch (p.source) {
        case pass_source::normal_map: {
          const std::size_t k = normal_map_of(in, p.clut);
          textured(regs, DPB, cbp, normal_map_stream(in, k), in.nm_at[k], colour, nm_uv);
          break;
        }
        case pass_source::sphere_map:
          g.texture(regs, in.sphere_at, 64, 64, std::nullopt, true, false);
          g.target(DPB, regs);
          g.triangles(regs, true, colour,
                      [&](const prepared_triangle& t, int k) { return vertex_uv(p.source, t, k, lv); });
          break;
        case pass_source::untextured:  // TME = 0: no TEX0, the UV sent is not read
          g.target(DPB, regs);
          g.triangles(regs, true, colour, nm_uv);
          break;
        case pass_source::dpb_alpha: {  // the DPB read as PSMT8H through the palette, 1:1
          g.clip(area);
          g.depth(depth_always, z_masked);
          g.texflush();
          gs::mem::buffer t8h = b.colour(DPB);
          t8h.PSM = gs::mem::psm::PSMT8H;
          g.texture(regs, t8h, ps.width, ps.height, cbp, false, false);
          g.target(DPB, regs);
          g.area_sprite(regs, white);
          break;
        }
      }
    }
    spot_pass(spot_step::after_light_passes);
    // 2.4: R += G, R += B; 2.5, 2.6: ILP[sum] × light colour added into the LAB.
    g.clip(area);
    g.depth(depth_always, z_masked);
    g.target(DPB, post_add_into_red);
    for (unsigned c : {1u, 2u}) {
      g.texflush();
      g.channel_pass(post_add_into_red, white, cbp(clut_slot::grey), c, DPB);
    }
    if (spot_pass(spot_step::after_post_filter)) {  // the post filter's clip and depth again
      g.clip(area);
      g.depth(depth_always, z_masked);
    }
    g.texflush();
    if (one) {  // the dot layer into free alpha l
      g.target(plane[l], move_into_alpha);
      g.channel_pass(move_into_alpha, white, cbp(clut_slot::alpha_index), 0, DPB);
      continue;
    }
    const auto& lc = s.lights[l].colour;
    g.target(LAB, ilp_into_lab);
    g.channel_pass(ilp_into_lab, rgb(lc[0], lc[1], lc[2], 0x80), cbp(clut_slot::ilp), 0, DPB);
  }

  // Step 5 (section 3.1, render.cpp): the non-normal-mapped geometry into the output over the whole
  // frame, Gouraud × the diffuse texture (resident: plain_needs_resident_texture), Z written.
  auto plain_step = [&] {
    if (ps.plain.empty()) return;
    g.clip(g.frame());
    g.depth(depth_gequal, z_written);
    g.texture(plain_gouraud, in.diffuse_at, in.diffuse->width, in.diffuse->height, std::nullopt, false, linear);
    g.target(OUT, plain_gouraud);
    g.triangles_of(
        ps.plain, plain_gouraud, true,
        [&](const prepared_triangle& t, int k) {
          return plain_colour(ps.plain_light[t.vertex[static_cast<std::size_t>(k)]]);
        },
        nm_uv);
  };
  if (one) {  // render.cpp's one_buffer_steps: 2.6 from the free alphas, their LAB channels, 3, 4
    g.clip(area);
    g.depth(depth_always, z_masked);
    g.target(OUT, flat_rgb);
    g.area_sprite(flat_rgb, rgb(s.ambient[0], s.ambient[1], s.ambient[2], 0x80));
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const auto& lc = s.lights[l].colour;
      g.texflush();
      g.target(OUT, ilp_into_lab);
      g.channel_pass(ilp_into_lab, rgb(lc[0], lc[1], lc[2], 0x80), cbp(clut_slot::ilp), 3, plane[l]);
    }
    for (unsigned c = 0; c < 3; ++c) {
      g.texflush();
      g.target(plane[c], move_into_alpha);
      g.channel_pass(move_into_alpha, white, cbp(clut_slot::alpha_index), c, OUT);
    }
    diffuse_step(OUT, flat_rgb, diffuse_layer_rgb);
    g.depth(depth_always, z_masked);
    g.clip(area);
    const pass_regs* multiply[3] = {&multiply_red_by_as, &multiply_green_by_as, &multiply_blue_by_as};
    for (unsigned c = 0; c < 3; ++c) {
      g.texflush();
      g.target(OUT, *multiply[c]);
      g.channel_pass(*multiply[c], white, cbp(clut_slot::alpha_index), 3, plane[c]);
    }
    plain_step();
    finish(fp, g, ps, OUT, b);
    return fp;
  }

  // Step 3: the DPB cleared to zero over the sprite area and the diffuse layer drawn into it.
  diffuse_step(DPB, step1_ambient, diffuse_layer);

  // Step 4: the LAB copied into the output by the renderer's transfer; per channel the LAB byte
  // moved into the output's alpha, then diffuse (the DPB) × alpha into that channel.
  g.depth(depth_always, z_masked);
  g.clip(area);
  g.copy(lab_to_output(b, area, false));
  const pass_regs* multiply[3] = {&multiply_red, &multiply_green, &multiply_blue};
  for (unsigned c = 0; c < 3; ++c) {
    g.texflush();
    g.target(OUT, move_into_alpha);
    g.channel_pass(move_into_alpha, white, cbp(clut_slot::alpha_index), c, LAB);
    g.texflush();
    g.texture(*multiply[c], b.colour(DPB), ps.width, ps.height, std::nullopt, false, false);
    g.target(OUT, *multiply[c]);
    g.area_sprite(*multiply[c], white);
  }
  plain_step();
  finish(fp, g, ps, OUT, b);
  return fp;
}

}  // namespace gsdot3::pipeline
