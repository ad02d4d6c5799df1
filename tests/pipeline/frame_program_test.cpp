// frame_program.hpp: the one list of a frame's operations. Two readings of it must agree: the packet
// stream's register state (the latest SCISSOR_1, TEST_1 / ZBUF_1, FRAME_1 and TEX0_1 before each
// primitive) and what the renderer's drawing operation draws with (its buffer, register set, depth
// rule, texture, area). The step sequence is checked against the paper's (section 3.1, the passes
// per method of sections 2, 3.5, 3.6 and 4), written here as step numbers, not read from the program.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipeline/default_scene.hpp"
#include "pipeline/floor.hpp"
#include "pipeline/frame_program.hpp"

namespace gsdot3::pipeline {
namespace {

using kind = frame_op::kind;

// The step number a checkpoint's label starts with ("2.3 Max(n,0)·l ..." -> "2.3").
std::string step_of(std::string_view label) { return std::string(label.substr(0, label.find(' '))); }

struct state {
  const frame_op* target = nullptr;
  const frame_op* depth = nullptr;
  const frame_op* texture = nullptr;
  area_role clip = area_role::frame;
};

bool in(const regs_list& l, const pass_regs* r) {
  for (std::size_t i = 0; i < l.n; ++i)
    if (l.at[i] == r) return true;
  return false;
}

// Every drawing operation against the register state the operations before it set.
void check_state(const frame_program& p, const std::string& what) {
  using namespace passes;
  state st;
  for (const frame_op& op : p.ops) {
    auto drawn_into_target = [&] {
      ASSERT_NE(st.target, nullptr) << what;
      EXPECT_EQ(st.target->buffer, op.buffer) << what;
      EXPECT_EQ(st.target->regs, op.regs) << what;
    };
    auto depth_is = [&](const gs::test_reg& t, const gs::zbuf_reg& z, buffer_role at = buffer_role::z_words) {
      ASSERT_NE(st.depth, nullptr) << what;
      EXPECT_EQ(st.depth->test, &t) << what;
      EXPECT_EQ(st.depth->zbuf, &z) << what;
      EXPECT_EQ(st.depth->buffer, at) << what;
    };
    switch (op.what) {
      case kind::scissor: st.clip = op.area; break;
      case kind::depth: st.depth = &op; break;
      case kind::target: st.target = &op; break;
      case kind::texture: st.texture = &op; break;
      case kind::fill:
        drawn_into_target();
        EXPECT_TRUE(in(program_regs::fill, op.regs)) << what;
        if (op.area == area_role::sprite_area) { EXPECT_EQ(st.clip, area_role::sprite_area) << what; }
        depth_is(depth_always, op.writes_z ? z_written : z_masked);
        break;
      case kind::ambient:
        drawn_into_target();
        depth_is(depth_gequal, z_written);
        break;
      case kind::triangles:
        drawn_into_target();
        EXPECT_TRUE(in(program_regs::triangles, op.regs)) << what;
        depth_is(depth_gequal, z_masked);  // band_renderer::draw's rule
        if (op.texture != texture_role::none) {
          ASSERT_NE(st.texture, nullptr) << what;
          EXPECT_EQ(st.texture->regs, op.regs) << what;
          EXPECT_EQ(st.texture->texture, op.piece < 0 ? op.texture : texture_role::piece) << what;
          EXPECT_EQ(st.texture->piece, op.piece) << what;
          EXPECT_EQ(st.texture->no_clut, op.no_clut) << what;
          if (!op.no_clut) { EXPECT_EQ(st.texture->clut, op.clut) << what; }
        }
        EXPECT_EQ(st.clip, op.piece < 0 ? area_role::frame : area_role::piece) << what;
        break;
      case kind::projective:
        drawn_into_target();
        EXPECT_TRUE(in(program_regs::projective, op.regs)) << what;
        depth_is(depth_gequal, z_masked);
        ASSERT_NE(st.texture, nullptr) << what;
        EXPECT_EQ(st.texture->texture, texture_role::spot_map) << what;
        break;
      case kind::buffer_sprite:
        drawn_into_target();
        EXPECT_TRUE(in(op.texture == texture_role::buffer_t8h ? program_regs::t8h_sprite : program_regs::buffer_sprite,
                       op.regs))
            << what;
        depth_is(depth_always, z_masked);
        EXPECT_EQ(st.clip, area_role::sprite_area) << what;
        ASSERT_NE(st.texture, nullptr) << what;
        EXPECT_EQ(st.texture->texture, op.texture) << what;
        EXPECT_EQ(st.texture->source, op.source) << what;
        break;
      case kind::channel:
        drawn_into_target();
        EXPECT_TRUE(in(program_regs::channel, op.regs)) << what;
        if (op.z_clear) {  // section 3.4: Z = 0x00808080 written into the DPB (PSMZ24) over whole pages
          EXPECT_EQ(op.source, buffer_role::dpb) << what;
          depth_is(depth_always, z_written, buffer_role::dpb);
          EXPECT_EQ(st.clip, area_role::sprite_pages) << what;
        } else {
          depth_is(depth_always, z_masked);
          EXPECT_EQ(st.clip, area_role::sprite_area) << what;
        }
        break;
      case kind::plain:
        drawn_into_target();
        depth_is(depth_gequal, z_written);
        EXPECT_EQ(st.clip, area_role::frame) << what;
        break;
      default: break;
    }
  }
}

// The paper's passes per light of each method: two-pass's two multiplications and its n'_a pass
// (section 3.5), three-pass's three (the terms added as a separate pass), four-pass's sphere map and
// three axis passes (3.6), the 2002 method's four (section 2), Gouraud's one (section 4).
std::size_t light_passes(method m) {
  switch (m) {
    case method::two_pass: return 3;
    case method::three_pass: return 3;
    case method::four_pass: return 4;
    case method::baseline: return 4;
    case method::gouraud: return 1;
  }
  return 0;
}

// Section 3.1's steps in order: 1; per light 2.1, the passes (2.3; two-pass's third is 2.4a), a spot
// light's texture (four-pass after the passes, the others after the post filter), 2.4 twice, 2.6;
// then 3, 4 (one buffer: 2.6' per light, then 2.6, 3, 4 in one); 5 with non-normal-mapped geometry.
// `spot`: the last light is a spot light.
std::vector<std::string> paper_steps(method m, std::size_t lights, bool spot_last, const render_options& o,
                                     bool plain) {
  std::vector<std::string> s{"1"};
  const bool one = o.buffers == draw_buffers::one;
  for (std::size_t l = 0; l < lights; ++l) {
    const bool spot = spot_last && l + 1 == lights;
    s.push_back("2.1");
    for (std::size_t k = 0; k < light_passes(m); ++k) {
      if (k == 1 && spot && m == method::four_pass && o.spot_after_first_pass) s.push_back("2.3");
      s.push_back(m == method::two_pass && k == 2 ? "2.4a" : "2.3");
    }
    if (spot && m == method::four_pass && !o.spot_after_first_pass) s.push_back("2.3");
    s.push_back("2.4");
    s.push_back("2.4");
    if (spot && m != method::four_pass) s.push_back("2.4");
    s.push_back(one ? "2.6'" : "2.6");
  }
  if (one) {
    s.push_back("2.6,");
  } else {
    s.push_back("3");
    s.push_back("4");
  }
  if (plain) s.push_back("5");
  return s;
}

struct variant {
  const char* name;
  render_options o;
  bool spot, plain;
};

std::vector<variant> variants() {
  std::vector<variant> v;
  for (bool spot : {false, true})
    for (bool plain : {false, true})
      for (int k = 0; k < 5; ++k) {
        render_options o;
        const char* n = "two buffers";
        if (k == 1) o.buffers = draw_buffers::one, n = "one buffer";
        if (k == 2) o.dpb_clear = dpb_clear_mode::z_trick, n = "z-trick";
        if (k == 3) o.dpb_clear = dpb_clear_mode::z_trick_psmz32, n = "z-trick-psmz32";
        if (k == 4) o.spot_after_first_pass = true, n = "spot after the first pass";
        v.push_back({n, o, spot, plain});
      }
  return v;
}

TEST(FrameProgram, FollowsThePapersStepsAndItsStateAgreesWithEveryDrawingOperation) {
  for (method m : gs_methods)
    for (const variant& v : variants()) {
      if (v.o.spot_after_first_pass && m != method::four_pass) continue;  // frame_limits refuses it
      scene s = default_scene(16);
      s.width = 96, s.height = 80;
      s.lights.resize(2);
      if (v.spot) s.lights[1].kind = light_kind::spot, s.lights[1].position = {0.5f, 1.5f, 2.5f};
      if (v.plain) s.plain = floor_under(s.model, 3);
      const prepared_scene ps = prepare(s);
      const gs_inputs in = make_inputs(s, m, v.o);
      const frame_program p = build_frame_program(s, ps, m, v.o, in);
      const std::string what =
          std::string(name(m)) + ", " + v.name + (v.spot ? ", spot" : "") + (v.plain ? ", floor" : "");
      std::vector<std::string> steps;
      std::size_t dpb_fills = 0, z_clears = 0, displays = 0;
      for (const frame_op& op : p.ops) {
        if (op.what == kind::checkpoint) steps.push_back(step_of(op.label));
        dpb_fills += op.what == kind::fill && op.area == area_role::sprite_area && op.colour.to_u32() == 0x00808080u;
        z_clears += op.what == kind::channel && op.z_clear;
        displays += op.what == kind::display;
      }
      EXPECT_EQ(steps, paper_steps(m, 2, v.spot, v.o, v.plain)) << what;
      // 2.1 (section 3.4): an explicit fill per light, or one before the first light and the ILP
      // pass's Z writes after that (every light's, the last one's clearing for a next frame).
      const bool z_trick = v.o.dpb_clear != dpb_clear_mode::explicit_clear;
      EXPECT_EQ(dpb_fills, z_trick ? 1u : 2u) << what;
      EXPECT_EQ(z_clears, z_trick && v.o.buffers == draw_buffers::two ? 2u : 0u) << what;
      EXPECT_EQ(displays, 1u) << what;
      EXPECT_EQ(p.ops.back().what, kind::display) << what;
      EXPECT_EQ(p.ops.back().buffer, buffer_role::output) << what;
      check_state(p, what);
    }
}

}  // namespace
}  // namespace gsdot3::pipeline
