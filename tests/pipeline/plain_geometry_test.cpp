// Section 3.1's step 5: non-normal-mapped geometry (scene::plain, here floor.hpp's floor) drawn after
// step 4 into the same buffer, Gouraud × the diffuse texture, Z-tested against the DOT3 object's Z.
// Expected values from outside the renderer: the same scene without the floor (step 5 must leave
// every other pixel as it was), the depth planes of the prepared triangles (which of the two surfaces
// is nearer at a pixel, so which one the frame shows), and the float Gouraud of compose_plain (the
// VU1's vertex light interpolated in double). Then value path = memory path = the dump replayed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "pipeline/default_scene.hpp"
#include "pipeline/floor.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/pixel_walk.hpp"
#include "pipeline/render.hpp"
#include "replayed_frame.hpp"

namespace gsdot3::pipeline {
namespace {

// The embedded scene from above the floor's plane, so the head hides part of the floor behind it.
scene floor_scene(int map = 64) {
  scene s = default_scene(map);
  s.view.eye = {0.4f, 1.6f, 3.2f};
  s.width = 192, s.height = 168;
  s.plain = floor_under(s.model, 12);
  return s;
}

TEST(PlainGeometry, FloorIsCounterClockwiseFromAboveAtTheModelsLowestPoint) {
  const scene s = default_scene(32);
  const mesh f = floor_under(s.model, 5);
  float low = s.model.vertices.front().position.y;
  for (const vertex& v : s.model.vertices) low = std::min(low, v.position.y);
  ASSERT_EQ(f.triangles.size(), 2u * 5u * 5u);
  for (const auto& t : f.triangles) {
    const glm::vec3 a = f.vertices[t[0]].position, b = f.vertices[t[1]].position, c = f.vertices[t[2]].position;
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
  }
  for (const vertex& v : f.vertices) EXPECT_EQ(v.position.y, low);
  EXPECT_THROW(floor_under(mesh{}), std::invalid_argument);
}

// Per pixel: the floor's largest depth where a floor triangle covers it (−1 where none does).
std::vector<std::int64_t> floor_depth(const prepared_scene& ps) {
  std::vector<std::int64_t> z(static_cast<std::size_t>(ps.width * ps.height), -1);
  for (const prepared_triangle& t : ps.plain)
    rasterise_triangle(t.setup, {0, 0, ps.width, ps.height}, [&](int x, int y) {
      std::int64_t& d = z[static_cast<std::size_t>(y * ps.width + x)];
      d = std::max<std::int64_t>(d, t.z.at(x, y));
    });
  return z;
}

TEST(PlainGeometry, StepFiveDrawsTheNearerSurfaceAndNothingElse) {
  const scene with = floor_scene();
  scene without = with;
  without.plain = {};
  const prepared_scene ps = prepare(with), pn = prepare(without);
  ASSERT_FALSE(ps.plain.empty());
  const std::vector<std::int64_t> fz = floor_depth(ps);
  struct variant {
    method m;
    bool memory;
    draw_buffers buffers;
  };
  std::vector<variant> variants;
  for (method m : gs_methods) variants.push_back({m, false, draw_buffers::two});
  variants.push_back({method::four_pass, true, draw_buffers::two});
  variants.push_back({method::two_pass, true, draw_buffers::one});
  for (const variant& v : variants) {
    render_options o;
    o.memory_path = v.memory;
    o.buffers = v.buffers;
    const frame f = render(with, ps, v.m, o), g = render(without, pn, v.m, o);
    int floor_shown = 0, floor_hidden = 0;
    for (std::size_t i = 0; i < f.colour.size(); ++i) {
      const int x = static_cast<int>(i) % ps.width, y = static_cast<int>(i) / ps.width;
      const std::int32_t model = g.visible_triangle[i];
      const bool nearer =
          fz[i] >= 0 && (model < 0 || fz[i] >= ps.triangles[static_cast<std::size_t>(model)].z.at(x, y));
      ASSERT_EQ(f.plain_triangle[i] >= 0, nearer) << name(v.m) << " pixel " << x << "," << y;
      if (nearer) {
        ++floor_shown;
        EXPECT_EQ(f.visible_triangle[i], -1);
      } else {
        ASSERT_EQ(f.colour[i], g.colour[i]) << name(v.m) << " pixel " << x << "," << y;
        ASSERT_EQ(f.visible_triangle[i], model);
        if (fz[i] >= 0) ++floor_hidden;
      }
    }
    EXPECT_GT(floor_shown, 2000) << name(v.m);
    EXPECT_GT(floor_hidden, 200) << name(v.m);
    EXPECT_EQ(f.dot, g.dot) << name(v.m);  // the lights' passes come before step 5
  }
}

// Every step-5 pixel within 3 of the float Gouraud per channel: the vertex colours are rounded to
// integers (≤ 0.5), the GS's Gouraud steps add ≤ 1 unit (gs_arith/gouraud.hpp: 8.4 colours rounded
// at each pixel, tests/gs_arith), so C differs by ≤ 1.5 of 128; the texel T ≤ 255 makes that
// ≤ 1.5·255/128 < 3 after MODULATE, whose >> 7 truncates (< 1 more) and the reference rounds (0.5):
// |e| < 4.5, and an integer difference ≤ 4. Dense check: every step-5 pixel of two filters.
TEST(PlainGeometry, FloorPixelsFollowTheFloatGouraud) {
  const scene s = floor_scene(128);
  const prepared_scene ps = prepare(s);
  for (const bool bilinear : {false, true}) {
    render_options o;
    o.bilinear = bilinear;
    const frame f = render(s, ps, method::two_pass, o);
    std::vector<std::uint32_t> ref(f.colour.size(), 0);
    compose_plain(s, ps, f.plain_triangle, bilinear, ref);
    int worst = 0, pixels = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      if (f.plain_triangle[i] < 0) continue;
      ++pixels;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(static_cast<int>((f.colour[i] >> (8 * c)) & 0xFF) -
                                         static_cast<int>((ref[i] >> (8 * c)) & 0xFF)));
    }
    EXPECT_GT(pixels, 2000);
    EXPECT_LE(worst, 4) << (bilinear ? "bilinear" : "nearest");
    EXPECT_GE(worst, 1);  // the GS's rounding shows somewhere: the comparison is not vacuous
  }
}

