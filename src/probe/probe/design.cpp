// probe/design.cpp — the probe's draws and patches (the table in docs/dumps.md, "The option probe").
#include "probe/design.hpp"

#include <array>
#include <stdexcept>
#include <utility>

#include "gs_memory/address.hpp"

namespace gsdot3::probe {
namespace {

using fixed::u8;

// The displayed frame (FBP 0, FBW 10, PSMCT32), Z test ALWAYS (ZBUF_1 has ZMSK = 1: no Z writes).
gs::gs_registers frame_regs() {
  gs::gs_registers r;
  r.PRIM.PRIM = gs::prim_type::SPRITE;
  r.PRIM.FST = true;
  r.FRAME_1.FBW = fixed::uint<6>::from_wrapped(frame_fbw);
  r.TEST_1.ZTE = true;
  r.TEST_1.ZTST = gs::ztst::ALWAYS;
  return r;
}

// A PSMCT16 buffer of one page (FBW 1) laid over frame page `page`.
gs::gs_registers sixteen_bit_regs(unsigned page) {
  gs::gs_registers r = frame_regs();
  r.FRAME_1.FBP = fixed::uint<9>::from_wrapped(page);
  r.FRAME_1.FBW = fixed::uint<6>::from_wrapped(1);
  r.FRAME_1.PSM = gs::frame_psm::PSMCT16;
  return r;
}

gs::tex0_reg small_texture(gs::tfx fn) {
  gs::tex0_reg t;
  t.TBP0 = fixed::uint<14>::from_wrapped(texture_page * 32);
  t.TBW = fixed::uint<6>::from_wrapped(1);
  t.TW = fixed::u4::from_wrapped(4);
  t.TH = fixed::u4::from_wrapped(4);
  t.TFX = fn;
  return t;
}

// A Gouraud TRIANGLE, MODULATE with the white texel (UV (8, 8) at every vertex), scissored to the cell at (x, y).
draw gouraud_ramp(const gs::gs_registers& regs, int x, int y, const std::array<vertex, 3>& v) {
  draw t;
  t.regs = regs;
  t.regs.PRIM.PRIM = gs::prim_type::TRIANGLE;
  t.regs.PRIM.IIP = t.regs.PRIM.TME = true;
  t.regs.TEX0_1 = small_texture(gs::tfx::MODULATE);
  t.scissor = {x, y, x + cell - 1, y + cell - 1};
  t.v.assign(v.begin(), v.end());
  return t;
}

draw sprite(const gs::gs_registers& regs, int x, int y, int w, int h, std::uint32_t rgba, int u16 = 0, int v16 = 0) {
  draw d;
  d.regs = regs;
  d.v = {{x, y, rgba, u16, v16}, {x + w, y + h, rgba, u16, v16}};
  return d;
}

gs::alpha_reg blend(gs::blend_colour a, gs::blend_colour b, gs::blend_alpha c, gs::blend_colour d, unsigned fix = 0) {
  return {a, b, c, d, u8::from_wrapped(fix)};
}

gs::dimx_reg uniform_dimx(unsigned entry) {
  gs::dimx_reg m;
  for (auto& row : m.DM)
    for (auto& e : row) e = gs::u3::from_wrapped(entry);
  return m;
}

// The bilinear 2×2 block at texels (4, 4) .. (5, 5); per channel t00, t10, t01, t11 (evidence.md P6
// for R; G and B add sets whose double truncation differs from the one-step sum at other weights).
constexpr int bilinear_texel = 4;
constexpr std::uint8_t bilinear_sets[3][4] = {
    {0x00, 0xFF, 0x01, 0xFE}, {0x00, 0x07, 0x09, 0x0F}, {0x10, 0x31, 0x52, 0x73}};

std::vector<std::uint32_t> texture_texels() {
  std::vector<std::uint32_t> t(texture_side * texture_side, 0x80000000u);
  t[0] = 0xFFFFFFFFu;  // (0, 0): white, the Gouraud ramp's texel
  t[1] = 0x80808080u;  // (1, 0): 1.0, the gouraud_setup ramps' texel: Cf's whole levels, its fraction dropped
  for (int k = 0; k < 4; ++k) {
    const int u = bilinear_texel + (k & 1), v = bilinear_texel + (k >> 1);
    t[static_cast<std::size_t>(v * texture_side + u)] = 0x80000000u | std::uint32_t{bilinear_sets[0][k]} |
                                                        std::uint32_t{bilinear_sets[1][k]} << 8 |
                                                        std::uint32_t{bilinear_sets[2][k]} << 16;
  }
  return t;
}

// Pixel (x, y) of the displayed frame as the PSMCT16 coordinates, in the one-page 16-bit buffer over
// the frame page holding (x, y), of the 16×8 block that shares the bytes of (x, y)'s 8×8 block.
struct sixteen_bit_cell {
  unsigned page;
  int x16, y16;
};
sixteen_bit_cell sixteen_bit_block(int x, int y) {
  namespace mem = gs::mem;
  const unsigned page = static_cast<unsigned>(y / 32) * frame_fbw + static_cast<unsigned>(x / 64);
  const mem::buffer frame{fixed::uint<14>::from_wrapped(0), fixed::uint<6>::from_wrapped(frame_fbw), mem::psm::PSMCT32};
  const mem::buffer b16{mem::from_page(fixed::uint<9>::from_wrapped(page)), fixed::uint<6>::from_wrapped(1),
                        mem::psm::PSMCT16};
  const std::uint32_t block = mem::locate(frame, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)).block();
  for (int by = 0; by < 64; by += 8)
    for (int bx = 0; bx < 64; bx += 16)
      if (mem::locate(b16, static_cast<std::uint32_t>(bx), static_cast<std::uint32_t>(by)).block() == block)
        return {page, bx, by};
  throw std::logic_error("probe: no PSMCT16 block shares the bytes of the cell");  // a page has 32 of each
}

class builder {
 public:
  design d;

