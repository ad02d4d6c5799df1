// Dump -> replay round trip (issue 15): the frame's GS dump (frame_packets + frame_dump, written and
// read back as bytes) replayed through gs_packets' interpreter leaves in its local memory exactly the
// renderer's memory-path buffers, at the same addresses (one buffer layout): the output (the
// displayed frame), the LAB and the DPB's pages (which step 3 draws the diffuse layer into) at the
// end, and the last light's DPB (the dot products) as the last pass into the LAB reads it, word for
// word over the frame, for every method, the embedded scene and random scenes.
// The renderer's buffers come from its trace (render_options::trace: each buffer after its last pass).
// (Checked to fail: with the triangle passes sent flat-shaded, PRIM.IIP = 0, the DPB and LAB differ.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "gs_arith/registers.hpp"
#include "gs_memory/address.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"

namespace gsdot3::pipeline {
namespace {

// The buffer a traced render left last in `target` ("DPB", "LAB", "diffuse", "frame").
const std::vector<std::uint32_t>& last(const std::vector<pass_record>& trace, const std::string& target) {
  for (auto it = trace.rbegin(); it != trace.rend(); ++it)
    if (it->target == target) return it->word;
  throw std::logic_error("no pass drew " + target);
}

void expect_round_trip(const scene& s, const prepared_scene& ps, method m, render_options o, const std::string& what,
                       std::size_t max_packet = gs::packets::default_max_packet_bytes) {
  o.memory_path = true;
  std::vector<pass_record> trace;
  o.trace = &trace;
  const frame f = render(s, ps, m, o);
  o.trace = nullptr;
  const frame_packets fp = build_frame_packets(s, ps, m, o);
  const gs::dump::gs_dump d =
      gs::dump::read_dump(gs::dump::write_dump(frame_dump(fp, {gs::packets::video_mode::ntsc, max_packet})));
  gs::mem::local_memory mem;
  gs::packets::interpreter gs(mem, {o.model, false});
  // The dump's PATH3 transfers (GIF packets of at most max_packet bytes) event by event (as interpreter::replay applies
  // it), the DPB read when the last primitive into the LAB (FRAME_1.FBP = P: the last light's ILP pass, which reads the
  // DPB's sums) starts.
  gs.load_state(d.state, d.state_version);
  const auto paths = gs::dump::decode_paths(d);
  ASSERT_EQ(paths[2].events.size(), paths[2].file_offsets.size());
  const std::uint8_t FRAME_1 = *gs::packets::gs_register_address("FRAME_1"),
                     PRIM = *gs::packets::gs_register_address("PRIM");
  const auto P = fp.buffers.pages;
  std::size_t last_into_lab = 0;
  std::uint32_t fbp = 0;
  for (std::size_t i = 0; i < paths[2].events.size(); ++i) {
    const gs::packets::gif_event& e = paths[2].events[i];
    if (e.what != gs::packets::gif_event::kind::reg_write) continue;
    if (e.address == FRAME_1) fbp = static_cast<std::uint32_t>(gs::decode_frame(e.value).FBP.value());
    if (e.address == PRIM && fbp == P) last_into_lab = i;
  }
  ASSERT_GT(last_into_lab, 0u);
  auto buffer_at = [&](std::uint32_t page) {  // PSMCT32, FBW = ceil(width / 64)
    return gs::mem::buffer{fixed::uint<14>::from_wrapped(32 * page), fixed::uint<6>::from_wrapped((s.width + 63) / 64),
                           gs::mem::psm::PSMCT32};
  };
  auto words = [&](const gs::mem::buffer& at) {
    std::vector<std::uint32_t> w(static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height));
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x)
        w[static_cast<std::size_t>(y * s.width + x)] =
            mem.read_pixel(at, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
    return w;
  };
  std::vector<std::uint32_t> dpb_read_by_ilp;
  for (std::size_t i = 0; i < paths[2].events.size(); ++i) {
    if (i == last_into_lab) dpb_read_by_ilp = words(buffer_at(0));
    gs.apply(paths[2].events[i],
             paths[2].file_offsets[i]);  // throws gs::packets::unmodelled_error at what the model cannot draw
  }
  for (const auto& u : gs.unmodelled_features())
    ADD_FAILURE() << what << ": unmodelled at byte " << u.offset << ": " << u.what;
  // The layout (docs/dumps.md): the DPB at FBP 0, the LAB at P, the output at 2P.
  const struct {
    const char* name;
    const std::vector<std::uint32_t>& replayed;
    const std::vector<std::uint32_t>& rendered;
  } buffers[] = {{"DPB read by the last ILP pass", dpb_read_by_ilp, last(trace, "DPB")},
                 {"DPB pages at the end (diffuse layer)", words(buffer_at(0)), last(trace, "diffuse")},
                 {"LAB", words(buffer_at(P)), last(trace, "LAB")},
                 {"output", words(buffer_at(2 * P)), last(trace, "frame")}};
  for (const auto& b : buffers) {
    long differing = 0;
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x) {
        const auto i = static_cast<std::size_t>(y * s.width + x);
        if (b.rendered[i] != b.replayed[i] && differing++ < 3)
          ADD_FAILURE() << what << ": " << b.name << " (" << x << ", " << y << "): renderer 0x" << std::hex
                        << b.rendered[i] << ", replay 0x" << b.replayed[i];
      }
    EXPECT_EQ(differing, 0) << what << ": " << b.name;
  }
  // The displayed frame and the last light's dot products, as render() returns them.
  const std::vector<std::uint32_t> out = words(buffer_at(2 * P));
  long differing = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    differing += f.colour[i] != (out[i] | 0xFF000000u);
    differing += f.dot.back()[i] != (dpb_read_by_ilp[i] & 0xFFu);
  }
  EXPECT_EQ(differing, 0) << what << ": frame / dot";
  EXPECT_GT(std::count_if(f.visible_triangle.begin(), f.visible_triangle.end(), [](std::int32_t t) { return t >= 0; }),
            200)
      << what << ": the head should be in view";
}

