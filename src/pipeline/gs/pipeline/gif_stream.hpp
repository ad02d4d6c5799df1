// pipeline/gif_stream.hpp — the GIF packets of frame_packets.cpp's operations: the A+D register writes
// (FRAME_1, ALPHA_1, COLCLAMP, TEST_1, ZBUF_1, SCISSOR_1, TEX0_1 ...) batched until a primitive, and the
// primitives as PACKED GIF tags (triangles: {RGBAQ, UV, XYZ2} or, FST = 0, {ST, RGBAQ, XYZ2} per vertex;
// sprites: {UV, XYZ2, UV, XYZ2}), the channel-fetch sprites per page. Internal to frame_packets.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "gs_arith/registers.hpp"
#include "gs_memory/channel_fetch.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_memory/overlay.hpp"
#include "gs_packets/builder.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/packed.hpp"
#include "gs_packets/register_values.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/pass_table.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/texture_stream.hpp"

namespace gsdot3::pipeline::gif {

namespace pk = gs::packets;

// The A+D addresses this stream writes (GS User's Manual register map; gs_registers.hpp's table).
inline constexpr std::uint8_t address(std::string_view name) { return *pk::gs_register_address(name); }

inline std::uint64_t rgbaq(gs::rgba8 c) { return gs::encode(gs::rgbaq_reg{c, 0x3F800000u}); }  // Q = 1.0

// log2 of the power of two >= n (TW / TH of a texture n texels wide).
inline fixed::u4 size_log2(int n) { return fixed::u4::from_wrapped(std::bit_width(static_cast<unsigned>(n - 1))); }

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
  // TEST_1 and ZBUF_1 of a pass (pass_table.hpp's depth settings), ZBUF_1.ZBP = zbp (the layout's Z
  // buffer; the DPB for the z-trick clear).
  void depth(const gs::test_reg& test, gs::zbuf_reg z, std::uint32_t zbp) {
    set(address("TEST_1"), gs::encode(test));
    z.ZBP = fixed::uint<9>::from_wrapped(zbp);
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

  // The prepared triangles `range` (every one by default), PACKED {RGBAQ, UV, XYZ2} per vertex,
  // PRE = 1; with `only` just those the streamed texture's piece draws (stream_piece::draws: the others
  // draw nothing in it).
  template <class Colour, class UV>
  void triangles(const pass_regs& p, bool gouraud, Colour&& colour, UV&& uv, const stream_piece* only = nullptr,
                 std::optional<triangle_range> range = std::nullopt) {
    triangles_of(ps_.triangles, p, gouraud, colour, uv, only, range);
  }
  // The same for a list of triangles (the DOT3 mesh's, or step 5's).
  template <class Colour, class UV>
  void triangles_of(const std::vector<prepared_triangle>& tris, const pass_regs& p, bool gouraud, Colour&& colour,
                    UV&& uv, const stream_piece* only = nullptr, std::optional<triangle_range> range = std::nullopt) {
    flush();
    const gs::prim_reg prim{gs::prim_type::TRIANGLE, gouraud, p.TME, false, p.ABE, false, true, false, false};
    static constexpr unsigned regs[] = {pk::desc::RGBAQ, pk::desc::UV, pk::desc::XYZ2};
    std::vector<pk::qword> data;
    auto send = [&] {
      if (!data.empty()) out.packed(static_cast<std::uint32_t>(gs::encode(prim)), regs, data);
      data.clear();
    };
    const triangle_range r = range.value_or(triangle_range{0, static_cast<std::uint32_t>(tris.size())});
    for (std::uint32_t i = r.first; i < r.end; ++i) {
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

  // Sprites of one flat colour, each [x0, x1) × [y0, y1) drawn 1:1 from texel (u0, v0), at Z = z.
  struct rect {
    int x0, y0, x1, y1, u0, v0;
  };
  void sprites(const pass_regs& p, gs::rgba8 colour, const std::vector<rect>& rs, std::uint32_t z = 0) {
    if (rs.empty()) return;
    set(address("RGBAQ"), rgbaq(colour));
    flush();
    const gs::prim_reg prim{gs::prim_type::SPRITE, false, p.TME, false, p.ABE, false, true, false, false};
    static constexpr unsigned regs[] = {pk::desc::UV, pk::desc::XYZ2, pk::desc::UV, pk::desc::XYZ2};
    std::vector<pk::qword> data;
    auto corner = [&](int x, int y, int u, int v) {
      data.push_back(pk::packed_uv(static_cast<std::uint32_t>(16 * u), static_cast<std::uint32_t>(16 * v)));
      data.push_back(pk::packed_xyz2(static_cast<std::uint16_t>(16 * (x + xy_offset_pixels)),
                                     static_cast<std::uint16_t>(16 * (y + xy_offset_pixels)), z, false));
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
  // gs_memory's channel-fetch sprites per page of the sprite area (as render.cpp's channel_pass), at
  // Z = z; a source in the Z layout has the tile that fetches PSMCT32 pixel M drawn at zsigma(M).
  void channel_pass(const pass_regs& p, gs::rgba8 colour, std::uint32_t cbp, unsigned channel, std::uint32_t src_fbp,
                    bool z_layout, std::uint32_t z) {
    const gs::mem::channel_fetch f = gs::mem::channel_fetch_sprites(channel);
    per_page(src_fbp, [&](int px, int py, std::uint32_t page, bool first) {
      const gs::mem::buffer tex{fixed::uint<14>::from_wrapped(32 * page), fixed::uint<6>::from_wrapped(2 * b_.fbw),
                                gs::mem::psm::PSMT8};
      texture(p, tex, 128, 64, cbp, false, false, &f.CLAMP, first);  // the CLUT loaded once per pass
      std::vector<rect> rs;
      for (const gs::mem::fetch_sprite& sp : f.sprites) {
        const int mx = px * 64 + static_cast<int>(sp.x0), my = py * 32 + static_cast<int>(sp.y0);
        const auto [x0, y0] = z_layout ? gs::mem::zsigma(mx, my) : std::array<int, 2>{mx, my};
        rs.push_back(
            {x0, y0, x0 + static_cast<int>(sp.x1 - sp.x0), y0 + static_cast<int>(sp.y1 - sp.y0), sp.u0, sp.v0});
      }
      sprites(p, colour, rs, z);
    });
  }
  // Two-pass step 2.4a from a DPB drawn in the Z layout: logical pixel (x, y) is the PSMT8H texel of
  // PSMCT32 pixel zsigma(x, y), so per page of the sprite area TEX0_1 = that page (PSMT8H, palette cbp
  // loaded by the first) and one sprite per 32x16 quarter reading the quarter zsigma swaps it with.
  void t8h_quarters(const pass_regs& p, std::uint32_t cbp, std::uint32_t src_fbp) {
    const scissor& a = area_;
    per_page(src_fbp, [&](int px, int py, std::uint32_t page, bool first) {
      const gs::mem::buffer tex{fixed::uint<14>::from_wrapped(32 * page), fixed::uint<6>::from_wrapped(b_.fbw),
                                gs::mem::psm::PSMT8H};
      texture(p, tex, 64, 32, cbp, false, false, nullptr, first);
      std::vector<rect> rs;
      for (int qy = 0; qy < 32; qy += 16)
        for (int qx = 0; qx < 64; qx += 32) {
          const int x0 = px * 64 + qx, y0 = py * 32 + qy;
          const auto [u0, v0] = gs::mem::zsigma(qx, qy);
          if (x0 < a.x1 && x0 + 32 > a.x0 && y0 < a.y1 && y0 + 16 > a.y0)
            rs.push_back({x0, y0, x0 + 32, y0 + 16, u0, v0});
        }
      sprites(p, passes::white, rs);
    });
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

  // f(px, py, page, first) for every page (px, py) the sprite area touches, in rows, with `page` the
  // FBP of that page of the buffer at src_fbp and `first` true for the first.
  template <class F>
  void per_page(std::uint32_t src_fbp, F&& f) {
    const scissor& a = area_;
    bool first = true;
    for (int py = a.y0 / 32; py * 32 < a.y1; ++py)
      for (int px = a.x0 / 64; px * 64 < a.x1; ++px) {
        f(px, py, src_fbp + static_cast<std::uint32_t>(px) + static_cast<std::uint32_t>(py) * b_.fbw, first);
        first = false;
      }
  }
};

}  // namespace gsdot3::pipeline::gif