TEST(PlainGeometry, ValuePathMemoryPathAndReplayedDumpAgree) {
  const scene s = floor_scene();
  const prepared_scene ps = prepare(s);
  for (const method m : {method::two_pass, method::four_pass, method::gouraud})
    for (const draw_buffers b : {draw_buffers::two, draw_buffers::one}) {
      render_options o;
      o.buffers = b;
      o.bilinear = m == method::four_pass;
      const frame value = render(s, ps, m, o);
      o.memory_path = true;
      const frame memory = render(s, ps, m, o);
      EXPECT_EQ(value.colour, memory.colour) << name(m);
      EXPECT_EQ(value.plain_triangle, memory.plain_triangle) << name(m);
      const replayed_frame replayed = replay_frame(build_frame_packets(s, ps, m, o), o.model);
      EXPECT_TRUE(replayed.unmodelled.empty());
      EXPECT_EQ(replayed.colour, value.colour) << name(m);
    }
}

// A normal map and diffuse texture too big to stay beside the buffers stream through a window; step 5
// needs the diffuse texture resident and is refused on the memory path and by the packet stream.
TEST(PlainGeometry, StreamedTexturesAreRefused) {
  scene s = floor_scene(1024);
  s.width = 512, s.height = 448;
  const prepared_scene ps = prepare(s);
  render_options o;
  o.memory_path = true;
  EXPECT_THROW(render(s, ps, method::two_pass, o), std::invalid_argument);
  EXPECT_THROW(build_frame_packets(s, ps, method::two_pass, o), std::invalid_argument);
}

}  // namespace
}  // namespace gsdot3::pipeline