class RoundTrip : public ::testing::TestWithParam<method> {};

TEST_P(RoundTrip, ReplayedDumpIsTheRenderersFrameOnTheEmbeddedScene) {
  static const scene s = default_scene();
  expect_round_trip(s, prepare(s), GetParam(), render_options{}, "embedded scene");
}

// Section 3.8's 4-bit map: the dump uploads it as PSMT4 and its passes load 16-entry palettes.
TEST_P(RoundTrip, ReplayedDumpIsTheRenderersFrameWithAFourBitMap) {
  scene s = default_scene();
  s.normals = with_index_bits(s.normals, 4);
  render_options o;
  o.bilinear = true;
  expect_round_trip(s, prepare(s), GetParam(), o, "4-bit map, bilinear");
}

TEST_P(RoundTrip, ReplayedDumpIsTheRenderersFrameOnRandomScenes) {
  std::mt19937 rng(1500 + static_cast<unsigned>(GetParam()));
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), yaw(0.0f, 360.0f);
  std::uniform_int_distribution<int> byte(0, 255), scale(60, 127), size(40, 200);
  static const scene base = default_scene(64);
  auto colour = [&] {
    return std::array<std::uint8_t, 3>{static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                                       static_cast<std::uint8_t>(byte(rng))};
  };
  for (int trial = 0; trial < 4; ++trial) {
    scene s = base;
    s.width = size(rng);
    s.height = size(rng);
    // Even trials make the second light directional (section 3: the same tolight at every vertex).
    const light_kind second = trial % 2 == 0 ? light_kind::directional : light_kind::point;
    s.lights = {{{pos(rng), pos(rng), pos(rng)}, colour()}, {{pos(rng), pos(rng), pos(rng)}, colour(), second}};
    s.view.eye = glm::vec3(pos(rng), pos(rng), 3.0f + std::fabs(pos(rng)));
    render_options o;
    o.s = scale(rng);
    o.bilinear = trial % 2 == 1;
    o.specular = trial >= 2;
    o.specular_power = o.specular ? 8.0 : 1.0;
    // Random scenes with a 4 KiB packet bound: hundreds of cuts inside triangle and IMAGE tags.
    expect_round_trip(s, prepare(s, yaw(rng), o.specular), GetParam(), o, "trial " + std::to_string(trial), 4096);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, RoundTrip, ::testing::ValuesIn(gs_methods), method_param_name);

}  // namespace
}  // namespace gsdot3::pipeline
