// The frame as GIF packets (pipeline/frame_packets.hpp): the stream's structure against the paper's
// pass sequence written out by hand, every register write decoded by the strict decoders to the
// value written and its fields checked against their manual layouts, the primitives against the
// prepared scene, the uploads replayed through the packet interpreter against the scene's textures,
// and the dump container (header, state, packets, display registers) read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gs_arith/registers.hpp"
#include "gs_memory/clut_load.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/interpreter.hpp"
#include "gs_packets/state.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/pass_table.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"
#include "replayed_frame.hpp"

namespace gsdot3::pipeline {
namespace {

namespace pk = gs::packets;

std::uint8_t addr(std::string_view n) { return *pk::gs_register_address(n); }
std::uint64_t bits(std::uint64_t v, int lo, int n) { return (v >> lo) & ((std::uint64_t{1} << n) - 1); }

const scene& small_scene() {
  static const scene s = [] {
    scene t = default_scene(64);
    t.width = 160;
    t.height = 120;
    return t;
  }();
  return s;
}

// The pass table by name (lookup of a drawn pass's decoded registers).
const std::vector<std::pair<std::string, const pass_regs*>>& table() {
  using namespace passes;
  static const std::vector<std::pair<std::string, const pass_regs*>> t = {
      {"fill", &step1_ambient},
      {"two_pass_positive", &two_pass_positive},
      {"two_pass_negative", &two_pass_negative},
      {"three_pass_add_terms", &three_pass_add_terms},
      {"two_pass_add_alpha", &two_pass_add_alpha},
      {"gouraud_dot", &gouraud_dot},
      {"four_pass_sphere", &four_pass_sphere},
      {"four_pass_x", &four_pass_x},
      {"four_pass_y", &four_pass_y},
      {"four_pass_z", &four_pass_z},
      {"baseline_add", &baseline_add},
      {"baseline_subtract", &baseline_subtract},
      {"post_add_into_red", &post_add_into_red},
      {"ilp_into_lab", &ilp_into_lab},
      {"diffuse_layer", &diffuse_layer},
      {"multiply_red", &multiply_red},
      {"multiply_green", &multiply_green},
      {"multiply_blue", &multiply_blue},
      {"move_into_alpha", &move_into_alpha}};
  return t;
}

struct decoded {
  std::vector<pk::gif_event> events;
  // per PRIM write: "sprite|triangle PASS BUFFER", per local -> local transfer "transfer SRC -> DST";
  // consecutive repeats collapsed
  std::vector<std::string> passes;
};

decoded decode(const frame_packets& fp) {
  decoded d;
  d.events = pk::decode_gif(fp.gif);
  std::map<std::uint8_t, std::uint64_t> regs;
  // The layout (docs/dumps.md): the DPB at FBP 0, the LAB at P, the output at 2P.
  const std::uint32_t P = fp.buffers.pages;
  const std::map<std::uint32_t, std::string> buffers = {{0, "DPB"}, {P, "LAB"}, {2 * P, "out"}};
  auto buffer_name = [&](std::uint32_t fbp) {
    const auto b = buffers.find(fbp);
    return b == buffers.end() ? std::string("?") : b->second;
  };
  for (const pk::gif_event& e : d.events) {
    if (e.what != pk::gif_event::kind::reg_write) continue;
    regs[e.address] = e.value;
    if (e.address == addr("TRXDIR") && gs::mem::decode_trxdir(e.value).XDIR == gs::mem::xdir::local_to_local) {
      const gs::mem::bitbltbuf_reg blt = gs::mem::decode_bitbltbuf(regs[addr("BITBLTBUF")]);
      d.passes.push_back("transfer " + buffer_name(static_cast<std::uint32_t>(blt.SBP.value()) / 32) + " -> " +
                         buffer_name(static_cast<std::uint32_t>(blt.DBP.value()) / 32));
    }
    if (e.address != addr("PRIM")) continue;
    const gs::prim_reg prim = gs::decode_prim(e.value);
    gs::gs_registers r;
    r.PRIM.TME = prim.TME;
    r.PRIM.ABE = prim.ABE;
    const gs::tex0_reg tex0 = gs::decode_tex0(regs[addr("TEX0_1")]);
    r.TEX0_1.TFX = tex0.TFX;
    r.TEX0_1.TCC = tex0.TCC;
    r.ALPHA_1 = gs::decode_alpha(regs[addr("ALPHA_1")]);
    r.COLCLAMP = gs::decode_colclamp(regs[addr("COLCLAMP")]);
    const gs::frame_reg frame = gs::decode_frame(regs[addr("FRAME_1")]);
    r.FRAME_1.FBMSK = frame.FBMSK;
    std::string pass = "?";
    if (!prim.TME) r.TEX0_1 = {};  // untextured: TEX0 is not part of the pass
    for (const auto& [n, p] : table()) {
      // Three-pass's pass 3 has two-pass's post-pass registers (DECAL, Cs + Cd, alpha kept), on triangles.
      if (p == &passes::three_pass_add_terms && prim.PRIM != gs::prim_type::TRIANGLE) continue;
      gs::gs_registers want = p->registers();
      if (!prim.TME) want.TEX0_1 = {};
      if (want == r) {
        pass = n;
        break;
      }
    }
    const std::string name = std::string(prim.PRIM == gs::prim_type::SPRITE ? "sprite " : "triangle ") + pass + " " +
                             buffer_name(static_cast<std::uint32_t>(frame.FBP.value()));
    if (d.passes.empty() || d.passes.back() != name) d.passes.push_back(name);
  }
  return d;
}

// The paper's steps (section 3.1; 3.5 two-pass, 3.6 four-pass, section 2 baseline) as the passes
// the stream must draw, per light the method's own.
std::vector<std::string> expected_passes(method m, std::size_t lights) {
  std::vector<std::string> p = {"sprite fill DPB", "sprite fill LAB", "sprite fill out", "triangle fill LAB"};
  for (std::size_t l = 0; l < lights; ++l) {
    p.push_back("sprite fill DPB");
    switch (m) {
      case method::two_pass:
        p.insert(p.end(),
                 {"triangle two_pass_positive DPB", "triangle two_pass_negative DPB", "sprite two_pass_add_alpha DPB"});
        break;
      case method::four_pass:
        p.insert(p.end(), {"triangle four_pass_sphere DPB", "triangle four_pass_x DPB", "triangle four_pass_y DPB",
                           "triangle four_pass_z DPB"});
        break;
      case method::baseline: p.insert(p.end(), {"triangle baseline_add DPB", "triangle baseline_subtract DPB"}); break;
      case method::gouraud: p.push_back("triangle gouraud_dot DPB"); break;
      case method::three_pass:
        p.insert(p.end(), {"triangle two_pass_positive DPB", "triangle two_pass_negative DPB",
                           "triangle three_pass_add_terms DPB"});
        break;
    }
    p.insert(p.end(), {"sprite post_add_into_red DPB", "sprite ilp_into_lab LAB"});
  }
  // Step 3 into the DPB ("We are done with the DPB. Clear it to zero and render all objects unlit"),
  // step 4's copy of the LAB into the output as a local -> local transfer.
  p.insert(p.end(), {"sprite fill DPB", "triangle diffuse_layer DPB", "transfer LAB -> out"});
  for (const char* c : {"red", "green", "blue"}) {
    p.push_back("sprite move_into_alpha out");
    p.push_back(std::string("sprite multiply_") + c + " out");
  }
  return p;
}

class FramePackets : public ::testing::TestWithParam<method> {};

TEST_P(FramePackets, DrawsThePapersPassesInOrder) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  const frame_packets fp = build_frame_packets(s, ps, GetParam(), render_options{});
  EXPECT_EQ(decode(fp).passes, expected_passes(GetParam(), s.lights.size()));
}

// Every register write decodes (strictly: no padding bit, no reserved value) to exactly the value
// written; the registers without a gs_arith / gs_memory decoder are checked field by field against
// the manual's layouts (XYOFFSET, SCISSOR, TEX1, PRMODECONT), ZBUF_1's fields too (ZBP 0-8, PSM 24-27,
// ZMSK 32), and the one local -> local transfer against the sprite area.
TEST_P(FramePackets, EveryRegisterWriteDecodesToTheValueWritten) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  const frame_packets fp = build_frame_packets(s, ps, GetParam(), render_options{});
  std::map<std::string, int> seen;
  for (const pk::gif_event& e : decode(fp).events) {
    if (e.what != pk::gif_event::kind::reg_write) continue;
    const std::string n(pk::gs_register_name_of(e.address).value_or("?"));
    ++seen[n];
    const std::uint64_t v = e.value;
    if (n == "PRIM")
      EXPECT_EQ(gs::encode(gs::decode_prim(v)), v);
    else if (n == "RGBAQ")
      EXPECT_EQ(gs::encode(gs::decode_rgbaq(v)), v);
    else if (n == "TEX0_1")
      EXPECT_EQ(gs::encode(gs::decode_tex0(v)), v);
    else if (n == "ALPHA_1")
      EXPECT_EQ(gs::encode(gs::decode_alpha(v)), v);
    else if (n == "TEST_1")
      EXPECT_EQ(gs::encode(gs::decode_test(v)), v);
    else if (n == "FRAME_1")
      EXPECT_EQ(gs::encode(gs::decode_frame(v)), v);
    else if (n == "COLCLAMP")
      EXPECT_EQ(gs::encode(gs::decode_colclamp(v)), v);
    else if (n == "PABE")
      EXPECT_EQ(v, 0u);
    else if (n == "FBA_1")
      EXPECT_EQ(v, 0u);
    else if (n == "DTHE")
      EXPECT_EQ(v, 0u);
    else if (n == "CLAMP_1")
      EXPECT_EQ(gs::mem::encode(gs::mem::decode_clamp(v)), v);
    else if (n == "BITBLTBUF")
      EXPECT_EQ(gs::mem::encode(gs::mem::decode_bitbltbuf(v)), v);
    else if (n == "TRXPOS")
      EXPECT_EQ(gs::mem::encode(gs::mem::decode_trxpos(v)), v);
    else if (n == "TRXREG")
      EXPECT_EQ(gs::mem::encode(gs::mem::decode_trxreg(v)), v);
    else if (n == "TRXDIR")
      EXPECT_TRUE(v == 0u || v == 2u) << v;  // host -> local, local -> local
    else if (n == "TEXFLUSH")
      EXPECT_EQ(v, 0u);
    else if (n == "UV")
      EXPECT_EQ(v & ~(0x3FFFull | 0x3FFFull << 16), 0u);  // U 0-13, V 16-29
    else if (n == "XYZ2")
      EXPECT_LT(v >> 32, 1ull << 24);  // Z fits PSMZ24
    else if (n == "PRMODECONT")
      EXPECT_EQ(v, 1u);  // AC = 1: PRIM (not PRMODE) gives the attributes
    else if (n == "XYOFFSET_1")
      EXPECT_EQ(v, (std::uint64_t{2048 << 4} << 32) | (2048 << 4));
    else if (n == "SCISSOR_1") {
      const auto x0 = bits(v, 0, 11), x1 = bits(v, 16, 11), y0 = bits(v, 32, 11), y1 = bits(v, 48, 11);
      EXPECT_EQ(v, x0 | x1 << 16 | y0 << 32 | y1 << 48);
      EXPECT_LE(x0, x1);
      EXPECT_LT(x1, static_cast<std::uint64_t>(s.width));
      EXPECT_LE(y0, y1);
      EXPECT_LT(y1, static_cast<std::uint64_t>(s.height));
    } else if (n == "ZBUF_1") {
      EXPECT_EQ(gs::encode(gs::decode_zbuf(v)), v);
      EXPECT_EQ(bits(v, 0, 9), 3u * fp.buffers.pages);  // ZBP = 3P, the Z buffer's own pages
      EXPECT_EQ(bits(v, 24, 4), 1u);                    // PSMZ24
      EXPECT_EQ(v & ~(0x1FFull | 0xFull << 24 | 1ull << 32), 0u);
    } else if (n == "TEX1_1") {
      EXPECT_EQ(v, 1u);  // LCM = 1 (K = 0: the base level), MMAG = MMIN = 0 (nearest)
    } else {
      ADD_FAILURE() << "unexpected register " << n << " = 0x" << std::hex << v;
    }
  }
  for (const char* n :
       {"PRIM",       "TEX0_1",    "TEX1_1",     "CLAMP_1",  "ALPHA_1", "TEST_1", "FRAME_1", "ZBUF_1",
        "XYOFFSET_1", "SCISSOR_1", "PRMODECONT", "COLCLAMP", "DTHE",    "PABE",   "FBA_1",   "BITBLTBUF",
        "TRXPOS",     "TRXREG",    "TRXDIR",     "RGBAQ",    "UV",      "XYZ2"})
    EXPECT_GT(seen[n], 0) << n << " is never written";
}

