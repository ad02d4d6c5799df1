// Every GS method × step 2.1's DPB clear {explicit, z-trick, z-trick-psmz32} × draw buffers {1, 2} ×
// {value, memory path} × {nothing, step 5's floor, a spot light} at frame sizes 1x1, 16x16, 33x17,
// 96x80, 128x112 and 200x150 (issue 51: the z-trick modes overflowed the heap at most sizes that are
// not whole pages, and no test drew them there), under both values of uv_convert (each model option
// is in this test from the day it is added). Each combination either renders or is refused with
// std::invalid_argument (the CLI's one-line exit 2); nothing else may escape. The frames are checked
// against the value path's two-buffer frame with explicit clears, each an independent sequence of
// passes or storage: the memory path, the SIMD units against gs::pixel_pipeline per pixel (traced, as
// the report's DPB pictures are: the z-trick crash was in the trace), the
// one-buffer variant, the z-trick clears (z-trick under every texture_buffer model; z-trick-psmz32
// where the texture buffer holds the page, memory_path_test.cpp's claim (e)), and the GS dump of every
// memory-path frame, each DPB clear, replayed through the packet interpreter.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "pipeline/default_scene.hpp"
#include "pipeline/floor.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/render.hpp"
#include "replayed_frame.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

enum class extra { none, floor, spot, layers };  // layers: a two-layer map (test_scenes.hpp's two_layers)
constexpr std::array<std::array<int, 2>, 6> sizes{{{1, 1}, {16, 16}, {33, 17}, {96, 80}, {128, 112}, {200, 150}}};

scene scene_for(std::array<int, 2> size, extra e) {
  static const scene base = default_scene(64);
  scene s = base;
  s.width = size[0], s.height = size[1];
  if (e == extra::floor) s.plain = floor_under(s.model);
  if (e == extra::spot) {
    scene_light& l = s.lights.front();
    l.kind = light_kind::spot;
    l.direction = glm::vec3{0.1f, -0.1f, 0.0f} - l.position;  // at the head's centre
    l.cone_degrees = 15.0f;
  }
  return e == extra::layers ? test::two_layers(s) : s;
}

// What the frame says of every pixel that another path must reproduce.
bool same(const frame& a, const frame& b) {
  return a.colour == b.colour && a.dot == b.dot && a.plain_triangle == b.plain_triangle;
}
std::string first_difference(const frame& a, const frame& b) {
  for (std::size_t i = 0; i < a.colour.size() && i < b.colour.size(); ++i)
    if (a.colour[i] != b.colour[i])
      return "pixel " + std::to_string(i) + ": " + std::to_string(a.colour[i]) + " vs " + std::to_string(b.colour[i]);
  return a.colour.size() != b.colour.size() ? "frame sizes differ" : "dot layers or step 5's pixels differ";
}

// Every pair of uv_plane and uv_convert values (the UV planes' two options).
constexpr std::array<gs::uv_rule, 4> uv_rules{{{gs::uv_plane_mode::exact, gs::uv_convert_mode::floor},
                                               {gs::uv_plane_mode::exact, gs::uv_convert_mode::floor_1_64},
                                               {gs::uv_plane_mode::fixed_16, gs::uv_convert_mode::floor},
                                               {gs::uv_plane_mode::fixed_16, gs::uv_convert_mode::floor_1_64}}};

class Combinations : public ::testing::TestWithParam<std::tuple<std::size_t, extra, std::size_t>> {};

