// probe/frame.cpp — the probe's frame through gs_memory and gs::pixel_pipeline (see frame.hpp).
#include "probe/frame.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>

#include "gs_arith/bilinear.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/uv_plane.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/texture_buffer.hpp"
#include "gs_memory/transfer.hpp"
#include "probe/design.hpp"

namespace gsdot3::probe {
namespace {

namespace mem = gs::mem;

mem::buffer frame_buffer(const gs::frame_reg& f) {
  return {mem::from_page(f.FBP), f.FBW, static_cast<mem::psm>(static_cast<std::uint8_t>(f.PSM))};
}

void upload_texture(mem::local_memory& m, const std::vector<std::uint32_t>& texels) {
  mem::bitbltbuf_reg b;
  b.DBP = fixed::uint<14>::from_wrapped(texture_page * 32);
  b.DBW = fixed::uint<6>::from_wrapped(1);
  mem::trxreg_reg size;
  size.RRW = size.RRH = fixed::uint<12>::from_wrapped(texture_side);
  std::vector<std::uint8_t> bytes;
  for (const std::uint32_t t : texels)
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<std::uint8_t>(t >> (8 * k)));
  mem::host_to_local(m, b, mem::trxpos_reg{}, size, mem::trxdir_reg{}, bytes);
}

// The bytes a texture's 2^TH rows of pages cover (the draw_snapshot copy).
std::pair<std::uint32_t, std::uint32_t> texture_extent(const gs::tex0_reg& t) {
  const std::uint32_t first = t.TBP0.value() * mem::block_bytes;
  const std::uint32_t rows = ((1u << t.TH.value()) + 31) / 32;
  const std::uint32_t size = rows * t.TBW.value() * mem::page_bytes;
  return {first, std::min(size, mem::memory_bytes - first)};
}

bool same_state(const draw& a, const draw& b) {
  return a.regs == b.regs && a.linear == b.linear && a.scissor == b.scissor;
}

gs::rgba8 fetch_texel(mem::texture_page_buffer& tb, const gs::tex0_reg& t, std::int32_t u, std::int32_t v) {
  const auto wrap = [](std::int32_t c, unsigned log2) {
    return static_cast<std::uint32_t>(c) & ((1u << log2) - 1);
  };  // REPEAT
  const mem::buffer tex{t.TBP0, t.TBW, t.PSM};
  const mem::location at = mem::locate(tex, wrap(u, t.TW.value()), wrap(v, t.TH.value()));
  std::uint32_t w = 0;
  for (std::uint32_t k = 0; k < 4; ++k) w |= std::uint32_t{tb.fetch(at.byte + k)} << (8 * k);
  return gs::rgba8::from_u32(w);
}

bool inside_triangle(const std::vector<vertex>& v, int x, int y) {
  auto edge = [&](const vertex& a, const vertex& b) {
    return static_cast<long long>(b.x - a.x) * (y - a.y) - static_cast<long long>(b.y - a.y) * (x - a.x);
  };
  const long long e0 = edge(v[0], v[1]), e1 = edge(v[1], v[2]), e2 = edge(v[2], v[0]);
  return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
}

void draw_primitive(mem::local_memory& m, const draw& d, std::optional<mem::texture_page_buffer>& tb,
                    const gs::model_options& o) {
  const bool triangle = d.regs.PRIM.PRIM == gs::prim_type::TRIANGLE;
  if (!triangle && d.regs.PRIM.PRIM != gs::prim_type::SPRITE)
    throw std::logic_error("probe: only sprites and triangles");
  if (d.regs.PRIM.TME && d.regs.TEX0_1.PSM != gs::tex_psm::PSMCT32)
    throw std::logic_error("probe: PSMCT32 textures only");
  const vertex& last = d.v.back();
  std::optional<gs::gouraud_plane> plane;
  if (triangle && d.regs.PRIM.IIP) {
    auto gv = [](const vertex& p) { return gs::gouraud_vertex{p.x * 16, p.y * 16, gs::rgba8::from_u32(p.rgba)}; };
    plane = gs::gouraud_triangle(gv(d.v[0]), gv(d.v[1]), gv(d.v[2]), d.v[0].x, d.v[0].y);
    if (plane) plane->clip_x0 = d.scissor.x0;  // pcsx2_rows: a row starts at SCISSOR's left at the latest
  }
  // A textured triangle's U and V planes under the options' UV rule (uv_plane.hpp; constant where every
  // vertex has one UV); a sprite samples its last vertex's UV at every pixel.
  std::optional<std::array<gs::plane, 2>> uv;
  if (triangle && d.regs.PRIM.TME) {
    const std::array<gs::xy124, 3> p{
        {{d.v[0].x * 16, d.v[0].y * 16}, {d.v[1].x * 16, d.v[1].y * 16}, {d.v[2].x * 16, d.v[2].y * 16}}};
    uv = {gs::make_uv_plane(p, {d.v[0].u16, d.v[1].u16, d.v[2].u16}, gs::uv_rule_of(o)),
          gs::make_uv_plane(p, {d.v[0].v16, d.v[1].v16, d.v[2].v16}, gs::uv_rule_of(o))};
  }
  auto sample_at = [&](std::int32_t u16, std::int32_t v16) {
    const gs::bilinear_mode mode = d.linear ? o.bilinear : gs::bilinear_mode::nearest;
    return gs::sample([&](std::int32_t u, std::int32_t v) { return fetch_texel(*tb, d.regs.TEX0_1, u, v); }, u16, v16,
                      mode);
  };
  // Without UV planes one texel serves the whole primitive: fetched once, before its writes.
  const gs::rgba8 one_texel = d.regs.PRIM.TME && !uv ? sample_at(last.u16, last.v16) : gs::rgba8{};
  auto texel_at = [&](int x, int y) { return uv ? sample_at((*uv)[0].at(x, y), (*uv)[1].at(x, y)) : one_texel; };
  int x0 = d.scissor.x0, y0 = d.scissor.y0, x1 = d.scissor.x1 + 1, y1 = d.scissor.y1 + 1;
  if (!triangle) {
    x0 = std::max(x0, d.v[0].x), y0 = std::max(y0, d.v[0].y);
    x1 = std::min(x1, d.v[1].x), y1 = std::min(y1, d.v[1].y);
  }
  const mem::buffer fb = frame_buffer(d.regs.FRAME_1);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      if (triangle && !inside_triangle(d.v, x, y)) continue;
      const gs::fragment_colour cf =
          plane ? gs::gouraud_colour(*plane, x, y, o.setup) : gs::fragment_colour::flat(gs::rgba8::from_u32(last.rgba));
      const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
      const gs::pixel_input in{cf, texel_at(x, y), m.read_pixel(fb, ux, uy), ux, uy};
      m.write_pixel(fb, ux, uy, gs::pixel_pipeline(d.regs, in, o).out);
    }
}

}  // namespace

std::vector<std::uint32_t> model_frame(const gs::model_options& o) {
  const design& des = probe_design();
  mem::local_memory m;
  upload_texture(m, des.texture);
  std::optional<mem::texture_page_buffer> tb;
  const draw* previous = nullptr;
  for (const draw& d : des.draws) {
    if (d.texflush || previous == nullptr || !same_state(*previous, d)) tb.reset();
    if (d.regs.PRIM.TME && !tb) {
      const auto [first, size] = texture_extent(d.regs.TEX0_1);
      tb.emplace(o.tex_buffer, m, first, size);
    }
    draw_primitive(m, d, tb, o);
    previous = &d;
  }
  std::vector<std::uint32_t> frame(static_cast<std::size_t>(frame_width) * frame_height);
  const mem::buffer shown{fixed::uint<14>{}, fixed::uint<6>::from_wrapped(frame_fbw), mem::psm::PSMCT32};
  for (int y = 0; y < frame_height; ++y)
    for (int x = 0; x < frame_width; ++x)
      frame[static_cast<std::size_t>(y) * frame_width + x] =
          m.read_pixel(shown, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  return frame;
}

}  // namespace gsdot3::probe