// Step 4's copy of the LAB into the output is one local -> local transfer (TRXDIR = 2) of the whole
// rectangle the step-4 sprites are clipped to (the SCISSOR_1 in effect): BITBLTBUF SBP = the LAB, DBP
// = the output (blocks: 32 per page), both PSMCT32 with the frame's FBW; TRXPOS the rectangle's corner
// on both sides with DIR = 0; TRXREG its width and height (SCISSOR's x1 / y1 are inclusive).
TEST_P(FramePackets, CopiesTheLabIntoTheOutputByOneLocalToLocalTransfer) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  const frame_packets fp = build_frame_packets(s, ps, GetParam(), render_options{});
  std::map<std::uint8_t, std::uint64_t> regs;
  int copies = 0;
  for (const pk::gif_event& e : decode(fp).events) {
    if (e.what != pk::gif_event::kind::reg_write) continue;
    regs[e.address] = e.value;
    if (e.address != addr("TRXDIR") || e.value != 2) continue;
    ++copies;
    const std::uint64_t blt = regs[addr("BITBLTBUF")], pos = regs[addr("TRXPOS")], size = regs[addr("TRXREG")],
                        clip = regs[addr("SCISSOR_1")];
    const std::uint64_t P = fp.buffers.pages, fbw = static_cast<std::uint64_t>((s.width + 63) / 64);
    EXPECT_EQ(bits(blt, 0, 14), 32 * P);       // SBP: the LAB
    EXPECT_EQ(bits(blt, 16, 6), fbw);          // SBW
    EXPECT_EQ(bits(blt, 24, 6), 0u);           // SPSM = PSMCT32
    EXPECT_EQ(bits(blt, 32, 14), 32 * 2 * P);  // DBP: the output
    EXPECT_EQ(bits(blt, 48, 6), fbw);          // DBW
    EXPECT_EQ(bits(blt, 56, 6), 0u);           // DPSM = PSMCT32
    const std::uint64_t x0 = bits(clip, 0, 11), x1 = bits(clip, 16, 11), y0 = bits(clip, 32, 11),
                        y1 = bits(clip, 48, 11);
    EXPECT_EQ(pos, x0 | y0 << 16 | x0 << 32 | y0 << 48);   // SSAX, SSAY, DSAX, DSAY; DIR = 0
    EXPECT_EQ(size, (x1 + 1 - x0) | (y1 + 1 - y0) << 32);  // RRW, RRH
    EXPECT_GT(x1, x0);
    EXPECT_GT(y1, y0);
  }
  EXPECT_EQ(copies, 1);
}