  void add(draw dr) { d.draws.push_back(std::move(dr)); }
  void add_patch(std::string name, std::string option, int x, int y, std::string what, std::string check = {}) {
    d.patches.push_back({std::move(name), std::move(option), std::move(check), x, y, std::move(what)});
  }

  // A cell of the displayed frame drawn through a 16-bit buffer: `regs` gets the buffer's FRAME_1.
  draw sixteen_bit_sprite(gs::gs_registers regs, int x, int y, std::uint32_t rgba) {
    const sixteen_bit_cell c = sixteen_bit_block(x, y);
    const gs::gs_registers fb = sixteen_bit_regs(c.page);
    regs.FRAME_1.FBP = fb.FRAME_1.FBP;
    regs.FRAME_1.FBW = fb.FRAME_1.FBW;
    regs.FRAME_1.PSM = fb.FRAME_1.PSM;
    return sprite(regs, c.x16, c.y16, 16, 8, rgba);
  }
};

design make_design() {
  using gs::blend_alpha;
  using gs::blend_colour;
  builder b;
  b.d.texture = texture_texels();
  const gs::gs_registers base = frame_regs();

  // ---- row y = 16: the 32-bit frame ----------------------------------------------------------------
  {  // gouraud_fraction (evidence.md P2): the 8.7 ramp 1 + 16/128 .. 1 + 44/128 times texel 0xFF.
    const int x = 16, y = 16;
    // Colour 1 at x − 4, 2 at x + 28: the step is exactly 128 / 32 = 4 (8.7) per pixel, no rounding.
    b.add(gouraud_ramp(
        base, x, y,
        {{{x - 4, y - 4, 0x80010101u, 8, 8}, {x + 28, y - 4, 0x80020202u, 8, 8}, {x - 4, y + 28, 0x80010101u, 8, 8}}}));
    b.add_patch("gouraud_fraction.ramp", "gouraud_fraction", x, y,
                "Gouraud TRIANGLE, MODULATE, texel 0xFF, Cf = 1 + (16 + 4k)/128 (8.7), scissored to the cell: "
                "(0xFF * Cf_8.7) >> 14 = 2 keeping the fraction, 1 truncating it");
  }
  {  // gouraud_setup (evidence.md P12): a ramp whose exact step is just below one 8.7 unit per pixel,
     // read ~500 pixels from the first vertex (the top-left one: the reference pixel of plane_steps).
    const int x = 520, y = 16;
    // Colour 0 at x − 500, 4 at x + 14 (two vertices, one above the other: the cell lies inside): the
    // step is 4·128/514 = 0.996 units per pixel, 0 along y.
    b.add(gouraud_ramp(base, x, y,
                       {{{x - 500, y - 4, 0x80000000u, 24, 8},
                         {x + 14, y - 4, 0x80040404u, 24, 8},
                         {x + 14, y + 28, 0x80040404u, 24, 8}}}));
    b.add_patch(
        "gouraud_setup.ramp", "gouraud_setup", x, y,
        "Gouraud TRIANGLE, MODULATE, texel 0x80, Cf from 0 to 4 over 514 pixels (0.996 units per pixel), read 501..506 "
        "pixels from the first vertex: 0 when the step truncates to whole units (plane_steps), Cf_8.7 = 499..504 and "
        "(0x80 * Cf) >> 14 = 3 from the exact plane (per_pixel and the other set-ups of a source)");
  }
  {  // gouraud_setup (P12): a long row, its start at x = 0, read ~600 pixels on (PCSX2's vectors).
    const int x = 600, y = 432;
    // Colour 0 along x = 0, 8 at x = 686: 1024/686 = 1.4927 units per pixel along x, 0 along y. Scissored to
    // the band x = 0 .. cell end, rows of the cell (no other patch there), so PCSX2's row starts at 0.
    draw d = gouraud_ramp(
        base, x, y,
        {{{0, y - 400, 0x80000000u, 24, 8}, {0, y + 408, 0x80000000u, 24, 8}, {686, y + 4, 0x80080808u, 24, 8}}});
    d.scissor = {0, y, x + cell - 1, y + cell - 1};
    b.add(d);
    b.add_patch(
        "gouraud_setup.rows", "gouraud_setup", x, y,
        "Gouraud TRIANGLE, MODULATE, texel 0x80, Cf = 1.4927 units per pixel from x = 0, read 601..606 pixels on: "
        "level 7 from the exact plane (897..904 units); 5 from 4-lane vector steps trunc(5.97) = 5 (~146 units "
        "behind), 6 from 8-lane steps trunc(11.94) = 11 (~71 behind), 4 from plane_steps' step 1");
  }
  {  // gouraud_setup (P12): the exact plane within half an 8.7 unit below a whole level (parallel-gs's bias).
    const int x = 616, y = 432;
    // Colour 0 along x = 108, 2 at x = 1132: 0.25·(x − 108) units, so 127.5 and 127.75 at x = 618, 619.
    b.add(gouraud_ramp(
        base, x, y,
        {{{108, y - 4, 0x80000000u, 24, 8}, {108, y + 1500, 0x80000000u, 24, 8}, {1132, y - 4, 0x80020202u, 24, 8}}}));
    b.add_patch("gouraud_setup.level", "gouraud_setup", x, y,
                "Gouraud TRIANGLE, MODULATE, texel 0x80, Cf = 0.25·(x − 108) units: 127.5 and 127.75 at x = 618, 619, "
                "level 0 truncated, 1 with parallel-gs's +1/256 level (per_pixel_level); 128 and more from x = 620 on");
  }
  {  // gouraud_setup (P12): a colour falling away from vertex 0, the exact plane within one 8.7 unit below a
     // whole level (issue 53: DobieStation truncates the value, per_pixel the distance from vertex 0).
    const int x = 624, y = 432;
    // Colour 1 along x = 623 (vertex 0 first), 0 at x = 2671: 128 − (x − 623)/16 units, so 127.53 .. 127.91
    // over the sampled pixels 625..630 ±1/2: every set-up gives one value over the cell.
    b.add(gouraud_ramp(
        base, x, y,
        {{{623, y - 4, 0x80010101u, 24, 8}, {2671, y - 4, 0x80000000u, 24, 8}, {623, y + 28, 0x80010101u, 24, 8}}}));
    b.add_patch("gouraud_setup.falling", "gouraud_setup", x, y,
                "Gouraud TRIANGLE, MODULATE, texel 0x80, Cf from 1 at x = 623 (vertex 0) falling 1/16 unit per pixel: "
                "127.56..127.88 units, level 0 floored (per_pixel_floor) or stepped from the row start (pcsx2_rows), 1 "
                "with the distance from vertex 0 truncated (per_pixel, plane_steps' start) or the +1/256 level "
                "(per_pixel_level)");
  }
  {  // uv_convert (P14): U rising 15/128 of a sixteenth per pixel from 14 at x = 116 (vertex 0), V 8 (row 0):
     // the exact U at x = 133 is 14 + 17·15/128 = 15 127/128, 1/128 below texel 1; at x = 129..132 and 134
     // at least 15/128 from 16 and from 16 − 1/64 (and fixed_16's plane lands on the same texels there).
    const int x = 128, y = 16;
    draw t;
    t.regs = base;
    t.regs.PRIM.PRIM = gs::prim_type::TRIANGLE;
    t.regs.PRIM.TME = true;
    t.regs.TEX0_1 = small_texture(gs::tfx::DECAL);
    t.scissor = {x, y, x + cell - 1, y + cell - 1};
    t.v = {{116, 0, 0x80808080u, 14, 8}, {244, 0, 0x80808080u, 29, 8}, {116, 64, 0x80808080u, 14, 8}};
    b.add(t);
    b.add_patch("uv_convert.below_texel", "uv_convert", x, y,
                "UV TRIANGLE (FST = 1), DECAL, nearest, U = 14 + 15·(x − 116)/128 sixteenths along row 0: at x = 133 "
                "U = 15 127/128, texel 0 (white) floored, texel 1 (0x80) with parallel-gs's +1/64 (floor_1_64); the "
                "columns left of it white, right of it 0x80 under both");
  }
  {  // blend_shift (P3, settled by the recordings; probed anyway): (0 − 0x81)·1 >> 7 + 0x81.
    const int x = 32, y = 16;
    b.add(sprite(base, x, y, cell, cell, 0x80818181u));
    gs::gs_registers r = base;
    r.PRIM.ABE = true;
    r.ALPHA_1 = blend(blend_colour::Cs, blend_colour::Cd, blend_alpha::As, blend_colour::Cd);
    b.add(sprite(r, x, y, cell, cell, 0x01000000u));
    b.add_patch("blend_shift.negative", "blend_shift", x, y,
                "Cd 0x81, then (Cs - Cd) * As >> 7 + Cd with Cs 0, As 1: -129 >> 7 = -2 (floor) or -1 (truncate)");
  }
  {  // dither_targets (P5): DIMX entry 3 (+3 under every decode) on PSMCT32.
    const int x = 48, y = 16;
    gs::gs_registers r = base;
    r.DTHE.DTHE = true;
    r.DIMX = uniform_dimx(3);
    b.add(sprite(r, x, y, cell, cell, 0x80808080u));
    b.add_patch("dither_targets.ct32", "dither_targets", x, y,
                "PSMCT32, DTHE = 1, every DIMX entry 3, colour 0x80: 0x80 undithered, 0x83 dithered");
  }
  for (int k = 0; k < 2; ++k) {  // bilinear (P6): one constant UV per sprite, weights (1, 2) and (9, 10).
    const int x = 64 + 16 * k, y = 16, wu = k == 0 ? 1 : 9, wv = k == 0 ? 2 : 10;
    gs::gs_registers r = base;
    r.PRIM.TME = true;
    r.TEX0_1 = small_texture(gs::tfx::DECAL);
    const int at = bilinear_texel * 16 + 8;  // texel (4, 4)'s centre: the footprint starts there
    draw s = sprite(r, x, y, cell, cell, 0x80808080u, at + wu, at + wv);
    s.linear = true;
    b.add(s);
    b.add_patch("bilinear.w" + std::to_string(wu) + "_" + std::to_string(wv), "bilinear", x, y,
                "DECAL, TEX1 LINEAR, every pixel at UV = texel (4, 4) + (" + std::to_string(wu) + ", " +
                    std::to_string(wv) + ")/16 of the 2x2 block R 00 ff 01 fe, G 00 07 09 0f, B 10 31 52 73");
  }
  {  // COLCLAMP = 0 wraps (evidence.md A1): 0xC0 + 0x80 = 0x140 -> 0x40.
    const int x = 96, y = 16;
    b.add(sprite(base, x, y, cell, cell, 0x80808080u));
    gs::gs_registers r = base;
    r.PRIM.ABE = true;
    r.COLCLAMP.CLAMP = false;
    r.ALPHA_1 = blend(blend_colour::Cs, blend_colour::zero, blend_alpha::FIX, blend_colour::Cd, 0x80);
    b.add(sprite(r, x, y, cell, cell, 0x80C0C0C0u));
    b.add_patch("check.colclamp_wrap", "", x, y,
                "Cd 0x80, COLCLAMP = 0, Cs * FIX(0x80) >> 7 + Cd with Cs 0xC0: 0x40 (wrap)", "colclamp_wrap");
  }
  {  // HIGHLIGHT clamps after the function (evidence.md D1): min(255, 0xFF·0x7F >> 7 + 0x7F) through a wrapping blend.
    const int x = 112, y = 16;
    gs::gs_registers r = base;
    r.PRIM.TME = r.PRIM.ABE = true;
    r.TEX0_1 = small_texture(gs::tfx::HIGHLIGHT);
    r.COLCLAMP.CLAMP = false;
    r.ALPHA_1 = blend(blend_colour::Cs, blend_colour::zero, blend_alpha::FIX, blend_colour::zero, 0x80);
    b.add(sprite(r, x, y, cell, cell, 0x7F7F7F7Fu, 8, 8));
    b.add_patch(
        "check.highlight_clamp", "", x, y,
        "HIGHLIGHT, texel 0xFF, Cf 0x7F: 0xFF (clamped after the function) through Cs * 0x80 >> 7 with COLCLAMP = 0",
        "highlight_clamp");
  }

  // ---- row y = 32: 16-bit cells ----------------------------------------------------------------------
  for (unsigned e = 4; e < 8; ++e) {  // dither_decode (P4): every DIMX entry e on PSMCT16.
    const int x = 16 + 16 * static_cast<int>(e - 4), y = 32;
    gs::gs_registers r = base;
    r.DTHE.DTHE = true;
    r.DIMX = uniform_dimx(e);
    b.add(b.sixteen_bit_sprite(r, x, y, 0x80838280u));
    b.add_patch("dither_decode.e" + std::to_string(e), "dither_decode", x, y,
                "PSMCT16, DTHE = 1, every DIMX entry " + std::to_string(e) +
                    ", colour R 0x80 G 0x82 B 0x83: (c + d) >> 3 is 15 or 16 per channel, showing d");
  }
  {  // rgb_only_targets (P7): AFAIL = RGB_ONLY over a 16-bit pixel with its A bit set.
    const int x = 80, y = 32;
    b.add(b.sixteen_bit_sprite(base, x, y, 0x80404040u));
    gs::gs_registers r = base;
    r.TEST_1.ATE = true;
    r.TEST_1.ATST = gs::atst::NEVER;
    r.TEST_1.AFAIL = gs::afail::RGB_ONLY;
    b.add(b.sixteen_bit_sprite(r, x, y, 0x00C0C0C0u));
    b.add_patch("rgb_only_targets.ct16", "rgb_only_targets", x, y,
                "PSMCT16 pixel 0xA108 (A set), ATST = NEVER, AFAIL = RGB_ONLY, colour 0x00C0C0C0: A bit cleared "
                "(RGB_ONLY acts as FB_ONLY) or kept");
  }
  for (int k = 0; k < 2; ++k) {  // the 16-bit FBMSK rule (evidence.md A2, P10).
    const int x = 96 + 16 * k, y = 32;
    b.add(b.sixteen_bit_sprite(base, x, y, 0x00000000u));
    gs::gs_registers r = base;
    r.FRAME_1.FBMSK = k == 0 ? 0x00000007u : 0x80000000u;
    b.add(b.sixteen_bit_sprite(r, x, y, 0xFFFFFFFFu));
    b.add_patch(k == 0 ? "check.fbmsk16_low_bits" : "check.fbmsk16_alpha", "", x, y,
                k == 0
                    ? "PSMCT16 over 0x0000, FBMSK 0x00000007, colour 0xFFFFFFFF: 0xFFFF (bits 0..2 have no 16-bit bit)"
                    : "PSMCT16 over 0x0000, FBMSK 0x80000000, colour 0xFFFFFFFF: 0x7FFF (bit 31 keeps the A bit)",
                "fbmsk16");
  }

  // ---- rows y = 64..95: section 3.4's read/write overlap (P11), the frame read as its own texture -----
  // Page P0 = frame page 20 (x 0..63, y 64..95), quarters q0 (x 0..31, y 64..79), q1 (x 0..31, y 80..95),
  // q2 (x 32..63, y 64..79), q3 (x 32..63, y 80..95); page P1 = frame page 21 (x 64..127).
  {
    struct at {
      int x, y;
    };
    const at a{8, 72}, bb{8, 88}, d{40, 64}, e{40, 72}, c{40, 88}, f{48, 88}, h{56, 88}, g{72, 72}, g2{88, 72};
    b.add(sprite(base, a.x, a.y, cell, cell, 0x80C04010u));    // A1 (q0)
    b.add(sprite(base, bb.x, bb.y, cell, cell, 0x80202020u));  // B0 (q1), overwritten by S1
    b.add(sprite(base, d.x, d.y, cell, cell, 0x8040C010u));    // D1 (q2)
    b.add(sprite(base, e.x, e.y, cell, cell, 0x80303030u));    // E0 (q2), overwritten by S3
    b.add(sprite(base, g.x, g.y, cell, cell, 0x80808080u));    // page P1
    gs::gs_registers r = base;
    r.PRIM.TME = true;
    r.TEX0_1.TBW = fixed::uint<6>::from_wrapped(frame_fbw);
    r.TEX0_1.TW = fixed::u4::from_wrapped(10);
    r.TEX0_1.TH = fixed::u4::from_wrapped(9);
    r.TEX0_1.TFX = gs::tfx::DECAL;
    // S1..S6 share one state (nothing is written between them but vertices): each copies the centre texel
    // of one cell into another.
    auto copy = [&](at from, at to, bool first) {
      draw s = sprite(r, to.x, to.y, cell, cell, 0x80808080u, (from.x + 4) * 16 + 8, (from.y + 4) * 16 + 8);
      s.texflush = first;
      b.add(s);
    };
    copy(a, bb, true);   // S1: q0 -> q1
    copy(bb, c, false);  // S2: reads q1 after S1 wrote it (the buffer held q0)
    copy(d, e, false);   // S3: q2 -> q2
    copy(e, f, false);   // S4: reads e, written by S3 while q2 was buffered
    copy(g, g2, false);  // S5: leaves page P0
    copy(bb, h, false);  // S6: back to q1 of P0
    b.add_patch("texture_buffer.other_quarter", "texture_buffer", c.x, c.y,
                "reads cell (8, 88) (quarter q1) after S1 wrote it while quarter q0 was buffered: new 0xc04010 unless "
                "the whole page (or the draw) was buffered");
    b.add_patch(
        "texture_buffer.same_quarter", "texture_buffer", f.x, f.y,
        "reads cell (40, 72) after S3 wrote it while its own quarter q2 was buffered: new 0x10c040 only per fragment");
    b.add_patch(
        "texture_buffer.after_leaving_page", "texture_buffer", h.x, h.y,
        "reads cell (8, 88) again after S5 read page 21: new 0x1040c0 unless the draw was read once before it began");
  }
  b.d.not_probed.push_back(
      {"tfx_rounding",
       "floor and truncate round (Ct * Cf) >> 7 alike: the product of the unsigned texel and fragment "
       "colour is never negative, so no drawable input tells them apart (tests/probe checks every "
       "Ct x Cf 8.7 pair)"});
  // Perspective texturing (docs/stq-evidence.md): a patch needs a texel boundary crossed at a chosen
  // S/Q, which the model's S, T, Q planes (rounded to float32 by the model's choice, perspective.hpp)
  // decide as much as the option does; not designed yet.
  for (const char* option : {"stq_range", "stq_convert"})
    b.d.not_probed.push_back({option,
                              "no patch designed yet: the texel a perspective triangle's pixel reads depends on how "
                              "S, T and Q are interpolated (float32 in a different order in each source, "
                              "docs/stq-evidence.md) as well as on this option; a sprite with Q = 1 cannot reach "
                              "the 2047 limit or a negative S/Q between 0 and -1/16 texel apart from the others"});
  // docs/evidence.md P14. uv_plane: fixed_16 lands below the exact value by at most
  // (|x − x0| + |y − y0| + 1) / 2^16 of a sixteenth, x0, y0 its first vertex up and left of the pixel.
  b.d.not_probed.push_back({"uv_plane",
                            "no patch designed yet: fixed_16 lands below the exact U by at most (|x - x0| + "
                            "|y - y0| + 1) / 65536 of a sixteenth from its first vertex; to differ also under "
                            "uv_convert=floor_1_64 (+1/64) that vertex must lie over 1000 pixels up and left of "
                            "the patch, off the probe's frame without an XYOFFSET"});
  return b.d;
}

}  // namespace

const design& probe_design() {
  static const design d = make_design();
  return d;
}

std::vector<std::pair<int, int>> sample_pixels(const patch& p) {
  std::vector<std::pair<int, int>> px;
  for (int y = p.y + sample_inset; y < p.y + cell - sample_inset; ++y)
    for (int x = p.x + sample_inset; x < p.x + cell - sample_inset; ++x) px.emplace_back(x, y);
  return px;
}

}  // namespace gsdot3::probe
