// gs_cost/walk.cpp — the pipeline's walk of one primitive (see walk.hpp).
#include "gs_cost/walk.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "gs_arith/perspective.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/uv_plane.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_memory/psm_names.hpp"
#include "gs_memory/texture_wrap.hpp"
#include "gs_regs/drawing.hpp"

namespace gs::cost {
namespace {

namespace R = gs::regs;

// A format gs_memory lays out (an unknown PSM is walked as PSMCT32).
mem::psm known_psm(std::uint32_t p) noexcept {
  const auto q = static_cast<mem::psm>(p);
  return mem::name_of(q) == "?" ? mem::psm::PSMCT32 : q;
}

// A texel coordinate in 12.4 for a vertex: UV with FST = 1, else S/Q · 2^TW converted as the packet
// interpreter does (gs::stq_texel under the default model options, clamped to the UV planes' range).
std::array<std::int32_t, 2> texel_124(const packets::vertex& x, bool fst, std::uint32_t tw, std::uint32_t th) {
  if (fst) {
    constexpr auto u_max = static_cast<std::int32_t>(R::max_value(R::UV::U));
    constexpr auto v_max = static_cast<std::int32_t>(R::max_value(R::UV::V));
    return {x.U & u_max, x.V & v_max};
  }
  const gs::stq v{std::bit_cast<float>(x.S), std::bit_cast<float>(x.T), std::bit_cast<float>(x.Q)};
  const double q = v.Q;
  if (!std::isfinite(v.S / q) || !std::isfinite(v.T / q)) return {0, 0};
  return gs::stq_vertex_texel(v, tw, th, {});
}

struct span {
  int x0 = 0, x1 = 0;  // [x0, x1); empty when x0 >= x1
};

}  // namespace

draw_mode decode_mode(const packets::draw_registers& r) {
  draw_mode m;
  m.prim = R::decode_as(R::PRIM::PRIM, r.PRIM);
  m.textured = R::decode_as(R::PRIM::TME, r.PRIM) != 0;
  m.fst = R::decode_as(R::PRIM::FST, r.PRIM) != 0;
  const bool abe = R::decode_as(R::PRIM::ABE, r.PRIM) != 0;
  // ALPHA A 0-1, B 2-3, D 6-7: selector 1 is Cd (the destination colour).
  m.blend_reads_dst = abe && (R::decode_as(R::ALPHA::A, r.ALPHA) == 1 || R::decode_as(R::ALPHA::B, r.ALPHA) == 1 ||
                              R::decode_as(R::ALPHA::D, r.ALPHA) == 1);
  const bool zte = R::decode_as(R::TEST::ZTE, r.TEST) != 0;
  const std::uint32_t ztst = R::decode_as(R::TEST::ZTST, r.TEST);  // 0 NEVER, 1 ALWAYS, 2 GEQUAL, 3 GREATER
  m.z_read = zte && ztst >= 2;
  m.z_write = zte && ztst != 0 && R::decode_as(R::ZBUF::ZMSK, r.ZBUF) == 0;
  m.frame_psm = R::decode_as(R::FRAME::PSM, r.FRAME);
  m.z_psm = 0x30 | R::decode_as(R::ZBUF::PSM, r.ZBUF);
  m.tex_psm = R::decode_as(R::TEX0::PSM, r.TEX0);
  const std::uint32_t mmag = R::decode_as(R::TEX1::MMAG, r.TEX1), mmin = R::decode_as(R::TEX1::MMIN, r.TEX1);
  m.bilinear = m.textured && (mmag == 1 || mmin == 1 || mmin == 4 || mmin == 5);
  return m;
}

walk_counts walk_primitive(const packets::draw_registers& r, std::span<const packets::vertex> v, page_state& pages,
                           texture_unit unit) {
  const draw_mode m = decode_mode(r);
  walk_counts c;
  const bool sprite = m.prim == 6, triangle = m.prim >= 3 && m.prim <= 5;
  if ((!sprite && !triangle) || v.size() < (sprite ? 2u : 3u)) return c;
  const std::int32_t ofx = static_cast<std::int32_t>(R::decode_as(R::XYOFFSET::OFX, r.XYOFFSET));
  const std::int32_t ofy = static_cast<std::int32_t>(R::decode_as(R::XYOFFSET::OFY, r.XYOFFSET));
  const scissor clip{static_cast<int>(R::decode_as(R::SCISSOR::SCAX0, r.SCISSOR)),
                     static_cast<int>(R::decode_as(R::SCISSOR::SCAY0, r.SCISSOR)),
                     static_cast<int>(R::decode_as(R::SCISSOR::SCAX1, r.SCISSOR)) + 1,
                     static_cast<int>(R::decode_as(R::SCISSOR::SCAY1, r.SCISSOR)) + 1};
  auto window = [&](const packets::vertex& x) { return xy124{x.X - ofx, x.Y - ofy}; };

  // The covered span of every row, from the rasteriser itself.
  int y_first = clip.y1, y_last = clip.y0 - 1, base = 0;  // rows[i] is row base + i
  std::vector<span> rows;
  auto cover = [&](int x, int y) {
    span& s = rows[static_cast<std::size_t>(y - base)];
    if (s.x0 >= s.x1)
      s = {x, x + 1};
    else
      s = {std::min(s.x0, x), std::max(s.x1, x + 1)};
    y_first = std::min(y_first, y), y_last = std::max(y_last, y);
  };
  // Texel planes (12.4) for textured primitives.
  plane pu{}, pv{};
  std::optional<gs::stq_sampler> stq_at;
  const std::uint32_t tw = R::decode_as(R::TEX0::TW, r.TEX0), th = R::decode_as(R::TEX0::TH, r.TEX0);
  if (sprite) {
    const xy124 a = window(v[0]), b = window(v[1]);
    const xy124 lo{std::min(a.x, b.x), std::min(a.y, b.y)}, hi{std::max(a.x, b.x), std::max(a.y, b.y)};
    if (lo.x == hi.x || lo.y == hi.y) return c;
    const int x0 = std::max(ceil_124(lo.x), clip.x0), x1 = std::min(ceil_124(hi.x), clip.x1);
    const int y0 = std::max(ceil_124(lo.y), clip.y0), y1 = std::min(ceil_124(hi.y), clip.y1);
    if (x0 >= x1 || y0 >= y1) return c;
    base = y0;
    rows.assign(static_cast<std::size_t>(y1 - y0), span{x0, x1});
    y_first = y0, y_last = y1 - 1;
    if (m.textured) {
      const auto ta = texel_124(v[0], m.fst, tw, th), tb = texel_124(v[1], m.fst, tw, th);
      const std::array<xy124, 3> corners{a, xy124{b.x, a.y}, xy124{a.x, b.y}};
      pu = gs::make_uv_plane(corners, {ta[0], tb[0], ta[0]}, gs::uv_rule_of(gs::model_options{}));
      pv = gs::make_uv_plane(corners, {ta[1], ta[1], tb[1]}, gs::uv_rule_of(gs::model_options{}));
    }
  } else {
    const triangle_setup t = setup_triangle({window(v[0]), window(v[1]), window(v[2])});
    if (t.area2 == 0) return c;
    const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    base = std::max(ceil_124(ymin), clip.y0);
    const int end = std::min(ceil_124(ymax + 1), clip.y1);
    if (end <= base) return c;
    rows.assign(static_cast<std::size_t>(end - base), span{0, 0});
    rasterise_triangle(t, clip, cover);
    if (m.textured && !m.fst) {  // ST/Q: the interpreter's sampler (gs_arith/perspective.hpp)
      auto stq = [](const packets::vertex& x) {
        return gs::stq{std::bit_cast<float>(x.S), std::bit_cast<float>(x.T), std::bit_cast<float>(x.Q)};
      };
      stq_at = gs::make_stq_sampler({t.v, t.area2, {stq(v[0]), stq(v[1]), stq(v[2])}}, tw, th, {});
    } else if (m.textured) {
      std::array<std::int32_t, 3> us{}, vs{};
      for (std::size_t k = 0; k < 3; ++k) {
        const auto tx = texel_124(v[k], m.fst, tw, th);
        us[k] = tx[0], vs[k] = tx[1];
      }
      pu = gs::make_uv_plane(t.v, us, gs::uv_rule_of(gs::model_options{}));
      pv = gs::make_uv_plane(t.v, vs, gs::uv_rule_of(gs::model_options{}));
    }
  }
  if (y_first > y_last) return c;

  const auto fbw = fixed::uint<6>::from_wrapped(R::decode_as(R::FRAME::FBW, r.FRAME));
  const mem::buffer frame{mem::from_page(fixed::uint<9>::from_wrapped(R::decode_as(R::FRAME::FBP, r.FRAME))), fbw,
                          known_psm(m.frame_psm)};
  const mem::buffer zbuf{mem::from_page(fixed::uint<9>::from_wrapped(R::decode_as(R::ZBUF::ZBP, r.ZBUF))), fbw,
                         known_psm(m.z_psm)};
  const mem::buffer tex{fixed::uint<14>::from_wrapped(R::decode_as(R::TEX0::TBP0, r.TEX0)),
                        fixed::uint<6>::from_wrapped(R::decode_as(R::TEX0::TBW, r.TEX0)), known_psm(m.tex_psm)};
  mem::clamp_reg clamp{};
  try {
    clamp = mem::decode_clamp(r.CLAMP & R::mask(R::CLAMP::fields));
  } catch (const std::invalid_argument&) {  // a reserved mode: walked as REPEAT
  }
  const bool z = m.z_read || m.z_write;
  const int bw = static_cast<int>(m.textured ? block_width_textured : block_width_untextured);
  const std::uint32_t unit_bytes = unit == texture_unit::page ? mem::page_bytes : 2048;
  auto row = [&](int y) -> span {
    if (y < base || y >= base + static_cast<int>(rows.size())) return {};
    return rows[static_cast<std::size_t>(y - base)];
  };
  for (int band = y_first >> 1; band <= (y_last >> 1); ++band) {
    const int ya = 2 * band;
    const span s0 = row(ya), s1 = row(ya + 1);
    const bool e0 = s0.x0 >= s0.x1, e1 = s1.x0 >= s1.x1;
    if (e0 && e1) continue;
    const int xa = e0 ? s1.x0 : e1 ? s0.x0 : std::min(s0.x0, s1.x0);
    const int xb = e0 ? s1.x1 : e1 ? s0.x1 : std::max(s0.x1, s1.x1);
    c.pixels += static_cast<std::uint64_t>((e0 ? 0 : s0.x1 - s0.x0) + (e1 ? 0 : s1.x1 - s1.x0));
    for (int bx = (xa / bw) * bw; bx < xb; bx += bw) {
      ++c.blocks;
      const auto x = static_cast<std::uint32_t>(std::max(bx, xa)), y = static_cast<std::uint32_t>(e0 ? ya + 1 : ya);
      const std::uint32_t fp = mem::locate(frame, x % 2048, y % 2048).page();
      const std::optional<std::uint32_t> zp =
          z ? std::optional<std::uint32_t>(mem::locate(zbuf, x % 2048, y % 2048).page()) : std::nullopt;
      if (pages.frame != fp || (z && pages.z != zp)) {
        ++c.page_breaks;
        pages.frame = fp;
        if (z) pages.z = zp;
      }
      if (!m.textured) continue;
      for (int yy = ya; yy <= ya + 1; ++yy) {
        const span s = row(yy);
        for (int px = std::max(bx, s.x0); px < std::min(bx + bw, s.x1); ++px) {
          const std::int32_t off = m.bilinear ? 8 : 0;
          const auto uv = stq_at ? stq_at->at(px, yy, {}) : std::array{pu.at(px, yy), pv.at(px, yy)};
          const mem::texel_coord tc = mem::wrap(clamp, fixed::u4::from_wrapped(tw), fixed::u4::from_wrapped(th),
                                                static_cast<std::int32_t>((std::int64_t{uv[0]} - off) >> 4),
                                                static_cast<std::int32_t>((std::int64_t{uv[1]} - off) >> 4));
          const std::uint32_t t = mem::locate(tex, tc.u % 2048, tc.v % 2048).byte / unit_bytes;
          if (pages.texture != t) ++c.texture_misses, pages.texture = t;
        }
      }
    }
  }
  return c;
}

}  // namespace gs::cost