// The triangles of every triangle pass are the prepared scene's, in mesh order: XYZ2 = window 12.4 +
// XYOFFSET and the vertex depth; UV the normal map's 12.4 coordinates (or the sphere map's).
TEST_P(FramePackets, TrianglesAreThePreparedScenes) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  const frame_packets fp = build_frame_packets(s, ps, GetParam(), render_options{});
  const std::size_t passes_per_light = GetParam() == method::gouraud      ? 1
                                       : GetParam() == method::two_pass   ? 2
                                       : GetParam() == method::three_pass ? 3
                                                                          : 4;
  EXPECT_EQ(fp.triangles, ps.triangles.size() * (2 + passes_per_light * s.lights.size()));
  std::size_t vertex = 0, mismatches = 0;
  std::uint64_t prim = 0, uv = 0;
  for (const pk::gif_event& e : decode(fp).events) {
    if (e.what != pk::gif_event::kind::reg_write) continue;
    if (e.address == addr("PRIM")) prim = e.value, vertex = 0;
    if (e.address == addr("UV")) uv = e.value;
    if (e.address != addr("XYZ2") || (prim & 7) != 3) continue;
    const prepared_triangle& t = ps.triangles[(vertex / 3) % ps.triangles.size()];
    const std::size_t k = vertex % 3;
    ++vertex;
    const bool xy_ok = bits(e.value, 0, 16) == static_cast<std::uint64_t>(t.setup.v[k].x + 32768) &&
                       bits(e.value, 16, 16) == static_cast<std::uint64_t>(t.setup.v[k].y + 32768) &&
                       bits(e.value, 32, 32) == static_cast<std::uint64_t>(t.z24[k]);
    // The normal-map passes send uv16; the four-pass sphere pass its own (checked only for range).
    const bool uv_nm = bits(uv, 0, 14) == static_cast<std::uint64_t>(t.uv16[k][0]) &&
                       bits(uv, 16, 14) == static_cast<std::uint64_t>(t.uv16[k][1]);
    if (!xy_ok || !(uv_nm || GetParam() == method::four_pass)) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0u);
}