TEST_P(Combinations, RenderOrRefuseAndAgree) {
  const auto [size_index, e, uv_index] = GetParam();
  const scene s = scene_for(sizes[size_index], e);
  const prepared_scene ps = prepare(s);
  int drawn = 0, refused = 0;
  for (const method m : gs_methods) {
    render_options base;
    base.model.uv_plane = uv_rules[uv_index].plane;
    base.model.uv_convert = uv_rules[uv_index].convert;
    const frame expected = render(s, ps, m, base);  // value path, explicit clears, two buffers, SIMD
    ASSERT_EQ(expected.colour.size(), static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height));
    render_options walked = base;
    walked.span_engine = false;  // every triangle pixel through the attribute walker and span_batch
    EXPECT_EQ(render(s, ps, m, walked).colour, expected.colour) << name(m) << ": the span engine against the walk";
    std::vector<std::pair<render_options, frame>> memory_frames;  // what each dump must replay to
    for (const dpb_clear_mode clear :
         {dpb_clear_mode::explicit_clear, dpb_clear_mode::z_trick, dpb_clear_mode::z_trick_psmz32})
      for (const draw_buffers buffers : {draw_buffers::two, draw_buffers::one})
        for (const bool memory : {false, true})
          for (const bool simd : {true, false}) {
            render_options o = base;
            o.dpb_clear = clear, o.buffers = buffers, o.memory_path = memory, o.simd = simd;
            std::vector<pass_record> trace;  // the scalar renders are traced (as the report's DPB pictures are)
            if (!simd) o.trace = &trace;
            // z-trick-psmz32 reproduces the explicit clears only where the texture buffer holds the
            // page (section 3.4 claim (e)); under the default quarter_page it is drawn for the crash check.
            const bool comparable = clear != dpb_clear_mode::z_trick_psmz32 || simd;
            if (clear == dpb_clear_mode::z_trick_psmz32 && simd) o.model.tex_buffer = gs::texture_buffer::page;
            const std::string what = std::string(name(m)) + ", " + std::string(name(clear)) + ", " +
                                     (buffers == draw_buffers::one ? "one buffer" : "two buffers") +
                                     (memory ? ", memory path" : ", value path") +
                                     (simd ? ", SIMD" : ", scalar, traced");
            frame f;
            try {
              f = render(s, ps, m, o);
            } catch (const std::invalid_argument&) {
              ++refused;
              continue;
            }
            ++drawn;
            ASSERT_EQ(f.colour.size(), expected.colour.size()) << what;
            for (const pass_record& p : trace) ASSERT_EQ(p.word.size(), f.colour.size()) << what << ": " << p.label;
            if (comparable) { EXPECT_TRUE(same(f, expected)) << what << ": " << first_difference(f, expected); }
            if (memory && simd) memory_frames.emplace_back(o, std::move(f));
          }
    // The dump of every memory-path frame (each clear, both buffer modes) replays to that frame.
    for (const auto& [o, f] : memory_frames) {
      const std::string what = std::string(name(m)) + ", " + std::string(name(o.dpb_clear)) +
                               (o.buffers == draw_buffers::one ? ", one buffer" : ", two buffers");
      const replayed_frame r = replay_frame(build_frame_packets(s, ps, m, o), o.model);
      EXPECT_EQ(r.colour, f.colour) << what << ": the dump replayed";
      EXPECT_TRUE(r.unmodelled.empty()) << what;
      ++drawn;
    }
  }
  // The refusals are the model's documented ones: the one-buffer variant with a z-trick clear (the
  // z-trick modes draw in the Z buffer the variant parks an alpha in); everything else draws.
  EXPECT_EQ(refused, 5 * 2 * 2 * 2);
  EXPECT_EQ(drawn, 5 * (3 * 2 * 2 * 2 - 2 * 2 * 2 + 4));
}

std::string param_name(const ::testing::TestParamInfo<std::tuple<std::size_t, extra, std::size_t>>& p) {
  const auto [i, e, uv_index] = p.param;
  const gs::uv_rule uv = uv_rules[uv_index];
  static constexpr const char* extras[] = {"none", "floor", "spot", "layers"};
  return std::to_string(sizes[i][0]) + "x" + std::to_string(sizes[i][1]) + "_" + extras[static_cast<int>(e)] +
         (uv.plane == gs::uv_plane_mode::exact ? "" : "_uv_fixed_16") +
         (uv.convert == gs::uv_convert_mode::floor ? "" : "_uv_floor_1_64");
}

INSTANTIATE_TEST_SUITE_P(SizesAndExtras, Combinations,
                         ::testing::Combine(::testing::Range<std::size_t>(0, sizes.size()),
                                            ::testing::Values(extra::none, extra::floor, extra::spot, extra::layers),
                                            ::testing::Range<std::size_t>(0, uv_rules.size())),
                         param_name);

}  // namespace
}  // namespace gsdot3::pipeline
