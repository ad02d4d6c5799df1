// gs_packets/draw.cpp — one primitive through the model (see draw.hpp).
//
// XYOFFSET, SCISSOR, TEXA, TEX1 and SCANMSK are read here by their field tables (gs_regs/drawing.hpp);
// the other registers go through gs_arith / gs_memory's strict decoders.
// Bits that belong to no field are dropped before the strict decoders see a value (the GS has nothing
// there to read; PCSX2's newest `GSState.h` masks register writes the same way, e.g. FRAME_REG_MASK
// 0xFFFFFFFF3F3F01FF, ALPHA_REG_MASK 0xFF000000FF, DIMX_REG_MASK 0x7777777777777777, ZBUF_REG_MASK
// 0x10F0001FF, which are gs_regs' `mask(REG::fields)`); reserved values in a field (ALPHA selector 3,
// PRIM 7, an unknown PSM) are still refused and named.
// The Z buffer is addressed with FRAME.FBW (the GS has no Z width; PCSX2 `GSState::Reset` builds the Z
// offset from ZBUF.Block() and FRAME.FBW).
#include "gs_packets/draw.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>

#include "gs_arith/attribute_setup.hpp"
#include "gs_arith/bilinear.hpp"
#include "gs_arith/clut.hpp"
#include "gs_arith/depth_test.hpp"
#include "gs_arith/perspective.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/registers.hpp"
#include "gs_arith/uv_plane.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/clut_load.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_memory/texture_buffer.hpp"
#include "gs_memory/texture_wrap.hpp"
#include "gs_regs/drawing.hpp"