// Replaying the stream through the packet interpreter (register writes and host -> local transfers)
// leaves the scene's textures in memory where TEX0 reads them and the palettes where CBP points.
TEST_P(FramePackets, UploadsPutTheScenesTexturesWhereTheTexturesAreRead) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  const frame_packets fp = build_frame_packets(s, ps, GetParam(), render_options{});
  gs::mem::local_memory m;
  pk::interpreter it(m);
  for (const pk::gif_event& e : decode(fp).events) it.apply(e, 16 * std::uint64_t{e.offset});
  // The textures, the eight palettes, and step 4's local -> local copy of the LAB.
  EXPECT_EQ(it.transfers().size(), (GetParam() == method::four_pass ? 3u : 2u) + 8u + 1u);
  std::map<std::uint64_t, gs::tex0_reg> textures;  // every TEX0 written, by TBP0
  for (const pk::gif_event& e : decode(fp).events)
    if (e.what == pk::gif_event::kind::reg_write && e.address == addr("TEX0_1")) {
      const gs::tex0_reg t = gs::decode_tex0(e.value);
      textures[static_cast<std::uint64_t>(t.TBP0.value())] = t;
    }
  const gs_inputs in = place_inputs(make_inputs(s, GetParam(), render_options{}), fp.buffers.first_texture_block());
  // Gouraud draws no texture in its light pass: its normal map is uploaded (one input set for every
  // method) but no TEX0 names it.
  const auto nm = textures.find(static_cast<std::uint64_t>(in.nm_at[0].BP.value()));
  if (GetParam() == method::gouraud) {
    EXPECT_EQ(nm, textures.end());
  } else {
    ASSERT_NE(nm, textures.end());
    EXPECT_EQ(nm->second.PSM, gs::tex_psm::PSMT8);
    EXPECT_EQ(1 << nm->second.TW.value(), s.normals.width);
  }
  long wrong = 0;
  for (int y = 0; y < s.normals.height; ++y)
    for (int x = 0; x < s.normals.width; ++x)
      wrong += m.read_pixel(in.nm_at[0], static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) !=
               s.normals.index[static_cast<std::size_t>(y * s.normals.width + x)];
  for (int y = 0; y < s.diffuse.height; ++y)
    for (int x = 0; x < s.diffuse.width; ++x)
      wrong += m.read_pixel(in.diffuse_at, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) !=
               s.diffuse.texels[static_cast<std::size_t>(y * s.diffuse.width + x)];
  EXPECT_EQ(wrong, 0);
  // The two-pass positive palette (section 3.5): entry i = nearest(127·max(n_i, 0)) packed as signed chars,
  // read back from memory by TEX0.CLD = 1 at the pass's CBP.
  if (GetParam() == method::two_pass) {
    gs::tex0_reg t;
    t.PSM = gs::tex_psm::PSMT8;
    t.CBP = fixed::uint<14>::from_wrapped(in.cbp[0][0]);
    t.CLD = gs::u3::from_wrapped(1);
    const gs::clut_buffer clut = gs::mem::load_clut(m, t, {}).buffer;
    EXPECT_EQ(clut, two_pass_palette(s.normals.palette, false));
  }
  // The three-pass terms palette at its slot: 128 + Max(−n, 0) − Max(n, 0) from Appendix 2's packing.
  if (GetParam() == method::three_pass) {
    gs::tex0_reg t;
    t.PSM = gs::tex_psm::PSMT8;
    t.CBP = fixed::uint<14>::from_wrapped(in.cbp[0][static_cast<std::size_t>(clut_slot::terms)]);
    t.CLD = gs::u3::from_wrapped(1);
    const gs::clut_buffer clut = gs::mem::load_clut(m, t, {}).buffer;
    for (std::size_t i = 0; i < s.normals.palette.size() && i < 256; ++i) {
      const two_pass_texel p = pack_two_pass(s.normals.palette[i]);  // Max(±n, 0): one side is 0
      EXPECT_EQ(clut[i].r.value(), 128 - (p.positive.r.value() - p.negative.r.value())) << i;
      EXPECT_EQ(clut[i].g.value(), 128 - (p.positive.g.value() - p.negative.g.value())) << i;
      EXPECT_EQ(clut[i].b.value(), 128 - (p.positive.b.value() - p.negative.b.value())) << i;
    }
  }
}

