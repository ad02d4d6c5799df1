// gs_cost/walk.cpp — the pipeline's walk of one primitive (see walk.hpp).
#include "gs_cost/walk.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "gs_arith/rasteriser.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_memory/psm_names.hpp"
#include "gs_memory/texture_wrap.hpp"

namespace gs::cost {
namespace {

constexpr std::uint32_t bits(std::uint64_t v, unsigned lo, unsigned n) noexcept {
  return static_cast<std::uint32_t>((v >> lo) & ((std::uint64_t{1} << n) - 1));
}

// A format gs_memory lays out (an unknown PSM is walked as PSMCT32).
mem::psm known_psm(std::uint32_t p) noexcept {
  const auto q = static_cast<mem::psm>(p);
  return mem::name_of(q) == "?" ? mem::psm::PSMCT32 : q;
}

// A texel coordinate in 12.4 for a vertex (UV with FST = 1, else S/Q · 2^TW, as draw.cpp does).
std::array<std::int32_t, 2> texel_124(const packets::vertex& x, bool fst, std::uint32_t tw, std::uint32_t th) {
  if (fst) return {x.U & 0x3FFF, x.V & 0x3FFF};
  const double q = std::bit_cast<float>(x.Q);
  auto fix = [&](std::uint32_t st, std::uint32_t size_log2) {
    const double u =
        static_cast<double>(std::bit_cast<float>(st)) / q * 16.0 * std::ldexp(1.0, static_cast<int>(size_log2));
    return std::isfinite(u) ? static_cast<std::int32_t>(std::clamp(std::floor(u), -1048576.0, 1048576.0)) : 0;
  };
  return {fix(x.S, tw), fix(x.T, th)};
}

struct span {
  int x0 = 0, x1 = 0;  // [x0, x1); empty when x0 >= x1
};

}  // namespace

draw_mode decode_mode(const packets::draw_registers& r) {
  draw_mode m;
  m.prim = bits(r.PRIM, 0, 3);
  m.textured = bits(r.PRIM, 4, 1) != 0;
  m.fst = bits(r.PRIM, 8, 1) != 0;
  const bool abe = bits(r.PRIM, 6, 1) != 0;
  // ALPHA A 0-1, B 2-3, D 6-7: selector 1 is Cd (the destination colour).
  m.blend_reads_dst = abe && (bits(r.ALPHA, 0, 2) == 1 || bits(r.ALPHA, 2, 2) == 1 || bits(r.ALPHA, 6, 2) == 1);
  const bool zte = bits(r.TEST, 16, 1) != 0;
  const std::uint32_t ztst = bits(r.TEST, 17, 2);  // 0 NEVER, 1 ALWAYS, 2 GEQUAL, 3 GREATER
  m.z_read = zte && ztst >= 2;
  m.z_write = zte && ztst != 0 && bits(r.ZBUF, 32, 1) == 0;
  m.frame_psm = bits(r.FRAME, 24, 6);
  m.z_psm = 0x30 | bits(r.ZBUF, 24, 4);
  m.tex_psm = bits(r.TEX0, 20, 6);
  const std::uint32_t mmag = bits(r.TEX1, 5, 1), mmin = bits(r.TEX1, 6, 3);
  m.bilinear = m.textured && (mmag == 1 || mmin == 1 || mmin == 4 || mmin == 5);
  return m;
}

walk_counts walk_primitive(const packets::draw_registers& r, std::span<const packets::vertex> v, page_state& pages,
                           texture_unit unit) {
  const draw_mode m = decode_mode(r);
  walk_counts c;
  const bool sprite = m.prim == 6, triangle = m.prim >= 3 && m.prim <= 5;
  if ((!sprite && !triangle) || v.size() < (sprite ? 2u : 3u)) return c;
  const std::int32_t ofx = static_cast<std::int32_t>(bits(r.XYOFFSET, 0, 16));
  const std::int32_t ofy = static_cast<std::int32_t>(bits(r.XYOFFSET, 32, 16));
  const scissor clip{static_cast<int>(bits(r.SCISSOR, 0, 11)), static_cast<int>(bits(r.SCISSOR, 32, 11)),
                     static_cast<int>(bits(r.SCISSOR, 16, 11)) + 1, static_cast<int>(bits(r.SCISSOR, 48, 11)) + 1};
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
  const std::uint32_t tw = bits(r.TEX0, 26, 4), th = bits(r.TEX0, 30, 4);
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
      pu = make_plane(corners, {ta[0], tb[0], ta[0]}, -(1 << 20), 1 << 20);
      pv = make_plane(corners, {ta[1], ta[1], tb[1]}, -(1 << 20), 1 << 20);
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
    if (m.textured) {
      std::array<std::int32_t, 3> us{}, vs{};
      for (std::size_t k = 0; k < 3; ++k) {
        const auto tx = texel_124(v[k], m.fst, tw, th);
        us[k] = tx[0], vs[k] = tx[1];
      }
      pu = make_plane(t.v, us, -(1 << 20), 1 << 20);
      pv = make_plane(t.v, vs, -(1 << 20), 1 << 20);
    }
  }
  if (y_first > y_last) return c;

  const auto fbw = fixed::uint<6>::from_wrapped(bits(r.FRAME, 16, 6));
  const mem::buffer frame{mem::from_page(fixed::uint<9>::from_wrapped(bits(r.FRAME, 0, 9))), fbw,
                          known_psm(m.frame_psm)};
  const mem::buffer zbuf{mem::from_page(fixed::uint<9>::from_wrapped(bits(r.ZBUF, 0, 9))), fbw, known_psm(m.z_psm)};
  const mem::buffer tex{fixed::uint<14>::from_wrapped(bits(r.TEX0, 0, 14)),
                        fixed::uint<6>::from_wrapped(bits(r.TEX0, 14, 6)), known_psm(m.tex_psm)};
  mem::clamp_reg clamp{};
  try {
    clamp = mem::decode_clamp(r.CLAMP & ((std::uint64_t{1} << 44) - 1));
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
          const mem::texel_coord tc = mem::wrap(clamp, fixed::u4::from_wrapped(tw), fixed::u4::from_wrapped(th),
                                                (pu.at(px, yy) - off) >> 4, (pv.at(px, yy) - off) >> 4);
          const std::uint32_t t = mem::locate(tex, tc.u % 2048, tc.v % 2048).byte / unit_bytes;
          if (pages.texture != t) ++c.texture_misses, pages.texture = t;
        }
      }
    }
  }
  return c;
}

}  // namespace gs::cost