namespace gs::packets {
namespace {

namespace R = gs::regs;

// Everything one primitive draws with, decoded.
struct decoded {
  gs_registers regs;  // what gs::pixel_pipeline reads (context registers in the _1 slots)
  mem::clamp_reg clamp;
  scissor clip;
  std::int32_t ofx = 0, ofy = 0;
  mem::buffer frame, zbuf;
  zbuf_reg ZBUF;
  std::uint8_t ta0 = 0, ta1 = 0;
  bool aem = false;
  unsigned scanmsk = 0;
  bilinear_mode filter = bilinear_mode::nearest;
  bool linear = false;
};

float as_float(std::uint32_t b) noexcept { return std::bit_cast<float>(b); }

// The TEX1 filter of the primitive, or what is not modelled. The LOD is K with LCM = 1 or FST = 1, else
// K + log2(1/|Q|)·2^L (ps2tek TEX1), evaluated at every vertex: Q over a triangle lies between its
// vertices' values, so one filter for the vertices is the filter of every pixel.
std::string texture_filter(const draw_registers& r, const decoded& d, std::span<const vertex> v, bool& linear) {
  const std::uint64_t t = r.TEX1;
  namespace T = R::TEX1;
  const bool lcm = R::decode_as(T::LCM, t) != 0;
  const unsigned mxl = R::decode_as(T::MXL, t), mmag = R::decode_as(T::MMAG, t), mmin = R::decode_as(T::MMIN, t),
                 l = R::decode_as(T::L, t);
  const int k_sign = 32 - T::K.width;
  const auto k16 = static_cast<std::int32_t>(R::decode_as(T::K, t) << k_sign) >> k_sign;  // signed 7.4
  if (mmin > 5) return "TEX1.MMIN = " + std::to_string(mmin) + " (reserved)";
  std::optional<bool> first;
  for (const vertex& x : v) {
    double lod = k16 / 16.0;
    if (!lcm && !d.regs.PRIM.FST) {
      const float q = as_float(x.Q);
      if (!(std::fabs(q) > 0.0f)) return "TEX1.LCM = 0 with Q = 0 (LOD undefined)";
      lod += std::log2(1.0 / std::fabs(static_cast<double>(q))) * static_cast<double>(1u << l);
    }
    const bool magnify = lod <= 0.0;
    const unsigned f = magnify ? mmag : mmin;
    if (!magnify && mmin >= 2 && mxl > 0)
      return "mip-mapping (TEX1.MMIN = " + std::to_string(mmin) + ", MXL = " + std::to_string(mxl) + ")";
    linear = f == 1 || f == 4 || f == 5;  // LINEAR, LINEAR_MIPMAP_NEAREST / _LINEAR at the base level
    if (first && *first != linear)
      return "TEX1.LCM = 0 with Q whose LOD changes the filter (MMAG / MMIN) within the primitive";
    first = linear;
  }
  return {};
}

// The field bits of each register the strict decoders read (the manual's layouts, registers.hpp).
constexpr std::uint64_t prim_fields = R::mask(R::PRIM::fields), frame_fields = R::mask(R::FRAME::fields),
                        test_fields = R::mask(R::TEST::fields), alpha_fields = R::mask(R::ALPHA::fields),
                        fba_fields = R::mask(R::FBA::fields), colclamp_fields = R::mask(R::COLCLAMP::fields),
                        pabe_fields = R::mask(R::PABE::fields), dthe_fields = R::mask(R::DTHE::fields),
                        dimx_fields = R::mask(R::DIMX::fields), clamp_fields = R::mask(R::CLAMP::fields),
                        zbuf_fields = R::mask(R::ZBUF::fields);

std::string decode(const draw_registers& r, std::span<const vertex> v, decoded& d) {
  const std::string ctx = "context " + std::to_string(r.context) + " ";
  try {
    d.regs.PRIM = decode_prim(r.PRIM & prim_fields);
  } catch (const register_error& e) { return e.what(); }
  const prim_reg& p = d.regs.PRIM;
  const auto type = static_cast<unsigned>(p.PRIM);
  if (p.PRIM != prim_type::TRIANGLE && p.PRIM != prim_type::TRIANGLE_STRIP && p.PRIM != prim_type::TRIANGLE_FAN &&
      p.PRIM != prim_type::SPRITE)
    return std::string("PRIM.PRIM = ") + prim_names[type & 7] + " (points and lines are not modelled)";
  if (p.FGE) return "PRIM.FGE = 1 (fog)";
  if (p.AA1) return "PRIM.AA1 = 1 (anti-aliasing)";
  try {
    d.regs.FRAME_1 = decode_frame(r.FRAME & frame_fields);
    d.regs.TEST_1 = decode_test(r.TEST & test_fields);
    d.regs.ALPHA_1 = decode_alpha(r.ALPHA & alpha_fields);
    d.regs.FBA_1 = decode_fba(r.FBA & fba_fields);
    d.regs.COLCLAMP = decode_colclamp(r.COLCLAMP & colclamp_fields);
    d.regs.PABE = decode_pabe(r.PABE & pabe_fields);
    d.regs.DTHE = decode_dthe(r.DTHE & dthe_fields);
    d.regs.DIMX = decode_dimx(r.DIMX & dimx_fields);
    d.ZBUF = decode_zbuf(r.ZBUF & zbuf_fields);
    if (p.TME) {
      d.regs.TEX0_1 = decode_tex0(r.TEX0);
      d.clamp = mem::decode_clamp(r.CLAMP & clamp_fields);
    }
  } catch (const register_error& e) {
    return ctx + "registers: " + e.what();  // the decoders name the field as context 1's (ALPHA_1.A ...)
  }
  d.frame = {mem::from_page(d.regs.FRAME_1.FBP), d.regs.FRAME_1.FBW,
             static_cast<mem::psm>(static_cast<std::uint8_t>(d.regs.FRAME_1.PSM))};
  d.zbuf = {mem::from_page(d.ZBUF.ZBP), d.regs.FRAME_1.FBW,
            static_cast<mem::psm>(0x30 | static_cast<unsigned>(d.ZBUF.PSM))};
  d.ofx = static_cast<std::int32_t>(R::decode_as(R::XYOFFSET::OFX, r.XYOFFSET));
  d.ofy = static_cast<std::int32_t>(R::decode_as(R::XYOFFSET::OFY, r.XYOFFSET));
  namespace S = R::SCISSOR;
  d.clip = {static_cast<int>(R::decode_as(S::SCAX0, r.SCISSOR)), static_cast<int>(R::decode_as(S::SCAY0, r.SCISSOR)),
            static_cast<int>(R::decode_as(S::SCAX1, r.SCISSOR)) + 1,
            static_cast<int>(R::decode_as(S::SCAY1, r.SCISSOR)) + 1};
  d.ta0 = static_cast<std::uint8_t>(R::decode_as(R::TEXA::TA0, r.TEXA));
  d.aem = R::decode_as(R::TEXA::AEM, r.TEXA) != 0;
  d.ta1 = static_cast<std::uint8_t>(R::decode_as(R::TEXA::TA1, r.TEXA));
  d.scanmsk = R::decode_as(R::SCANMSK::MSK, r.SCANMSK);
  if (d.scanmsk == R::SCANMSK::MSK_reserved) return "SCANMSK.MSK = 1 (reserved)";
  if (!p.TME) return {};
  if (!p.FST)
    for (const vertex& x : v) {
      // A sprite's Q: PCSX2 takes the second vertex's (GSRendererSW ConvertVertexBuffer), unconfirmed.
      if (p.PRIM == prim_type::SPRITE && x.Q != v[0].Q) return "PRIM.FST = 0 on a SPRITE with differing Q";
      // S/Q and T/Q must be numbers: the GS's own float unit has no NaN or infinity (a NaN, an
      // infinite S, T or Q, or Q = 0 would need that unit's rules, which the model lacks).
      const double q = as_float(x.Q), s = as_float(x.S), t = as_float(x.T);
      if (!std::isfinite(s / q) || !std::isfinite(t / q))
        return "PRIM.FST = 0 with S/Q or T/Q not a finite number (Q = 0, or a NaN / infinite S, T or Q)";
      // Q of both signs: zero somewhere inside, and the sources disagree on negative Q (stq-evidence.md).
      if (std::signbit(q) != std::signbit(static_cast<double>(as_float(v[0].Q))))
        return "PRIM.FST = 0 with Q of both signs";
    }
  if (const auto e = texture_filter(r, d, v, d.linear); !e.empty()) return ctx + e;
  return {};
}

// A 16-bit colour (texel or CLUT entry) widened with TEXA (GS User's Manual TEXA: TA0 for the A bit 0,
// TA1 for 1; AEM = 1 makes A = 0 where R = G = B = 0); RGB widened as c << 3.
rgba8 expand16(const decoded& d, std::uint32_t t) {
  const std::uint32_t r = (t & 31u) << 3, g = ((t >> 5) & 31u) << 3, b = ((t >> 10) & 31u) << 3;
  const std::uint8_t a = (t & 0x8000u) != 0 ? d.ta1 : (d.aem && (t & 0x7FFFu) == 0 ? std::uint8_t{0} : d.ta0);
  return rgba8::from_u32(r | (g << 8) | (b << 16) | (std::uint32_t{a} << 24));
}

// A texel's colour from its raw value (gs_memory's right-aligned value bits). PSMCT24 takes A = TA0
// (0 for black under AEM); 16-bit texels expand16; indexed texels look up the CLUT buffer: a 32-bit
// entry (CPSM = PSMCT32), or a 16-bit half (PSMCT16/16S: half i for PSMT8, 16·CSA + i for PSMT4,
// gs_memory/clut_load.hpp's storage) widened by expand16.
rgba8 texel_colour(const decoded& d, const clut_buffer& clut, std::uint32_t t) {
  const tex0_reg& x = d.regs.TEX0_1;
  const bool clut16 = x.CPSM != clut_psm::PSMCT32;
  switch (mem::value_bits(x.PSM)) {
    case 32: return rgba8::from_u32(t);
    case 24: {
      const bool black = (t & 0xFFFFFFu) == 0;
      return rgba8::from_u32((t & 0xFFFFFFu) | (std::uint32_t{d.aem && black ? std::uint8_t{0} : d.ta0} << 24));
    }
    case 16: return expand16(d, t);
    case 8: return clut16 ? expand16(d, mem::clut_half(clut, t)) : clut_t8(clut, u8::from_wrapped(t));
    default:
      return clut16 ? expand16(d, mem::clut_half(clut, 16u * static_cast<std::uint32_t>(x.CSA.value()) + t))
                    : clut_t4(clut, fixed::u4::from_wrapped(t), x.CSA);
  }
}

// The vertex's S, T, Q as floats.
gs::stq stq_of(const vertex& x) { return {as_float(x.S), as_float(x.T), as_float(x.Q)}; }

// 12.4 texel coordinates of a sprite's vertex: UV with FST = 1, else S/Q·2^TW and T/Q·2^TH converted
// as a triangle's are (gs::stq_sampler with one Q).
std::array<std::int32_t, 2> texel_position(const decoded& d, const vertex& x, const model_options& o) {
  if (!d.regs.PRIM.TME) return {0, 0};  // no texture: the coordinates are not used (nor checked)
  if (d.regs.PRIM.FST) {
    constexpr auto u_max = static_cast<std::int32_t>(R::max_value(R::UV::U));
    constexpr auto v_max = static_cast<std::int32_t>(R::max_value(R::UV::V));
    return {x.U & u_max, x.V & v_max};
  }
  return gs::stq_vertex_texel(stq_of(x), static_cast<unsigned>(d.regs.TEX0_1.TW.value()),
                              static_cast<unsigned>(d.regs.TEX0_1.TH.value()), o);
}

}  // namespace

std::string check_primitive(const draw_registers& r, const clut_unit& clut, std::span<const vertex> v) {
  decoded d;
  if (auto e = decode(r, v, d); !e.empty()) return e;
  if (d.regs.PRIM.TME && mem::value_bits(d.regs.TEX0_1.PSM) <= 8 && !clut.load_error.empty())
    return "context " + std::to_string(r.context) + " CLUT: " + clut.load_error;
  return {};
}

std::uint64_t draw_primitive(mem::local_memory& m, const draw_registers& r, const clut_unit& clut,
                             std::span<const vertex> v, const model_options& o,
                             std::optional<mem::texture_page_buffer>& texture) {
  decoded d;
  if (!check_primitive(r, clut, v).empty()) return 0;
  decode(r, v, d);
  const prim_reg& p = d.regs.PRIM;
  const tex0_reg& tex = d.regs.TEX0_1;
  const mem::buffer tb{tex.TBP0, tex.TBW, tex.PSM};
  if (!texture)
    texture.emplace(o.tex_buffer, m, 0, o.tex_buffer == texture_buffer::draw_snapshot ? mem::memory_bytes : 0);
  mem::texture_page_buffer& cache = *texture;
  auto fetch = [&](std::int32_t u, std::int32_t w) {
    const mem::texel_coord c = mem::wrap(d.clamp, tex.TW, tex.TH, u, w);
    const mem::location at = mem::locate(tb, c.u, c.v);
    std::uint64_t raw = 0;
    for (unsigned i = 0; i < (at.bit + at.bits + 7) / 8; ++i)
      raw |= std::uint64_t{cache.fetch((at.byte + i) % mem::memory_bytes)} << (8 * i);
    return texel_colour(d, clut.state.buffer,
                        static_cast<std::uint32_t>((raw >> at.bit) & ((std::uint64_t{1} << at.bits) - 1)));
  };
  const bilinear_mode filter = d.linear ? o.bilinear : bilinear_mode::nearest;
  const bool ZTE = d.regs.TEST_1.ZTE;
  const unsigned fbits = mem::value_bits(d.frame.PSM);
  std::uint64_t pixels = 0;
  auto shade = [&](int x, int y, const fragment_colour& cf, std::int32_t u16, std::int32_t v16, std::uint32_t z) {
    if ((d.scanmsk == 2 && y % 2 == 0) || (d.scanmsk == 3 && y % 2 == 1)) return;
    const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
    const std::uint32_t dst = m.read_pixel(d.frame, ux, uy);
    if (d.regs.TEST_1.DATE && fbits != 24 && (((dst >> (fbits - 1)) & 1u) != 0) != d.regs.TEST_1.DATM) return;
    const depth_result zt = depth_test(d.regs.TEST_1, d.ZBUF, z, ZTE ? m.read_pixel(d.zbuf, ux, uy) : 0);
    if (!zt.pass) return;
    const rgba8 texel = p.TME ? sample(fetch, u16, v16, filter) : rgba8{};
    const pixel_trace t = pixel_pipeline(d.regs, {cf, texel, dst, ux, uy}, o);
    m.write_pixel(d.frame, ux, uy, t.out);
    if (zt.write_z && t.test.z) m.write_pixel(d.zbuf, ux, uy, zt.z);  // ZMSK, and the alpha test's Z enable
    ++pixels;
  };
  auto window = [&](const vertex& x) { return xy124{x.X - d.ofx, x.Y - d.ofy}; };
  if (p.PRIM == prim_type::SPRITE) {
    const xy124 a = window(v[0]), b = window(v[1]);
    const auto ta = texel_position(d, v[0], o), tb2 = texel_position(d, v[1], o);
    const fragment_colour cf = fragment_colour::flat(v[1].colour);  // a sprite takes its second vertex's colour
    const xy124 lo{std::min(a.x, b.x), std::min(a.y, b.y)}, hi{std::max(a.x, b.x), std::max(a.y, b.y)};
    if (lo.x == hi.x || lo.y == hi.y) return 0;
    // U varies along x only and V along y only: the planes through the corners (a, U0), (b.x, U1), (b.y, V1).
    const std::array<xy124, 3> corners{a, xy124{b.x, a.y}, xy124{a.x, b.y}};
    const plane pu = make_uv_plane(corners, {ta[0], tb2[0], ta[0]}, uv_rule_of(o));
    const plane pv = make_uv_plane(corners, {ta[1], ta[1], tb2[1]}, uv_rule_of(o));
    rasterise_sprite(lo, hi, d.clip, [&](int x, int y) { shade(x, y, cf, pu.at(x, y), pv.at(x, y), v[1].Z); });
    return pixels;
  }
  const triangle_setup t = setup_triangle({window(v[0]), window(v[1]), window(v[2])});
  if (t.area2 == 0) return 0;
  const bool stq = p.TME && !p.FST;
  std::array<std::array<std::int32_t, 2>, 3> uv{};
  if (p.TME && p.FST)
    for (std::size_t k = 0; k < 3; ++k) uv[k] = texel_position(d, v[k], o);
  const gs::stq_sampler st =
      stq ? gs::make_stq_sampler({t.v, t.area2, {stq_of(v[0]), stq_of(v[1]), stq_of(v[2])}},
                                 static_cast<unsigned>(tex.TW.value()), static_cast<unsigned>(tex.TH.value()), o)
          : gs::stq_sampler{};
  const triangle_attributes a = setup_attributes(t, {v[0].colour, v[1].colour, v[2].colour}, uv, d.ofx >> 4, d.ofy >> 4,
                                                 o.setup, uv_rule_of(o), d.clip.x0);
  // Z as a plane (MODEL-PLANE-16, rasteriser.hpp); Z above 24 bits through Z / 256 (the plane's
  // 32-bit range), low 8 bits 0: a model limit, stated.
  const bool wide = std::max({v[0].Z, v[1].Z, v[2].Z}) > 0xFFFFFFu;
  const unsigned zs = wide ? 8 : 0;
  const plane pz = make_plane(t.v,
                              {static_cast<std::int32_t>(v[0].Z >> zs), static_cast<std::int32_t>(v[1].Z >> zs),
                               static_cast<std::int32_t>(v[2].Z >> zs)},
                              0, 0xFFFFFF);
  const fragment_colour flat = flat_shading(v[2].colour);  // IIP = 0: the last vertex's colour
  rasterise_triangle(t, d.clip, [&](int x, int y) {
    const auto uv16 = stq ? st.at(x, y, o) : std::array{a.u.at(x, y), a.v.at(x, y)};
    shade(x, y, p.IIP ? a.colour_at(x, y) : flat, uv16[0], uv16[1], static_cast<std::uint32_t>(pz.at(x, y)) << zs);
  });
  return pixels;
}

}  // namespace gs::packets