// The dump: new layout, state version 8 and its size, PATH3 transfers of at most 1 MiB holding the
// stream's register writes and IMAGE data in order (decode_gif of the unsplit stream, the reference),
// each ending at an EOP tag, then the registers and a vsync; PMODE / DISPFB1 / DISPLAY1 show circuit 1
// reading the output buffer; SMODE1.CMOD = 2 (NTSC, PCSX2's GetVideoMode), SMODE2.INT = 1.
TEST_P(FramePackets, DumpHoldsTheStreamAndDisplaysTheOutputBuffer) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  const frame_packets fp = build_frame_packets(s, ps, GetParam(), render_options{});
  const gs::dump::gs_dump d = gs::dump::read_dump(gs::dump::write_dump(frame_dump(fp)));
  EXPECT_TRUE(d.new_layout);
  EXPECT_EQ(d.state_version, 8u);
  EXPECT_EQ(d.state.size(), 4194752u);  // GSState::Freeze, version 8 (docs/dumps.md: UV and FOG are u32)
  EXPECT_EQ(d.serial, "gsdot3");
  ASSERT_GE(d.packets.size(), 3u);
  std::vector<std::uint8_t> all;
  for (std::size_t i = 0; i + 2 < d.packets.size(); ++i) {
    EXPECT_EQ(d.packets[i].type, gs::dump::packet_type::transfer);
    EXPECT_EQ(d.packets[i].path, 2u);
    EXPECT_LE(d.packets[i].data.size(), std::size_t{1} << 20);
    const auto events = gs::packets::decode_gif(d.packets[i].data);
    std::size_t last_tag = 0;
    for (std::size_t k = 0; k < events.size(); ++k)
      if (events[k].what == gs::packets::gif_event::kind::tag) last_tag = k;
    EXPECT_TRUE(events[last_tag].tag.EOP);
    all.insert(all.end(), d.packets[i].data.begin(), d.packets[i].data.end());
  }
  auto contents = [](const std::vector<std::uint8_t>& bytes) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> c;
    for (const auto& e : gs::packets::decode_gif(bytes)) {
      if (e.what == gs::packets::gif_event::kind::reg_write) c.emplace_back(e.address, e.value);
      if (e.what == gs::packets::gif_event::kind::image)
        for (const std::uint8_t b : e.data) c.emplace_back(0x100, b);
    }
    return c;
  };
  EXPECT_EQ(contents(all), contents(fp.gif));
  EXPECT_EQ(d.packets[d.packets.size() - 2].type, gs::dump::packet_type::registers);
  EXPECT_EQ(d.packets.back().type, gs::dump::packet_type::vsync);
  auto priv = [&](std::uint32_t at) {
    std::uint64_t v = 0;
    for (int b = 7; b >= 0; --b) v = v << 8 | d.privileged[at + static_cast<std::uint32_t>(b)];
    return v;
  };
  const std::uint64_t pmode = priv(0x0000), dispfb1 = priv(0x0070), display1 = priv(0x0080);
  EXPECT_EQ(bits(pmode, 0, 1), 1u);                       // EN1
  EXPECT_EQ(bits(pmode, 1, 1), 0u);                       // EN2
  EXPECT_EQ(bits(pmode, 2, 3), 1u);                       // CRTMD = 001
  EXPECT_EQ(bits(pmode, 8, 8), 0xFFu);                    // ALP: circuit 1 only
  EXPECT_EQ(bits(dispfb1, 0, 9), 2u * fp.buffers.pages);  // FBP: the output buffer, 2P
  EXPECT_EQ(bits(dispfb1, 9, 6), static_cast<std::uint64_t>((s.width + 63) / 64));
  EXPECT_EQ(bits(dispfb1, 15, 5), 0u);       // PSMCT32
  EXPECT_EQ(bits(priv(0x0010), 13, 2), 2u);  // SMODE1.CMOD: NTSC
  EXPECT_EQ(bits(priv(0x0020), 0, 1), 1u);   // SMODE2.INT
  EXPECT_EQ((bits(display1, 32, 12) + 1) % (bits(display1, 23, 4) + 1), 0u);
  EXPECT_EQ((bits(display1, 32, 12) + 1) / (bits(display1, 23, 4) + 1),
            static_cast<std::uint64_t>(s.width));                               // DW / MAGH
  EXPECT_EQ(bits(display1, 44, 11) + 1, static_cast<std::uint64_t>(s.height));  // DH
  EXPECT_EQ(gs::dump::state_get(d.state, *gs::dump::state_field_v8("PRMODECONT")), 1u);
}

TEST(FramePacketsLimits, RefusesWhatItDoesNotWrite) {
  const scene& s = small_scene();
  scene wide = s;
  wide.width = 1024;
  wide.height = 64;
  EXPECT_THROW(build_frame_packets(wide, prepare(wide), method::two_pass, render_options{}), std::invalid_argument);
}

// Section 3.4's z-trick clears as register writes, read back from the stream: the DPB (z-trick) or
// the LAB (z-trick-psmz32) and no other buffer drawn with FRAME_1.PSM = PSMZ32; the ILP pass of each
// light the only primitives with ZBUF_1 at the DPB, each with ZMSK = 0, ZTST = ALWAYS, Z = 0x00808080
// and FRAME_1 = the LAB under a SCISSOR_1 of whole 64x32 pages, the page in 8x2 channel-fetch tiles.
TEST(FramePacketsZTrick, DrawsInTheZLayoutAndClearsTheDpbThroughZbuf) {
  const scene& s = small_scene();
  const prepared_scene ps = prepare(s);
  for (const dpb_clear_mode clear : {dpb_clear_mode::z_trick, dpb_clear_mode::z_trick_psmz32}) {
    render_options o;
    o.dpb_clear = clear;
    const frame_packets fp = build_frame_packets(s, ps, method::two_pass, o);
    const std::uint32_t P = fp.buffers.pages, z_fbp = clear == dpb_clear_mode::z_trick ? 0 : P;
    std::map<std::uint8_t, std::uint64_t> regs;
    std::map<std::uint32_t, std::size_t> z_layout_prims;  // per FBP
    std::size_t clear_prims = 0, clear_vertices = 0, clear_pages = 0;
    for (const pk::gif_event& e : pk::decode_gif(fp.gif)) {
      if (e.what != pk::gif_event::kind::reg_write) continue;
      regs[e.address] = e.value;
      const gs::frame_reg frame = gs::decode_frame(regs[addr("FRAME_1")]);
      const gs::zbuf_reg zbuf = gs::decode_zbuf(regs[addr("ZBUF_1")]);
      if (e.address == addr("PRIM") && frame.PSM == gs::frame_psm::PSMZ32) ++z_layout_prims[frame.FBP.value()];
      if (regs.count(addr("ZBUF_1")) == 0 || zbuf.ZBP.value() != 0) continue;
      if (e.address == addr("PRIM")) {  // one PRIM (GIF tag) per page
        ++clear_prims;
        EXPECT_FALSE(zbuf.ZMSK);
        EXPECT_EQ(gs::decode_test(regs[addr("TEST_1")]).ZTST, gs::ztst::ALWAYS);
        EXPECT_EQ(frame.FBP.value(), P);  // the LAB
        const std::uint64_t sc = regs[addr("SCISSOR_1")];
        const std::uint64_t x0 = bits(sc, 0, 11), x1 = bits(sc, 16, 11) + 1, y0 = bits(sc, 32, 11),
                            y1 = bits(sc, 48, 11) + 1;
        EXPECT_TRUE(x0 % 64 == 0 && x1 % 64 == 0 && y0 % 32 == 0 && y1 % 32 == 0) << std::hex << sc;
        clear_pages = (x1 - x0) / 64 * ((y1 - y0) / 32);
      }
      if (e.address == addr("XYZ2")) {
        EXPECT_EQ(bits(e.value, 32, 32), 0x00808080u);
        ++clear_vertices;
      }
    }
    EXPECT_EQ(z_layout_prims.size(), 1u) << name(clear);
    EXPECT_GT(z_layout_prims[z_fbp], 0u) << name(clear);
    ASSERT_GT(clear_pages, 0u);
    EXPECT_EQ(clear_prims, s.lights.size() * clear_pages) << name(clear);
    EXPECT_EQ(clear_vertices, clear_prims * (64 * 32 / (8 * 2)) * 2) << name(clear);  // 8x2 tiles, two XYZ2 each
  }
}

// A frame whose triangles all lie above it has an empty sprite area at row 0, which SCISSOR_1 cannot
// hold as SCAY1 = SCAY0 - 1 = -1 (render_small found it); the stream clips it to nothing and replays
// to the renderer's frame: the ambient-free clear everywhere.
TEST_P(FramePackets, AFrameShowingNoTriangleIsWrittenAndReplays) {
  scene s = small_scene();
  s.view.eye = {0.0f, -1.0f, 3.0f};
  s.view.target = {0.0f, -6.0f, 0.0f};  // the head far above the frame's top edge
  const prepared_scene ps = prepare(s);
  const frame f = render(s, ps, GetParam(), render_options{});
  ASSERT_TRUE(std::all_of(f.visible_triangle.begin(), f.visible_triangle.end(), [](int t) { return t < 0; }));
  const replayed_frame r = replay_frame(build_frame_packets(s, ps, GetParam(), render_options{}), {});
  EXPECT_EQ(r.colour, f.colour);
}

INSTANTIATE_TEST_SUITE_P(Methods, FramePackets, ::testing::ValuesIn(gs_methods), method_param_name);

}  // namespace
}  // namespace gsdot3::pipeline
